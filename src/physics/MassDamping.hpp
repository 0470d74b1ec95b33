// The structural model's inertia and Rayleigh damping, C = aK K0 + aM M (K0: the internal
// force's damping stiffness, InternalForce::applyDampingStiffness): the mass products, the
// damping forces C v, the effective matrix's coefficients of M and K, the kinetic energy and
// the damping power. The mass is the assembled M, or its diagonal m for an explicit run
// (useDiagonal), whose products are element by element. Rows of M that are zero (redistributed
// contact mass) are listed: those DOFs have no inertia. The products K0 v and M v of the last
// velocity the forces were computed with are kept when asked (the energies of the state a step
// ended at cost no second product).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/TpetraTypes.hpp"
#include "physics/InternalForce.hpp"
#include "physics/MasslessBasis.hpp"
#include "physics/ProductCache.hpp"
#include "solvers/LinearSolver.hpp"
#include "timeint/SecondOrderOperator.hpp"

namespace choc {

class RigidBodies;

class MassDamping {
 public:
  MassDamping(RCP<const CrsMatrix> M, double aK, double aM, std::shared_ptr<InternalForce> internal);
  RCP<const CrsMatrix> matrix() const { return M_; }
  void useDiagonal(RCP<const Vector> m) { diagonal_ = std::move(m); }
  // The rigid bodies of an explicit run (physics/RigidBodies.hpp): their inertia is theirs, not
  // the nodes' (the diagonal given to useDiagonal has their rows zero); null: none.
  void setRigidBodies(std::shared_ptr<RigidBodies> bodies) { rigid_ = std::move(bodies); }
  RigidBodies* rigidBodies() const { return rigid_.get(); }
  // out = M x.
  void applyMass(const Vector& x, Vector& out) const;
  // out += C v; with `keep`, K0 v and M v are kept for the energies of v.
  void addDampingForces(const Vector& v, Vector& out, bool keep);
  double kineticEnergy(const Vector& v) const;                // 1/2 v.M v
  // x = M^-1 b: by the direct package given to solveMassBy (M factored at the first solve and
  // kept: M does not change in a run), else by conjugate gradients preconditioned by M's
  // diagonal, to 1e-13 of |b| (a mass matrix's condition number does not grow with the mesh:
  // tens of iterations). Throws NumericalError when it fails (a singular M: massless DOFs).
  // Collective.
  void solveMass(const Vector& b, Vector& x) const;
  void solveMassBy(std::string directPackage) { massPackage_ = std::move(directPackage); }
  bool damps() const { return aK_ != 0.0 || aM_ != 0.0; }      // Rayleigh damping: C v depends on v
  double dampingPower(const Vector& v, double kinetic) const;  // v.C v, given 1/2 v.M v
  // W = ca M + cv C + cd K = (ca + cv aM) M + (cd + cv aK) K: its coefficients of M and K.
  double massCoefficient(const EffectiveCoefficients& c) const { return c.ca + c.cv * aM_; }
  double stiffnessCoefficient(const EffectiveCoefficients& c) const { return c.cd + c.cv * aK_; }
  // The DOFs without inertia: M's zero rows, or, after useMasslessBasis, the massless rotated
  // DOFs of Q^T M Q ('Contact Mass' = normal: physics/MasslessBasis.hpp).
  void useMasslessBasis(MasslessBasis b);
  const std::vector<char>& masslessMask() const { return massless_; }  // per local (rotated) DOF
  long long masslessDofs() const { return masslessGlobal_; }
  const RCP<const CrsMatrix>& masslessRotation() const { return rotation_; }  // Q; null: the axes

 private:
  std::shared_ptr<RigidBodies> rigid_;
  std::shared_ptr<InternalForce> internal_;
  RCP<const CrsMatrix> M_;
  RCP<const Vector> diagonal_;  // useDiagonal(); null: M's own product
  double aK_, aM_;
  ProductCache vProducts_;  // K0 v and M v (one copy of v)
  static constexpr int kKv = 0, kMv = 1;
  RCP<Vector> tmp_, energyTmp_;
  std::vector<char> massless_;
  RCP<const CrsMatrix> rotation_;
  std::string massPackage_;                         // solveMassBy; empty: conjugate gradients
  mutable std::unique_ptr<LinearSolver> massSolver_;  // M's factorisation, at the first solve
  long long masslessGlobal_ = 0;
};

}  // namespace choc
