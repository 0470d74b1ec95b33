// A load that depends on the state: forces on groups of nodes computed from their current
// positions x = X + u (follower pressures on faces, a coupling's load spread over its nodes),
// with their derivative df/dx, the load stiffness K = -df/du, which need not be symmetric. The
// model's nonlinear force carries such loads (FiniteStrainForce: f_int(u) - lambda(t) f(u)) and
// their tangent; LoadWork integrates their work. Every DOF of a group is a column of the model's
// stiffness on a rank that owns one of its rows (a face of an element, or a group the model's
// graph couples: Model/Couplings), so a rank evaluates the groups it has a row of, on u imported
// to the column map.
#pragma once
#include <string>
#include <vector>

#include <Tpetra_Import.hpp>

#include "core/TpetraTypes.hpp"
#include "fem/DenseMatrix.hpp"
#include "mesh/Mesh.hpp"

namespace choc {

class DofMap;

class StateLoad {
 public:
  virtual ~StateLoad() = default;
  const std::string& name() const { return name_; }
  double rampTime() const { return rampTime_; }
  // The ramp lambda(t) (rampFactor).
  double factor(double t) const;
  // out (rows) -= lambda(t) f(u), u on the column map.
  void subtractForce(const Teuchos::ArrayRCP<const double>& uCol, double t, Teuchos::ArrayRCP<double>& out) const;
  // K += lambda(t) (-df/du) on the rows this rank owns (K open for fill).
  void addTangent(const Teuchos::ArrayRCP<const double>& uCol, double t, CrsMatrix& K) const;
  // out += lambda(t) f(u), u on the row map (imported here).
  void addForce(const Vector& u, double t, Vector& out) const;

 protected:
  // K: the model's stiffness (its row and column maps); components: the DOFs per node.
  StateLoad(std::string name, double rampTime, const DofMap& dofs, int components, const CrsMatrix& K);
  // A group of nodes one evaluation couples: their reference positions, per DOF (3 per node) its
  // column and row here (-1: none, fixed or not owned), and the derived class's index of it.
  struct Group {
    std::vector<Point3> X;
    std::vector<LO> col, row;
    size_t index = 0;
  };
  // Keeps the group of these nodes if this rank owns one of its rows.
  void addGroup(const std::vector<int>& nodes, std::vector<Point3> X, size_t index);
  // The group's external force at the nodes' positions x (3 per node) and, when K is given,
  // df/dx (3n x 3n).
  virtual void groupForce(const Group& g, const std::vector<Point3>& x, std::vector<double>& f,
                          DenseMatrix* K) const = 0;

 private:
  template <class Visit>
  void forEachGroup(const Teuchos::ArrayRCP<const double>& uCol, bool withTangent, Visit&& visit) const;
  std::string name_;
  double rampTime_;
  const DofMap& dofs_;
  int components_;
  std::vector<Group> groups_;
  RCP<const Map> rowMap_, colMap_;
  RCP<const Tpetra::Import<LO, GO>> importer_;
  RCP<Vector> uCol_;  // scratch: u on the column map (made once)
};

}  // namespace choc
