// The linear and angular momentum of a node set, for the history's PX ... LZ columns:
//   P = sum_i (M v)_i,   L = sum_i (x_i - c) x (M v)_i,   x_i = X_i + u_i,
// about the set's centre of mass c (each coordinate weighted by its component's mass, the row
// sums of M restricted to the set). With the consistent mass matrix of isoparametric elements
// these are exactly the integrals of rho v and rho (x - c) x v over the elements the set
// covers; with a lumped (or redistributed) mass, the discrete momenta of the same equations.
// Central differences conserve both for a free body whose internal forces derive from a
// frame-invariant energy (finite strain); small strain does not conserve L.
#pragma once
#include <array>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Vector.hpp>

#include "core/TpetraTypes.hpp"
#include "observers/Probes.hpp"

namespace choc {

// P (0..2) and L (3..5) of the probe's set (collective: sums over the ranks' owned DOFs).
// mass applies M; u and v on its map.
template <class ApplyMass>
std::array<double, 6> setMomentum(const Probe& p, const Vector& u, const Vector& v, ApplyMass&& mass);

// The sums one rank contributes, from u, M v and the set's mass row sums w[c] (on the map).
std::array<double, 18> localMomentumSums(const Probe& p, const Vector& u, const Vector& Mv,
                                         const std::array<RCP<Vector>, 3>& w);
// P and L from the sums of every rank.
std::array<double, 6> momentumFromSums(const std::array<double, 18>& s);
// The set's indicator vectors e[c] (1 at its DOFs of component c).
std::array<RCP<Vector>, 3> setIndicators(const Probe& p, RCP<const Map> map);

template <class ApplyMass>
std::array<double, 6> setMomentum(const Probe& p, const Vector& u, const Vector& v, ApplyMass&& mass) {
  auto map = u.getMap();
  std::array<RCP<Vector>, 3> w = setIndicators(p, map);
  for (auto& wc : w) {
    Vector e(*wc, Teuchos::Copy);
    mass(e, *wc);
  }
  Vector Mv(map);
  mass(v, Mv);
  const std::array<double, 18> mine = localMomentumSums(p, u, Mv, w);
  std::array<double, 18> all{};
  Teuchos::reduceAll<int, double>(*map->getComm(), Teuchos::REDUCE_SUM, 18, mine.data(), all.data());
  return momentumFromSums(all);
}

}  // namespace choc
