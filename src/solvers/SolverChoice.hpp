// The 'auto' linear solver ('Linear Solver/Method' = auto, the default): the method and the
// preconditioner picked by the problem's size and regime, the reason stated in the log.
//   - up to kAlwaysDirectUpTo unknowns: Direct (Amesos2 KLU2), cheap at that size; where the
//     tangent changes at every Newton iteration (finite-strain blocks: every solve a new
//     factorisation), only up to kChangingTangentDirectUpTo, then by the regime below (the 3D
//     TET10 rubber ball, 4,713 unknowns, mass-dominated: CG + Jacobi 0.2 s per step against
//     KLU2's 3 s);
//   - a matrix that is not symmetric positive definite (Continuous contact multipliers between
//     meshed bodies, friction, links; multipliers against rigid obstacles alone are condensed out
//     of an iterative solve, leaving K's and M's regime, contact/ContactCondensation.hpp, and
//     Lagrange's between meshed bodies projected out, contact/ContactProjection.hpp):
//     Direct, whatever the size (Jacobi has no diagonal to invert on a multiplier row), with
//     the distributed package (MUMPS, when the build has it) above kAlwaysDirectUpTo: it factors
//     on every rank where KLU2 gathers the system to rank 0 (measured on the scale scene's bars
//     with Lagrange contact, docs/performance/direct-packages.md: at 43,308 unknowns MUMPS takes
//     0.95 of KLU2's time on one rank and 0.61 on two, where KLU2 gains nothing); but GMRES +
//     Jacobi when mass-dominated (theta <= kJacobiUpTo) and only a few rows are not symmetric
//     (friction with Lagrange multipliers, which an iterative solve condenses or projects out);
//   - symmetric and mass-dominated (theta <= kJacobiUpTo, theta the largest ratio of a row's
//     stiffness to its mass in the Newton matrix): CG + Jacobi, whose iterations are bounded by
//     the condition number of D^-1 W, at most about 1 + theta;
//   - symmetric and stiffness-dominated: Direct up to kDirectUpTo unknowns (MUMPS when the build
//     has it: on a compact body it factors 8 times faster than KLU2, docs/performance/
//     direct-packages.md); beyond, CG + Jacobi while theta <= kLargeJacobiUpTo, then CG +
//     Multigrid (smoothed aggregation for elasticity, ElasticityMultigrid.hpp; Additive Schwarz,
//     ILU(0) per rank, when the caller has no node blocks to give it).
// Measured on the scale scene's bars (docs/performance/linear-solver-auto.md): at dt = 1e-6 s (theta 1.6 to 22)
// CG + Jacobi takes 0.4, 0.28, 0.22 and 0.11 of Direct's time at 9,648, 22,575, 43,308 and
// 134,592 unknowns and 0.55 of CG + Additive Schwarz's at 300,300; at dt = 1e-5 s (43,308
// unknowns) Direct takes 0.53 of Jacobi's time and 0.30 of Schwarz's. At 153,792 unknowns
// (adaptive linear tolerance) CG + Jacobi takes 0.57 of Schwarz's solve time at theta 1,190
// (dt = 1e-5 s) and 0.62 at theta 10,600 (dt = 3e-5 s, 427 iterations per solve); at theta
// 119,000 (dt = 1e-4 s) it exceeds 1,000 iterations per solve where Schwarz takes 333. Multigrid
// for elasticity (whole nodes aggregated, rigid-body modes; docs/performance/multigrid.md) takes
// 33 per solve there and 0.29 of Schwarz's linear-solve time on one rank; at theta 10,600 it
// takes 0.84 of Jacobi's time and at 1,190 2.6 times Jacobi's (its set-up dominates): the
// Jacobi limit stays where it was.
#pragma once
#include <limits>
#include <string>

#include "core/TpetraTypes.hpp"

namespace choc {

constexpr long long kAlwaysDirectUpTo = 5000;
constexpr long long kChangingTangentDirectUpTo = 1000;
constexpr long long kDirectUpTo = 100000;
constexpr double kJacobiUpTo = 100.0;
constexpr double kLargeJacobiUpTo = 1e4;

struct SolverRegime {
  long long unknowns = 0;             // global rows of K
  std::string notSymmetricBecause;    // empty: symmetric positive definite; else why not, e.g.
                                      // "contact method 'Lagrange' has multipliers"
  double stiffnessToMass = std::numeric_limits<double>::infinity();  // theta
  std::string distributedDirect;      // the direct package that factors on every rank ("": none)
  bool nodeBlocks = true;             // the caller can give Multigrid the model's node blocks
  // Not symmetric, but W (K and M) plus a tangent on a few rows (friction against obstacles,
  // the multipliers condensed): GMRES + Jacobi when mass-dominated, as CG + Jacobi would be.
  bool nearlySymmetric = false;
  // A new tangent at every Newton iteration (finite strain): a direct solve refactors each time.
  bool tangentChanges = false;
  long long alwaysDirectUpTo() const { return tangentChanges ? kChangingTangentDirectUpTo : kAlwaysDirectUpTo; }
  bool symmetricPositive() const { return notSymmetricBecause.empty(); }
};

struct SolverChoice {
  std::string method, preconditioner;  // 'Linear Solver' values; preconditioner "" for Direct
  std::string package;                 // Direct's package ("": the input's 'Direct Package')
  std::string reason;                  // one clause for the log
};

SolverChoice chooseLinearSolver(const SolverRegime& regime);

// theta = max_i kCoef sum_j |K_ij| / (mCoef sum_j |M_ij|) over the rows with stiffness, for a
// Newton matrix kCoef K + mCoef M (W = ca M + cv C + cd K with C = aK K + aM M: kCoef = cd +
// cv aK, mCoef = ca + cv aM); +inf when such a row has no mass. K and M share their row map.
// Collective.
double stiffnessToMassRatio(const CrsMatrix& K, const CrsMatrix& M, double mCoef, double kCoef);

}  // namespace choc
