// The Newmark family on a one-DOF oscillator m u'' + c u' + k u = 0 (STYLE: integrators are
// tested on a one-DOF oscillator): measured order of accuracy over halvings of dt for every
// preset, energy conservation of average acceleration, and the numerical damping of HHT and
// modified average acceleration against the spectral radius of the scheme's amplification
// matrix (derived here from the scheme's defining equations, independently of the driver).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <complex>
#include <vector>

#include <Teuchos_DefaultMpiComm.hpp>
#include <Teuchos_LAPACK.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Errors.hpp"
#include "timeint/CentralDifferenceStepper.hpp"
#include "timeint/NewmarkStepper.hpp"

namespace choc {
namespace {

class Oscillator : public ExplicitOperator {
 public:
  Oscillator(double m, double c, double k) : m_(m), c_(c), k_(k) {
    RCP<const Comm> self = rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
    map_ = rcp(new Map(1, 0, self));
  }
  RCP<const Map> map() const override { return map_; }
  void applyMass(const Vector& a, Vector& out) override { set(out, m_ * get(a)); }
  void applyForces(const Vector& u, const Vector& v, double, Vector& out) override {
    set(out, c_ * get(v) + k_ * get(u));
  }
  double addConstraintForces(const Vector&, const Vector&, Vector&) override { return 0.0; }
  CorrectionStatus solveCorrection(const EffectiveCoefficients& c, const Vector&, const Vector& r,
                                   Vector& du) override {
    set(du, -get(r) / (c.ca * m_ + c.cv * c_ + c.cd * k_));
    CorrectionStatus s;
    s.ok = true;
    return s;
  }
  ConstraintUpdate updateConstraints(const Vector&) override { return {}; }
  static double get(const Vector& x) { return x.getData()[0]; }
  static void set(Vector& x, double v) { x.getDataNonConst()[0] = v; }

 private:
  double m_, c_, k_;
  RCP<const Map> map_;
};

struct Recorder : StepObserver {
  std::vector<double> t, u, v;
  void stepAccepted(const StepInfo& i, const Vector& uu, const Vector& vv, const Vector&) override {
    t.push_back(i.time);
    u.push_back(Oscillator::get(uu));
    v.push_back(Oscillator::get(vv));
  }
};

// Free response from u0 = 1, v0 = 0.
Recorder integrate(const NewmarkFamily& s, double omega, double xi, double dt, double end) {
  Oscillator osc(1.0, 2 * xi * omega, omega * omega);
  TransientSettings ts;
  ts.timeStep = dt;
  ts.endTime = end;
  ts.newton.residualTolerance = 1e-10;
  ts.newton.incrementTolerance = 1e-10;
  Vector u(osc.map()), v(osc.map());
  Oscillator::set(u, 1.0);
  NewmarkStepper d(osc, s, ts);
  Recorder rec;
  d.addObserver(&rec);
  d.run(u, v);
  return rec;
}

double exactU(double omega, double xi, double t) {
  const double wd = omega * std::sqrt(1 - xi * xi);
  return std::exp(-xi * omega * t) * (std::cos(wd * t) + xi * omega / wd * std::sin(wd * t));
}

std::vector<NewmarkFamily> presets() {
  return {NewmarkFamily::averageAcceleration(), NewmarkFamily::modifiedAverageAcceleration(-0.1),
          NewmarkFamily::modifiedAverageAcceleration(-0.3), NewmarkFamily::hht(-0.1),
          NewmarkFamily::hht(-0.3), NewmarkFamily::generalizedAlpha(0.5),
          NewmarkFamily::generalizedAlpha(0.0), NewmarkFamily::newmark(0.3025, 0.6)};
}

TEST(NewmarkFamily, MeasuredOrderOfAccuracyMatchesTheStatedOrder) {
  const double omega = 2 * M_PI, xi = 0.02, end = 1.0;
  for (const auto& s : presets()) {
    std::vector<double> err;
    for (int n : {40, 80, 160, 320, 640}) {
      const Recorder r = integrate(s, omega, xi, 1.0 / n, end);
      ASSERT_NEAR(r.t.back(), end, 1e-12);
      // Error of the whole state (u, v/omega) at the end, measured by its largest value over
      // the run so that a sign change of one component at t = end cannot fake the order.
      double e = 0;
      for (size_t k = 0; k < r.t.size(); ++k) {
        const double h = 1e-7;
        const double ve = (exactU(omega, xi, r.t[k] + h) - exactU(omega, xi, r.t[k] - h)) / (2 * h);
        e = std::max(e, std::hypot(r.u[k] - exactU(omega, xi, r.t[k]), (r.v[k] - ve) / omega));
      }
      err.push_back(e);
    }
    for (size_t i = 0; i + 1 < err.size(); ++i) {
      const double p = std::log2(err[i] / err[i + 1]);
      // The observed order tends to the stated one as dt -> 0: the last halvings are within
      // 0.1 of it (the next term of the error expansion is one order higher).
      std::printf("  %-32s halving %zu: observed order %.3f\n", s.name().c_str(), i, p);
      if (i + 2 >= err.size())
        EXPECT_NEAR(p, s.order(), 0.1) << s.describe() << " halving " << i;
    }
  }
}

TEST(NewmarkFamily, AverageAccelerationConservesEnergy) {
  for (double Omega : {0.1, 1.0, 100.0}) {  // omega dt, up to far beyond resolution
    const double omega = 3.0, dt = Omega / omega;
    const Recorder r = integrate(NewmarkFamily::averageAcceleration(), omega, 0.0, dt, 2000 * dt);
    const double e0 = 0.5 * omega * omega;
    double worst = 0;
    for (size_t i = 0; i < r.u.size(); ++i) {
      const double e = 0.5 * r.v[i] * r.v[i] + 0.5 * omega * omega * r.u[i] * r.u[i];
      worst = std::max(worst, std::abs(e - e0) / e0);
    }
    // The trapezoidal rule conserves the energy exactly; only round-off remains.
    EXPECT_LT(worst, 1e-11) << "Omega = " << Omega;
  }
}

// Eigenvalues of the amplification matrix x_{n+1} = A x_n, x = (u, v, a), of the undamped
// oscillator (m = 1, k = omega^2) under the generalized-alpha equations.
std::vector<std::complex<double>> amplificationEigenvalues(const NewmarkFamily& s, double omega,
                                                           double dt) {
  const double b = s.beta(), g = s.gamma(), af = s.alphaF(), am = s.alphaM(), w2 = omega * omega;
  // L x_{n+1} = R x_n, column-major.
  double L[9] = {(1 - af) * w2, 1, 0, 0, 0, 1, (1 - am), -b * dt * dt, -g * dt};
  double R[9] = {-af * w2, 1, 0, 0, dt, 1, -am, (0.5 - b) * dt * dt, (1 - g) * dt};
  Teuchos::LAPACK<int, double> lapack;
  int ipiv[3], info = 0;
  lapack.GESV(3, 3, L, 3, ipiv, R, 3, &info);
  EXPECT_EQ(info, 0);
  double wr[3], wi[3], work[64], dummy[1];
  lapack.GEEV('N', 'N', 3, R, 3, wr, wi, dummy, 1, dummy, 1, work, 64, nullptr, &info);
  EXPECT_EQ(info, 0);
  std::vector<std::complex<double>> ev;
  for (int i = 0; i < 3; ++i) ev.push_back({wr[i], wi[i]});
  return ev;
}

TEST(NewmarkFamily, NumericalDampingMatchesTheSpectralRadius) {
  for (const auto& s : {NewmarkFamily::hht(-0.1), NewmarkFamily::hht(-0.3),
                        NewmarkFamily::modifiedAverageAcceleration(-0.1),
                        NewmarkFamily::modifiedAverageAcceleration(-0.3),
                        NewmarkFamily::generalizedAlpha(0.6)}) {
    for (double Omega : {0.3, 1.0, 2.0}) {
      const double omega = 1.0, dt = Omega / omega;
      const auto ev = amplificationEigenvalues(s, omega, dt);
      std::complex<double> principal = 0;
      for (auto e : ev)
        if (std::abs(e.imag()) > 0 && std::abs(e) > std::abs(principal)) principal = e;
      ASSERT_GT(std::abs(principal.imag()), 0) << s.describe() << " Omega " << Omega;
      const double rho = std::abs(principal);
      const Recorder r = integrate(s, omega, 0.0, dt, 400 * dt);
      // For u_n = a l^n + conj(a l^n), d_n = u_n^2 - u_{n+1} u_{n-1} = C |l|^(2n): the measured
      // per-step decay, once the spurious root has died out (after 60 steps).
      auto d = [&](int n) { return r.u[n] * r.u[n] - r.u[n + 1] * r.u[n - 1]; };
      const int n0 = 60, n1 = 260;
      const double measured = std::pow(d(n1) / d(n0), 1.0 / (2.0 * (n1 - n0)));
      EXPECT_NEAR(measured, rho, 1e-6 * rho) << s.describe() << " Omega " << Omega;
      EXPECT_LT(rho, 1.0);
    }
    // High-frequency limit: the closed form of rho_inf against the amplification matrix.
    double rhoInf = 0;
    for (auto e : amplificationEigenvalues(s, 1.0, 1e7)) rhoInf = std::max(rhoInf, std::abs(e));
    EXPECT_NEAR(s.spectralRadiusAtInfinity(), rhoInf, 1e-4) << s.describe();
  }
  // Average acceleration does not damp: rho = 1 at every omega dt.
  for (double Omega : {0.3, 3.0, 300.0}) {
    double rho = 0;
    for (auto e : amplificationEigenvalues(NewmarkFamily::averageAcceleration(), 1.0, Omega))
      rho = std::max(rho, std::abs(e));
    EXPECT_NEAR(rho, 1.0, 1e-12);
  }
}

TEST(NewmarkFamily, PresetsHaveTheDocumentedCoefficients) {
  const auto m = NewmarkFamily::modifiedAverageAcceleration(-0.1);
  EXPECT_DOUBLE_EQ(m.beta(), 0.3025);
  EXPECT_DOUBLE_EQ(m.gamma(), 0.6);
  EXPECT_EQ(m.alphaF(), 0.0);
  EXPECT_EQ(m.order(), 1);
  const auto h = NewmarkFamily::hht(-0.3);
  EXPECT_DOUBLE_EQ(h.beta(), 0.4225);
  EXPECT_DOUBLE_EQ(h.gamma(), 0.8);
  EXPECT_DOUBLE_EQ(h.alphaF(), 0.3);
  EXPECT_EQ(h.order(), 2);
  EXPECT_NEAR(h.spectralRadiusAtInfinity(), 0.7 / 1.3, 1e-15);
  EXPECT_EQ(NewmarkFamily::averageAcceleration().order(), 2);
  EXPECT_EQ(NewmarkFamily::generalizedAlpha(0.3).order(), 2);
  for (const auto& s : presets()) EXPECT_TRUE(s.unconditionallyStable()) << s.describe();
}

TEST(NewmarkFamily, OutOfRangeParametersAreErrorsNamingTheParameter) {
  auto param = [](auto f) {
    try {
      f();
    } catch (const SchemeRangeError& e) {
      return e.parameter();
    }
    return std::string("no error");
  };
  EXPECT_EQ(param([] { NewmarkFamily::hht(-0.34); }), "Alpha");
  EXPECT_EQ(param([] { NewmarkFamily::hht(0.01); }), "Alpha");
  EXPECT_EQ(param([] { NewmarkFamily::modifiedAverageAcceleration(-0.5); }), "Alpha");
  EXPECT_EQ(param([] { NewmarkFamily::generalizedAlpha(1.2); }), "Spectral Radius");
  EXPECT_EQ(param([] { NewmarkFamily::newmark(0.25, 0.4); }), "Gamma");
  EXPECT_EQ(param([] { NewmarkFamily::newmark(0.2, 0.5); }), "Beta");
  EXPECT_EQ(param([] { NewmarkFamily::hht(-1.0 / 3.0); }), "no error");
}

// A failing step is cut, and the run stops with a clear error when cuts run out.
class FailingOscillator : public Oscillator {
 public:
  using Oscillator::Oscillator;
  double failAbove = 1e300;  // dt above which every correction fails
  CorrectionStatus solveCorrection(const EffectiveCoefficients& c, const Vector& u, const Vector& r,
                                   Vector& du) override {
    if (c.ca > 0 && c.cv == 0 && c.cd == 0) return Oscillator::solveCorrection(c, u, r, du);
    const double dt = std::sqrt(1.0 / (0.25 * c.ca));  // average acceleration: ca = 4/dt^2
    if (dt > failAbove) {
      CorrectionStatus s;
      s.message = "injected failure";
      return s;
    }
    return Oscillator::solveCorrection(c, u, r, du);
  }
};

// The grid's start time shifts the run (the oscillator does not depend on t): from u0 = 1 at
// t0 = 0.5, the state at t0 + s is the state at s of the run from 0, to round-off of the times.
TEST(NewmarkStepper, AStartTimeShiftsTheRun) {
  Oscillator a(1.0, 0.1, 40.0), b(1.0, 0.1, 40.0);
  TransientSettings ts;
  ts.timeStep = 0.01;
  ts.endTime = 1.0;
  ts.newton.residualTolerance = 1e-12;
  ts.newton.incrementTolerance = 1e-12;
  Vector u(a.map()), v(a.map()), u2(b.map()), v2(b.map());
  Oscillator::set(u, 1.0);
  Oscillator::set(u2, 1.0);
  NewmarkStepper da(a, NewmarkFamily::hht(-0.1), ts);
  ts.startTime = 0.5;
  ts.endTime = 1.5;
  NewmarkStepper db(b, NewmarkFamily::hht(-0.1), ts);
  Recorder ra, rb;
  da.addObserver(&ra);
  db.addObserver(&rb);
  da.run(u, v);
  db.run(u2, v2);
  ASSERT_EQ(ra.t.size(), 101u);
  ASSERT_EQ(rb.t.size(), ra.t.size());
  EXPECT_EQ(rb.t.front(), 0.5);
  EXPECT_EQ(rb.t.back(), 1.5);
  for (size_t k = 0; k < ra.t.size(); ++k) {
    EXPECT_NEAR(rb.t[k] - 0.5, ra.t[k], 1e-12) << k;
    EXPECT_NEAR(rb.u[k], ra.u[k], 1e-9) << k;
  }
}

TEST(NewmarkStepper, CutsDtOnFailureAndStopsWhenCutsRunOut) {
  FailingOscillator osc(1.0, 0.0, 1.0);
  osc.failAbove = 0.03;
  TransientSettings ts;
  ts.timeStep = 0.1;
  ts.endTime = 1.0;
  ts.maxCuts = 2;  // 0.1 -> 0.05 -> 0.025 < 0.03: accepted after two cuts
  Vector u(osc.map()), v(osc.map());
  Oscillator::set(u, 1.0);
  NewmarkStepper d(osc, NewmarkFamily::averageAcceleration(), ts);
  Recorder rec;
  d.addObserver(&rec);
  const TransientSummary sum = d.run(u, v);
  EXPECT_EQ(sum.steps, 40);
  EXPECT_NEAR(rec.t.back(), 1.0, 1e-12);
  // The converged solution with the smaller step is a proper solution.
  EXPECT_NEAR(rec.u.back(), std::cos(1.0), 1e-3);

  FailingOscillator osc2(1.0, 0.0, 1.0);
  osc2.failAbove = 0.01;
  NewmarkStepper d2(osc2, NewmarkFamily::averageAcceleration(), ts);
  Recorder rec2;
  d2.addObserver(&rec2);
  Vector u2(osc2.map()), v2(osc2.map());
  Oscillator::set(u2, 1.0);
  try {
    d2.run(u2, v2);
    FAIL() << "expected a NumericalError";
  } catch (const std::exception& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("t = 0.000000e+00"), std::string::npos) << msg;
    EXPECT_NE(msg.find("injected failure"), std::string::npos) << msg;
    EXPECT_NE(msg.find("2 cut(s)"), std::string::npos) << msg;
  }
  EXPECT_EQ(rec2.t.size(), 1u);  // only the initial state was ever reported
}

}  // namespace
}  // namespace choc

namespace choc {
namespace {

// Central differences (CentralDifferenceStepper) on the undamped oscillator from u0 = 1 at rest: the
// discrete solution is u_n = cos(w~ n h) with cos(w~ h) = 1 - (w h)^2 / 2 (the scheme's
// defining recurrence u_{n+1} - 2 u_n + u_{n-1} = -(w h)^2 u_n, started by
// u_1 = 1 - (w h)^2 / 2), for any h below 2 / w; above it the state grows without bound and
// the driver says so.
Recorder integrateExplicit(double omega, double dt, double end, int substeps) {
  Oscillator osc(1.0, 0.0, omega * omega);
  TransientSettings ts;
  ts.timeStep = dt;
  ts.endTime = end;
  Vector u(osc.map()), v(osc.map());
  Oscillator::set(u, 1.0);
  auto inverseMass = rcp(new Vector(osc.map()));
  inverseMass->putScalar(1.0);
  CentralDifferenceStepper d(osc, inverseMass, ts, substeps);
  Recorder rec;
  d.addObserver(&rec);
  d.run(u, v);
  return rec;
}

TEST(CentralDifferenceStepper, CentralDifferencesFollowTheirDiscreteSolution) {
  const double omega = 100.0;
  for (double h : {1e-3, 1e-2, 1.9e-2}) {
    const Recorder r = integrateExplicit(omega, h, 200 * h, 1);
    const double wt = std::acos(1 - 0.5 * omega * omega * h * h) / h;
    ASSERT_EQ(r.u.size(), 201u);
    for (size_t n = 0; n < r.u.size(); ++n)
      ASSERT_NEAR(r.u[n], std::cos(wt * r.t[n]), 1e-10) << "h = " << h << ", step " << n;
  }
}

TEST(CentralDifferenceStepper, SubstepsAreStepsOfTheirOwnLength) {
  // 4 sub-steps of h / 4 reproduce the discrete solution at h / 4, seen every 4th step.
  const double omega = 100.0, h = 1e-2;
  const Recorder r = integrateExplicit(omega, h, 50 * h, 4);
  const double wt = std::acos(1 - 0.5 * omega * omega * (h / 4) * (h / 4)) / (h / 4);
  for (size_t n = 0; n < r.u.size(); ++n) ASSERT_NEAR(r.u[n], std::cos(wt * r.t[n]), 1e-10);
}

TEST(CentralDifferenceStepper, AStepAboveTheStabilityLimitStopsTheRun) {
  // h = 2.1 / w: |u| grows by about 2 per step; within 2000 steps it overflows.
  EXPECT_THROW(integrateExplicit(100.0, 2.1e-2, 2000 * 2.1e-2, 1), NumericalError);
}

}  // namespace
}  // namespace choc
