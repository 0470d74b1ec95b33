// J2 plasticity as a material point (J2Point.hpp).
#include "materials/J2Point.hpp"

#include <algorithm>

namespace choc {

namespace {

class J2Point : public MaterialPoint {
 public:
  explicit J2Point(std::shared_ptr<const J2Plasticity> law) : law_(std::move(law)) {}
  const char* name() const override { return law_->parameters().johnsonCook ? "Johnson-Cook" : "J2 plasticity"; }
  bool finiteStrain() const override { return law_->finiteStrain(); }
  bool dissipative() const override { return true; }
  int stateSize() const override { return kJ2StateSize; }
  void initialState(double* state) const override {
    const auto s0 = law_->initialState();
    std::copy(s0.begin(), s0.end(), state);
  }
  double modulus() const override { return law_->bulkModulus() + 4.0 / 3.0 * law_->shearModulus(); }
  void respond(const Mat3& F, const double* old, double* next, const PointRequest& request,
               PointResponse& out) const override {
    thread_local J2Response r;
    std::array<double, kJ2StateSize> virgin;
    if (!old) virgin = law_->initialState(), old = virgin.data();
    law_->respond(F, old, request.tangent, r, request.elasticTangent, request.dt);
    out.P = r.P;
    out.energy = r.energy;
    out.dissipated = r.plasticWork;
    if (request.tangent) std::copy(&r.A[0][0], &r.A[0][0] + 81, &out.A[0][0]);
    if (next) std::copy(r.state.begin(), r.state.end(), next);
  }

  bool reportsState() const override { return true; }
  // P F^T / det F from the last accepted P and F (F-bar's Fbar), P itself in small strain.
  Mat3 recordedCauchy(const double* st) const override {
    Mat3 P, F;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) P[i][j] = st[kJ2Stress + 3 * i + j], F[i][j] = st[kJ2Deformation + 3 * i + j];
    return cauchyFromFirstPiola(P, F, law_->finiteStrain());
  }
  double recordedEnergy(const double* st) const override { return st[kJ2Energy]; }
  std::vector<std::string> fieldNames() const override {
    std::vector<std::string> names = {"VON_MISES", "EQ_PLASTIC_STRAIN", "PRESSURE"};
    if (hasTemperature()) names.push_back("TEMPERATURE");
    if (hasDamage()) names.push_back("DAMAGE");
    return names;
  }
  void addFields(const double* st, const Mat3& c, double w, double* sums) const override {
    sums[0] += w * vonMises(c);
    sums[1] += w * st[kJ2Alpha];
    sums[2] -= w * trace(c) / 3;
    int k = 3;
    if (hasTemperature()) sums[k++] += w * st[kJ2Temperature];
    if (hasDamage()) sums[k] += w * st[kJ2Damage];
  }

  bool hasDamage() const override { return law_->hasDamage(); }
  double damage(const double* st) const override { return st[kJ2Damage]; }
  bool hasTemperature() const override { return law_->flowStress().hasTemperature(); }
  bool melted(const double* st) const override {
    return hasTemperature() && law_->flowStress().melted(st[kJ2Temperature]);
  }

 private:
  std::shared_ptr<const J2Plasticity> law_;
};

}  // namespace

std::shared_ptr<const MaterialPoint> j2Point(std::shared_ptr<const J2Plasticity> law) {
  return std::make_shared<J2Point>(std::move(law));
}

}  // namespace choc
