// The small-strain domain of the blocks whose stiffness is assembled (linear elastic, 'Strain' =
// 'small'; the blocks computed element by element are FiniteStrainForce's): each element's strain
// and rotation at its centre from u, against ElementValidity's bounds (a warning past 5 % / 0.05
// rad, a failure past 50 % / 0.5 rad). A small-strain body turned or crushed that far gives an
// answer of the linear strain measure, not of the motion.
#pragma once
#include <string>
#include <vector>

#include <Tpetra_Import.hpp>

#include "fem/ElementChecks.hpp"
#include "fem/ElementValidity.hpp"
#include "core/TpetraTypes.hpp"

namespace choc {

class Model;

class SmallStrainDomain {
 public:
  explicit SmallStrainDomain(Model& model);
  bool empty() const { return elementsOnAnyRank_ == 0; }
  // Sets v's warning (when it has none) or failure (when it has none) from the worst element.
  // Collective.
  void check(const Vector& u, ElementValidity& v) const;

 private:
  struct Element {
    int number;            // global element index (0-based)
    int block;
    const CheckPoints* points;
    int nc;                // components per node
    bool axisymmetric;
    std::vector<LO> col;   // local column of each element DOF (-1: fixed)
    std::vector<Point3> X; // reference coordinates
  };
  std::vector<Element> elements_;  // the owners' (the rank owning the first node)
  std::vector<std::string> blockNames_;
  RCP<const Map> columns_;
  RCP<const Tpetra::Import<LO, GO>> importer_;
  RCP<Vector> uCol_;  // scratch: u on the column map (made once)
  long long elementsOnAnyRank_ = 0;
};

}  // namespace choc
