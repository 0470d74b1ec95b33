#include "analysis/ModalStepView.hpp"

#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "physics/ModalProjection.hpp"

namespace choc {

ModalStepView::ModalStepView(const ModalState& state, const ModalIntegrator& integrator,
                             const ModalLinks& links, const ModalBasis& basis,
                             std::vector<double> omega2, ModalProbes probes, bool symplecticEuler)
    : state_(state), integrator_(integrator), links_(links), basis_(basis), w2_(std::move(omega2)),
      probes_(std::move(probes)), symplecticEuler_(symplecticEuler) {}

void ModalStepView::at(long long step, double dt, bool last) {
  point_.step = step;
  point_.time = state_.t;
  point_.dt = dt;
  point_.last = last;
  point_.nominal = step;
}

// Velocities: the scheme's own v for symplectic Euler (as the reference deck reports it),
// the synchronized one (with the constraint impulse) for the other schemes.
std::vector<double> ModalStepView::probeValues() const {
  const size_t nm = w2_.size();
  const std::vector<double> vsync = integrator_.synchronizedVelocity(state_);
  std::vector<double> out;
  for (size_t i = 0; i < probes_.probes.size(); ++i) {
    const ProbeField f = probes_.probes[i].field;
    const auto& x = f == ProbeField::Displacement ? state_.q
                    : f == ProbeField::Velocity   ? (symplecticEuler_ ? state_.v : vsync)
                                                  : state_.a;
    double s = 0.0;
    const double* r = &probes_.rows[i * nm];
    for (size_t k = 0; k < nm; ++k) s += r[k] * x[k];
    out.push_back(s);
  }
  return out;
}

// No external loads in a modal transient (obstacles are fixed): W_external = 0.
EnergyTerms ModalStepView::energies() {
  EnergyTerms e;
  const std::vector<double> vs = integrator_.synchronizedVelocity(state_);
  for (size_t k = 0; k < w2_.size(); ++k) {
    e.kinetic += 0.5 * vs[k] * vs[k];
    e.strain += 0.5 * w2_[k] * state_.q[k] * state_.q[k];
  }
  e.contact = links_.springEnergy();
  e.dissipated = integrator_.modalDissipation() + links_.dissipatedEnergy();
  // Every modal scheme is explicit: (h^2/8) a^T a on the mass-normalised basis (EnergyTerms).
  for (double a : state_.a) e.shadow += 0.125 * substep_ * substep_ * a * a;
  return e;
}

void ModalStepView::fields(Vector& u, Vector& v, Vector& a) const {
  const std::vector<double>* x[3] = {&state_.q, &state_.v, &state_.a};
  Vector* out[3] = {&u, &v, &a};
  for (int i = 0; i < 3; ++i) expandOnBasis(*basis_.vectors, *x[i], *out[i]);
}

}  // namespace choc
