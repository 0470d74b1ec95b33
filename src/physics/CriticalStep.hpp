// The critical step of explicit central differences on the nodal unknowns: an upper bound of
// the highest circular frequency of M^-1 K_t, where K_t is the stiffness with every penalty
// contact constraint active and every shock link pressing, by Gershgorin's theorem on the
// symmetric M^-1/2 K_t M^-1/2 (its largest row sum of absolute values), or by the element
// eigenvalue bound of the mesh plus Gershgorin's bound of the couplings, whichever is smaller.
// M is diagonal (lumped). On a 1D bar of equal elements both are exact (2 c / h); in 3D the
// element bound is the tighter.
#pragma once
#include <limits>

#include "contact/ContactManager.hpp"
#include "core/TpetraTypes.hpp"
#include "physics/DirectLinks.hpp"

namespace choc {

// massDiagonal: M_ii on K's row map (positive). contact (may be null) with its penalty
// stiffness per slave node; links may be null. `meshBound`, when finite, is another upper bound
// of the highest eigenvalue of (K, M) alone (the element bound, Model::eigenvalueBound): the
// result is then the smaller of Gershgorin's bound of the whole and the square root of
// meshBound plus Gershgorin's bound of the contact and link couplings alone (Weyl: the
// largest eigenvalue of a sum is at most the sum of the largest). Collective; the same value on
// every rank.
struct FrequencyBound {
  double omegaMax = 0.0;      // rad/s: the smaller of the two below
  double gershgorin = 0.0;    // rad/s: Gershgorin's bound of the whole
  double element = 0.0;       // rad/s: sqrt(meshBound + the couplings' Gershgorin bound)
};
FrequencyBound omegaMaxBound(const CrsMatrix& K, const Vector& massDiagonal, const ContactManager* contact,
                             double contactStiffness, const DirectLinks* links,
                             double meshBound = std::numeric_limits<double>::infinity());

// The diagonal of M when M is diagonal with positive entries, else null (collective).
RCP<Vector> lumpedMassDiagonal(const CrsMatrix& M);

}  // namespace choc
