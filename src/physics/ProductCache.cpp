#include "physics/ProductCache.hpp"

#include <algorithm>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Vector.hpp>

namespace choc {

ProductCache::ProductCache(RCP<const Map> map, int products)
    : x_(rcp(new Vector(map))), held_(size_t(products), 0) {
  for (int i = 0; i < products; ++i) Ax_.push_back(rcp(new Vector(map)));
}

void ProductCache::reset(const Vector& x) {
  x_->assign(x);
  std::fill(held_.begin(), held_.end(), 0);
}

Vector& ProductCache::write(int i) {
  held_[size_t(i)] = 1;
  return *Ax_[size_t(i)];
}

bool ProductCache::holds(const Vector& x, int i) const {
  int differs = held_[size_t(i)] ? 0 : 1;  // the same on every rank: every rank writes alike
  if (!differs) {
    auto a = x.getData(), b = x_->getData();
    for (size_t k = 0; k < size_t(a.size()) && !differs; ++k) differs = a[k] != b[k];
  }
  int anyDiffers = 0;
  Teuchos::reduceAll(*x.getMap()->getComm(), Teuchos::REDUCE_MAX, differs, Teuchos::outArg(anyDiffers));
  return anyDiffers == 0;
}

}  // namespace choc
