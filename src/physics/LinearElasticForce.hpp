// Linear elasticity assembled once: f_int(u) = K u, the tangent K whatever u (its version
// never changes), no material state; Rayleigh damping's stiffness is K.
#pragma once
#include <memory>

#include "fem/SymmetricProduct.hpp"
#include "physics/InternalForce.hpp"

namespace choc {

class LinearElasticForce : public InternalForce {
 public:
  explicit LinearElasticForce(RCP<const CrsMatrix> K);
  RCP<const Map> map() const override { return K_->getRowMap(); }
  void internalForce(const Vector& u, Vector& out) override { apply(u, out); }
  RCP<const CrsMatrix> tangent(const Vector& /*u*/) override { return K_; }
  long long tangentVersion() const override { return 0; }
  void applyDampingStiffness(const Vector& x, Vector& out) const override { apply(x, out); }
  bool linear() const override { return true; }
  // 1/2 u.K u
  double strainEnergy(const Vector& u, const Vector* internalForceAtU) const override;
  double termsNorm(const Vector& u) const override;
  // K's products through SymmetricProduct (half the bytes streamed) from kWorthwhileRows rows.
  void preferSymmetricProducts() override;

 private:
  void apply(const Vector& x, Vector& out) const;
  RCP<const CrsMatrix> K_;
  std::unique_ptr<SymmetricProduct> symmetricK_;
  RCP<Vector> tmp_;     // scratch: K u for strainEnergy without a given product
  RCP<Vector> colTmp_;  // scratch: u on K's column map, for termsNorm
};

}  // namespace choc
