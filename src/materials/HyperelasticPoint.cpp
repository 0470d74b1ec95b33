// A hyperelastic law as a material point (formulas in the header).
#include "materials/HyperelasticPoint.hpp"

namespace choc {

namespace {

class HyperelasticPoint : public MaterialPoint {
 public:
  explicit HyperelasticPoint(std::shared_ptr<const HyperelasticMaterial> law) : law_(std::move(law)) {}
  const char* name() const override { return law_->name(); }
  double modulus() const override {
    StressResponse r;
    law_->respond(identity3(), true, r);
    return r.tangent[0][0][0][0];
  }
  void respond(const Mat3& F, const double* /*old*/, double* /*next*/, const PointRequest& request,
               PointResponse& out) const override {
    thread_local StressResponse r;
    law_->respond(transposeTimes(F), request.tangent, r);
    out.P = multiply(F, r.S);
    out.energy = r.energy;
    out.dissipated = 0.0;
    if (request.tangent) firstElasticity(F, r, out.A);
  }

 private:
  // A = delta_ik S_JL + F_iI F_kK CC_IJKL, the contraction in two passes (T_iJKL = F_iI CC_IJKL,
  // then F_kK T_iJKL): 486 products instead of 6,561.
  static void firstElasticity(const Mat3& F, const StressResponse& r, double (&A)[9][9]) {
    const auto& C = r.tangent;
    double T[3][3][3][3];
    for (int i = 0; i < 3; ++i)
      for (int J = 0; J < 3; ++J)
        for (int K = 0; K < 3; ++K)
          for (int L = 0; L < 3; ++L)
            T[i][J][K][L] = F[i][0] * C[0][J][K][L] + F[i][1] * C[1][J][K][L] + F[i][2] * C[2][J][K][L];
    for (int i = 0; i < 3; ++i)
      for (int J = 0; J < 3; ++J)
        for (int k = 0; k < 3; ++k)
          for (int L = 0; L < 3; ++L)
            A[3 * i + J][3 * k + L] = (i == k ? r.S[J][L] : 0.0) + F[k][0] * T[i][J][0][L] + F[k][1] * T[i][J][1][L] +
                                      F[k][2] * T[i][J][2][L];
  }
  std::shared_ptr<const HyperelasticMaterial> law_;
};

}  // namespace

std::shared_ptr<const MaterialPoint> hyperelasticPoint(std::shared_ptr<const HyperelasticMaterial> law) {
  return std::make_shared<HyperelasticPoint>(std::move(law));
}

}  // namespace choc
