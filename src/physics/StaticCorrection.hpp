// Static correction of a modal basis: the basis enriched by the structure's static
// responses to unit forces at the shock links' nodes, along their shapes' normal directions
// (planes: e; circles: e2 and e3), which carry the local flexibility a truncated basis misses at
// a stop. Each response psi = (K + s M)^-1 f (s = 0, or 1 % of the lowest flexible eigenvalue
// when the basis has rigid-body modes, K being singular then) is M-orthogonalised against the
// modes and the others (dropped when it lies in their span), and the enlarged set is made M-
// and K-orthogonal by a Rayleigh-Ritz step (the dense generalised eigenproblem of [Phi Psi]):
// the result is a basis like any other, M-orthonormal with its eigenvalues.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/Vec3.hpp"
#include "physics/ModalBasis.hpp"
#include "physics/Model.hpp"

namespace choc {

struct StaticLoad {
  int node = -1;
  Vec3 direction{};
};

struct StaticCorrection {
  std::shared_ptr<const ModalBasis> basis;  // the enriched basis
  int added = 0;                            // static modes kept
  int dropped = 0;                          // loads whose response lay in the basis' span
};

// Throws NumericalError when the static solve or the eigenproblem fails.
StaticCorrection enrichWithStaticModes(const ModalBasis& basis, Model& model,
                                       const std::vector<StaticLoad>& loads, double rigidFrequencyHz);

}  // namespace choc
