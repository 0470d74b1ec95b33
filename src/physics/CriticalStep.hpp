// The critical step of explicit central differences on the nodal unknowns: an upper bound of
// the highest circular frequency of M^-1 K_t, where K_t is the stiffness with every penalty
// contact constraint active and every shock link pressing, by Gershgorin's theorem on the
// symmetric M^-1/2 K_t M^-1/2 (its largest row sum of absolute values). M is diagonal (lumped).
// On a 1D bar of equal elements the bound is exact (2 c / h); in 3D it is conservative.
#pragma once
#include "contact/ContactManager.hpp"
#include "core/TpetraTypes.hpp"
#include "physics/DirectLinks.hpp"

namespace choc {

// massDiagonal: M_ii on K's row map (positive). contact (may be null) with its penalty
// stiffness per slave node; links may be null. Collective; the same value on every rank.
double omegaMaxBound(const CrsMatrix& K, const Vector& massDiagonal, const ContactManager* contact,
                     double contactStiffness, const DirectLinks* links);

// The diagonal of M when M is diagonal with positive entries, else null (collective).
RCP<Vector> lumpedMassDiagonal(const CrsMatrix& M);

}  // namespace choc
