// The exact solution against the SDNL111 document's tables and the wave speeds of the SDNL111
// definition (docs/verification/benchmarks.md).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "reference/BarImpactExact.hpp"

namespace {

using choc::BarImpactExact;
using choc::BarImpactParameters;

constexpr double kE = 2e11, kRho = 7800.0, kS = 4e-4, kL = 1.0;

BarImpactParameters bars(double c, double t0, bool bilateral) {
  BarImpactParameters p;
  p.length = kL;
  p.waveSpeed = c;
  p.impedance = kRho * c * kS;
  p.impactVelocity = -1.0;
  p.contactStart = t0;
  p.bilateral = bilateral;
  return p;
}

double bar1D() { return std::sqrt(kE / kRho); }
double oedometric() { return std::sqrt(kE * 0.7 / (kRho * 1.3 * 0.4)); }

struct Row {
  double time, reference;
};
// Sections 3.3 (A) and 4.3 (B); -1e-9 is the document's stand-in for 0 (absolute 1e-5).
const std::vector<Row> kTableA = {
    {2e-4, -1e-4}, {4e-4, -2e-4}, {6e-4, -1e-4}, {8e-4, 0.0}, {1e-3, 2e-4}};
const std::vector<Row> kTableB = {{2e-4, -1e-4}, {4e-4, -2e-4}, {6e-4, -1e-4}, {8e-4, 0.0},
                                  {1e-3, 1e-4},  {1.2e-3, 2e-4}, {1.4e-3, 1e-4}, {1.6e-3, 0.0}};
// Sections 5.3, 6.3, 7.3 (C, D, E).
const std::vector<Row> kTable3D = {
    {2e-4, -1.050e-4}, {4e-4, -1.550e-4}, {6e-4, -5.540e-5}, {8e-4, 9.920e-5}, {1e-3, 2.990e-4}};

TEST(BarImpactExact, WaveSpeedsMatchFormulasAndBrief) {
  const double c = BarImpactExact::barWaveSpeed(kE, kRho);
  const double cp = BarImpactExact::oedometricWaveSpeed(kE, 0.3, kRho);
  EXPECT_NEAR(c, bar1D(), 1e-9);
  EXPECT_NEAR(cp, oedometric(), 1e-9);
  EXPECT_NEAR(c, 5063.7, 0.05);  // benchmarks.md: 5063.7
  // benchmarks.md: "5875.3"; the formula gives 5875.097: 4 significant digits (5875) agree.
  EXPECT_NEAR(cp, 5875.0, 0.5);
  EXPECT_NEAR(cp, 5875.1, 0.01);
  // nu = 0: the oedometric speed is the bar speed.
  EXPECT_NEAR(BarImpactExact::oedometricWaveSpeed(kE, 0.0, kRho), c, 1e-9);
}

TEST(BarImpactExact, ContactForceMatchesBrief) {
  const BarImpactExact oneD(bars(bar1D(), 0.0, false));
  const BarImpactExact threeD(bars(oedometric(), 1e-5, false));
  EXPECT_NEAR(oneD.contactForce(1e-4), 7899.0, 0.5);
  EXPECT_NEAR(threeD.contactForce(1e-4), 9165.0, 0.5);
  EXPECT_DOUBLE_EQ(oneD.contactForceMagnitude(), 0.5 * kRho * bar1D() * kS);
}

TEST(BarImpactExact, Table3DIsTheExactSolutionRoundedTo3Digits) {
  const BarImpactExact exact(bars(oedometric(), 1e-5, false));
  for (const Row& r : kTable3D) {
    const double rel = std::abs(exact.displacementA(r.time) - r.reference) / std::abs(r.reference);
    if (r.time == 4e-4) {
      // The known inconsistency of E's 0.03 % row: the exact value is 0.27 % away.
      EXPECT_GT(rel, 2e-3) << "t = " << r.time;
      EXPECT_LT(rel, 3.5e-3) << "t = " << r.time;
      EXPECT_GT(rel, 3e-4) << "E's 0.03 % tolerance is unreachable by the exact solution";
    } else {
      EXPECT_LT(rel, 5e-3) << "t = " << r.time;
    }
  }
}

void expectTableExact(const BarImpactExact& exact, const std::vector<Row>& table) {
  for (const Row& r : table) {
    const double u = exact.displacementA(r.time);
    if (r.reference == 0.0) {
      EXPECT_LE(std::abs(u), 1e-15) << "t = " << r.time;
      EXPECT_LE(std::abs(u - (-1e-9)), 1e-5) << "t = " << r.time;  // the document's row
    } else {
      EXPECT_LE(std::abs(u - r.reference), 1e-12 * std::abs(r.reference)) << "t = " << r.time;
    }
  }
}

TEST(BarImpactExact, Tables1DAreExactForC5000) {
  expectTableExact(BarImpactExact(bars(5000.0, 0.0, false)), kTableA);
  expectTableExact(BarImpactExact(bars(5000.0, 0.0, true)), kTableB);
}

TEST(BarImpactExact, Tables1DAreNotTheExactSolutionForBarSpeed) {
  const BarImpactExact exact(bars(bar1D(), 0.0, false));
  for (double t : {4e-4, 6e-4, 1e-3}) {
    const double ref = t == 1e-3 ? 2e-4 : (t == 4e-4 ? -2e-4 : -1e-4);
    EXPECT_GT(std::abs(exact.displacementA(t) - ref) / std::abs(ref), 0.01) << "t = " << t;
  }
  EXPECT_NEAR(exact.displacementA(2e-4), -1e-4, 1e-18);  // before the first reflection
}

// Which document rows the exact solution (c = sqrt(E/rho)) passes with the document's own
// tolerances. Fact found here: A misses 3 rows (6e-4 and 1e-3 by 5.03 %, 8e-4 by
// 1.0064e-5 > 1e-5 absolute); B misses 4 (6e-4, 1.2e-3, 1.4e-3, and 1.6e-3 absolute).
TEST(BarImpactExact, DocumentTolerancesWithBarSpeed) {
  struct Tol {
    double time, reference, tolerance;
    bool relative, passes;
  };
  const std::vector<Tol> a = {{2e-4, -1e-4, 0.01, true, true},
                              {4e-4, -2e-4, 0.035, true, true},
                              {6e-4, -1e-4, 0.05, true, false},
                              {8e-4, -1e-9, 1e-5, false, false},
                              {1e-3, 2e-4, 0.035, true, false}};
  const std::vector<Tol> b = {{2e-4, -1e-4, 0.01, true, true},    {4e-4, -2e-4, 0.035, true, true},
                              {6e-4, -1e-4, 0.05, true, false},   {8e-4, -1e-9, 1e-5, false, true},
                              {1e-3, 1e-4, 0.07, true, true},     {1.2e-3, 2e-4, 0.05, true, false},
                              {1.4e-3, 1e-4, 0.07, true, false},  {1.6e-3, -1e-9, 1e-5, false, false}};
  const auto run = [](const BarImpactExact& exact, const std::vector<Tol>& rows) {
    for (const Tol& r : rows) {
      const double d = std::abs(exact.displacementA(r.time) - r.reference);
      const double err = r.relative ? d / std::abs(r.reference) : d;
      EXPECT_EQ(err <= r.tolerance, r.passes) << "t = " << r.time << " error " << err;
    }
  };
  run(BarImpactExact(bars(bar1D(), 0.0, false)), a);
  run(BarImpactExact(bars(bar1D(), 0.0, true)), b);
}

}  // namespace
