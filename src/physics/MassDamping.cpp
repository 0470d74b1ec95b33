#include "physics/MassDamping.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "physics/MasslessInitialAcceleration.hpp"
#include "solvers/DirectSolver.hpp"

namespace choc {

MassDamping::MassDamping(RCP<const CrsMatrix> M, double aK, double aM, std::shared_ptr<InternalForce> internal)
    : internal_(std::move(internal)), M_(std::move(M)), aK_(aK), aM_(aM), vProducts_(M_->getRowMap(), 2) {
  tmp_ = rcp(new Vector(M_->getRowMap()));
  energyTmp_ = rcp(new Vector(M_->getRowMap()));
  const MasslessRows rows = masslessRows(*M_);
  massless_ = rows.mask;
  masslessGlobal_ = rows.global;
}

void MassDamping::useMasslessBasis(MasslessBasis b) {
  rotation_ = std::move(b.rotation);
  massless_ = std::move(b.mask);
  masslessGlobal_ = b.global;
}

void MassDamping::applyMass(const Vector& x, Vector& out) const {
  if (diagonal_.is_null()) M_->apply(x, out);
  else out.elementWiseMultiply(1.0, *diagonal_, x, 0.0);
}

void MassDamping::addDampingForces(const Vector& v, Vector& out, bool keep) {
  if (keep) vProducts_.reset(v);
  // K0 v and M v straight into the cache's buffers when kept.
  if (aK_ != 0.0) {
    Vector& Kv = keep ? vProducts_.write(kKv) : *tmp_;
    internal_->applyDampingStiffness(v, Kv);
    out.update(aK_, Kv, 1.0);
  }
  if (aM_ != 0.0 && !keep && !diagonal_.is_null()) {
    out.elementWiseMultiply(aM_, *diagonal_, v, 1.0);  // out += aM m .* v in one pass
  } else if (aM_ != 0.0) {
    Vector& Mv = keep ? vProducts_.write(kMv) : *tmp_;
    applyMass(v, Mv);
    out.update(aM_, Mv, 1.0);
  }
}

void MassDamping::solveMass(const Vector& b, Vector& x) const {
  if (!massPackage_.empty()) {
    if (!massSolver_) {
      massSolver_ = makeDirectSolver(massPackage_, 1e-12, 0, true, false);
      massSolver_->setMatrix(M_);
    }
    const LinearSolveStatus st = massSolver_->solve(b, x);
    if (!st.converged)
      throw NumericalError(format("the mass matrix's solve (%s) failed: %s", massPackage_.c_str(), st.message.c_str()));
    return;
  }
  const auto map = M_->getRowMap();
  Vector d(map), r(b, Teuchos::Copy), z(map), p(map), q(map);
  M_->getLocalDiagCopy(d);
  d.reciprocal(d);
  x.putScalar(0.0);
  const double bnorm = b.norm2();
  if (bnorm == 0.0) return;
  z.elementWiseMultiply(1.0, d, r, 0.0);
  p.assign(z);
  double rz = r.dot(z);
  for (int k = 0; k < 1000; ++k) {
    M_->apply(p, q);
    const double pq = p.dot(q);
    if (!(pq > 0)) break;
    const double alpha = rz / pq;
    x.update(alpha, p, 1.0);
    r.update(-alpha, q, 1.0);
    if (r.norm2() <= 1e-13 * bnorm) return;
    z.elementWiseMultiply(1.0, d, r, 0.0);
    const double rzNew = r.dot(z);
    p.update(1.0, z, rzNew / rz);
    rz = rzNew;
  }
  throw NumericalError(format("the mass matrix's solve (conjugate gradients, Jacobi) did not converge: residual %.3e "
                              "of the right-hand side's norm",
                              r.norm2() / bnorm));
}

double MassDamping::kineticEnergy(const Vector& v) const {
  if (vProducts_.holds(v, kMv)) return 0.5 * v.dot(vProducts_.product(kMv));
  if (!diagonal_.is_null()) {  // sum m_i v_i^2 in one pass, without M v's vector
    const auto m = diagonal_->getData();
    const auto x = v.getData();
    double local = 0.0, global = 0.0;
    for (size_t i = 0; i < size_t(x.size()); ++i) local += x[i] * (m[i] * x[i]);
    Teuchos::reduceAll(*v.getMap()->getComm(), Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
    return 0.5 * global;
  }
  applyMass(v, *energyTmp_);
  return 0.5 * v.dot(*energyTmp_);
}

// v^T C v = aK v^T K0 v + aM v^T M v.
double MassDamping::dampingPower(const Vector& v, double kinetic) const {
  double power = aM_ * 2.0 * kinetic;
  if (aK_ != 0.0) {
    if (vProducts_.holds(v, kKv)) return power + aK_ * v.dot(vProducts_.product(kKv));
    internal_->applyDampingStiffness(v, *energyTmp_);
    power += aK_ * v.dot(*energyTmp_);
  }
  return power;
}

}  // namespace choc
