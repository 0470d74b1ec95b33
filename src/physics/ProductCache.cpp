#include "physics/ProductCache.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Vector.hpp>

namespace choc {

ProductCache::ProductCache(RCP<const Map> map) : x_(rcp(new Vector(map))), Ax_(rcp(new Vector(map))) {}

void ProductCache::store(const Vector& x, const Vector& Ax) {
  x_->assign(x);
  Ax_->assign(Ax);
  valid_ = true;
}

bool ProductCache::holds(const Vector& x) const {
  int differs = valid_ ? 0 : 1;
  if (valid_) {
    auto a = x.getData(), b = x_->getData();
    for (size_t i = 0; i < size_t(a.size()) && !differs; ++i) differs = a[i] != b[i];
  }
  int anyDiffers = 0;
  Teuchos::reduceAll(*x.getMap()->getComm(), Teuchos::REDUCE_MAX, differs, Teuchos::outArg(anyDiffers));
  return anyDiffers == 0;
}

}  // namespace choc
