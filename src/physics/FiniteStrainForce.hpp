// The internal force of a model with finite-strain blocks (Model/Blocks/<name>/Strain =
// 'finite'): the small-strain blocks and the springs stay an assembled matrix K_lin (their
// products: the linear path), the finite-strain blocks are computed element by element from
// the current displacement (FiniteStrainSolid: total Lagrangian, hyperelastic):
//
//   f_int(u) = K_lin u + sum_e f_e(u_e),   K_T(u) = K_lin + sum_e K_e(u_e)
//
// K_T is written into one matrix on the graph of the model's stiffness (every block's entries,
// the same every iteration), its version bumped whenever its values change: the operator's
// factorisation key then refactors (InternalForce.hpp). Each rank computes the elements touching
// its nodes (the Assembler's elements) and sums their rows it owns in global element order.
// Rayleigh damping's stiffness is the model's K at u = 0. An element that inverts (det F <= 0)
// on any rank throws InadmissibleState on every rank, naming the element, its block and det F.
// The material points' states (a plastic law's, per quadrature point) are MaterialStates.hpp's:
// every evaluation starts from the committed copy, internalForce writes the trial (its u's),
// commit() and revert() follow the steps, checkpoints store them by global element number.
// Follower pressures (FollowerPressure.hpp), loads that depend on the state, are carried here
// too: f_int(u) - f_p(u, t) and K_T + K_p(u, t), at the time setTime last gave.
#pragma once
#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Tpetra_Import.hpp>

#include "fem/ElementChecks.hpp"
#include "fem/FiniteStrainSolid.hpp"
#include "physics/FollowerPressure.hpp"
#include "physics/InternalForce.hpp"
#include "physics/MaterialStates.hpp"

namespace choc {

class Model;
struct Mesh;

class FiniteStrainForce : public InternalForce {
 public:
  explicit FiniteStrainForce(Model& model);
  RCP<const Map> map() const override { return K0_->getRowMap(); }
  void internalForce(const Vector& u, Vector& out) override;
  RCP<const CrsMatrix> tangent(const Vector& u) override;
  long long tangentVersion() const override { return version_; }
  void applyDampingStiffness(const Vector& x, Vector& out) const override { K0_->apply(x, out); }
  bool linear() const override { return false; }
  // The time of the next evaluations; the first one given is the committed state's (the start).
  void setTime(double t) override {
    time_ = t;
    states_.startAt(t);
  }
  // A load that depends on the state (a follower pressure, a coupling's load): its force and load stiffness.
  void addStateLoad(std::shared_ptr<const StateLoad> p) { followers_.push_back(std::move(p)); }
  // 1/2 u.K_lin u + the elements' int W dV (each element counted on the rank owning its first node).
  double strainEnergy(const Vector& u, const Vector* internalForceAtU) const override;
  // || |K_lin| |u| + sum_e (|f_e| + its round-off) || (see the constructor: E = (C - I) / 2
  // errs by eps whatever u).
  double termsNorm(const Vector& u) const override;
  // max over the finite-strain elements of lambda_max(K_e(u), M_e), M_e the block's lumped mass;
  // plastic points with their elastic tangent (an unloading point is the stiffest).
  double stateEigenvalueBound(const Vector& u) const override;
  double dissipatedWork() const override { return states_.dissipatedWork(); }
  double hourglassEnergy(const Vector& u) const override;
  ElementValidity validity(const Vector& u) const override;  // FiniteStrainValidity.cpp
  bool hasReturnMap() const override { return states_.any(); }
  void commit() override { states_.commit(); }
  void revert() override { states_.revert(); }
  void archive(StateArchive& a) const override { states_.archive(a); }
  void restore(const StateArchive& a) override { states_.restore(a); }

  // The Cauchy stress averaged over each finite-strain element (FiniteStrainSolid::
  // averageStress) and its strain-energy density: SIGMA_XX, SIGMA_YY, SIGMA_ZZ, SIGMA_XY
  // (and SIGMA_YZ, SIGMA_ZX in 3D; axisymmetric: XX radial, YY axial, ZZ hoop, XY the rz
  // shear), STRAIN_ENERGY_DENSITY (the stored elastic energy), then the blocks' materials' own
  // fields (MaterialPoint::fieldNames, in the order the blocks first name them; 0 on the blocks
  // without them: J2Point.hpp's VON_MISES, EQ_PLASTIC_STRAIN, PRESSURE, TEMPERATURE, DAMAGE); a
  // material with state reports what it recorded at the last accepted step. On the nonlinear
  // blocks, each element by the rank owning its first node.
  std::vector<std::string> elementFieldNames() const override;
  std::vector<char> elementFieldBlocks() const override { return finiteBlocks_; }
  void elementFields(const Vector& u, std::vector<std::vector<double>>& values) const override;

 private:
  struct Element {
    const FiniteStrainSolid* kernel;
    int number;   // global element index (0-based)
    int block;
    bool owner;   // this rank owns its first node: it counts its energy and its output
    ElementGeometry geometry;  // the reference geometry at the quadrature points
    std::vector<LO> col;  // local column of each element DOF in K's column map (-1: fixed)
    std::vector<LO> row;  // local row when this rank owns that DOF (-1: not owned or fixed)
    std::vector<double> lumpedMass;  // the element's lumped mass per DOF (reference configuration)
    std::vector<double> roundoff;    // per DOF: the round-off of its force (termsNorm)
    size_t state = 0;                // its material state's offset in states_
  };
  // A pass at a trial u: the new states (element offsets into `state`) and the owners' plastic
  // work and hourglass energy (this rank).
  struct TrialPass {
    double* state;
    double work = 0.0, hourglass = 0.0;
  };
  // Per element: the displacements from u on the column map, the force (and tangent when K),
  // from the committed state; with `trial`, the new states and the owners' work go to it.
  // Returns this rank's first failure ("" if none); the callers make it collective.
  void prefetch(const Element& e, bool trial) const;
  void packElements();  // the arrays the force reads, in element order (FiniteStrainForce.cpp)
  template <class Visit>
  std::string forEachElement(const Vector& uCol, bool withTangent, Visit&& visit, TrialPass* trial = nullptr,
                             bool elasticTangent = false) const;
  const Vector& onColumns(const Vector& u) const;
  // The element's displacements (element DOF order, 0 where fixed) from u on the column map.
  static void gather(const Element& e, const Teuchos::ArrayRCP<const double>& uCol, std::vector<double>& ue);
  void throwIfFailed(const std::string& localFailure) const;
  std::string describe(const Element& e, const std::string& what) const;

  RCP<const CrsMatrix> K0_, Klin_;
  RCP<CrsMatrix> KT_;
  RCP<const Tpetra::Import<LO, GO>> importer_;
  std::vector<Element> elements_;
  std::vector<std::string> blockNames_;
  std::vector<char> finiteBlocks_;
  int numElements_ = 0;
  bool threeD_ = true;
  long long version_ = 0;
  std::vector<std::shared_ptr<const StateLoad>> followers_;
  double time_ = 0.0;
  double tangentTime_ = 0.0;    // the time of KT_'s values (the followers' ramp)
  RCP<Vector> tangentAt_;       // the u of KT_'s values
  bool tangentValid_ = false;  // KT_ holds the complete tangent at tangentAt_
  // The elements' energy (this rank's share) at the u of the last internal force, for the
  // energies of the state a step ended at without a second pass over the elements.
  struct LastForce {
    RCP<Vector> u;           // where it was evaluated
    bool valid = false;      // once a force was evaluated
    double energy = 0.0;     // the owners' strain energy there (this rank)
    double hourglass = 0.0;  // the owners' hourglass energy there (this rank)
  } lastForce_;
  bool sameState(const RCP<Vector>& at, const Vector& u) const;
  // The plastic states: committed, and the trial of the last internal force (see above).
  MaterialStates states_;  // the material points' states and their lifecycle
  bool hourglass_ = false;  // a block has one-point elements
  bool linearPart_ = true;  // K_lin has a nonzero value (else its products are skipped)
  static bool anyNonzero(const CrsMatrix& K);
  // Per element DOF: the round-off of its force (termsNorm; see the .cpp).
  static std::vector<double> forceRoundoff(const FiniteStrainSolid& kernel, const ElementGeometry& g);
  void layoutFields(const std::vector<std::shared_ptr<const FiniteStrainSolid>>& kernels);
  std::vector<std::string> materialFields_;       // the blocks' material fields (elementFieldNames)
  std::vector<std::vector<size_t>> blockFields_;  // per block: its material's fields' places in them
  // Each element's reference node coordinates (3 per node, elements_' order) for validity().
  std::vector<double> reference_;
  std::vector<size_t> referenceAt_;
  using Measure = ElementMeasure;
  void measureElement(const Element& e, const std::vector<double>& ue, Measure& detF, Measure& strain,
                      Measure& rotation) const;
  std::string describeMeasure(const Measure& m, const std::string& text) const;
  RCP<Vector> uCol_, tmp_;  // scratch: u on the column map, K_lin u (made once)
};

}  // namespace choc
