// The direct transient's shock-link tangent against central differences (fd_tangent.hpp).
// DirectLinks computes d(residual)/du = dF/dd + (dv/du) dF/dw by central differences of the
// law (step 1e-8 of the link's length scale); here it is checked, for every obstacle shape,
// closed, with and without a dashpot, with the tangential laws sticking and sliding, on two
// nodes and against a fixed obstacle:
//   - against an independent central difference of the residual DirectLinks::addForces adds,
//     with v = v0 + (dv/du) (u - u0) as in a Newmark iteration (fd_tangent's step, 6e-10 m);
//   - against the law's closed-form derivative (below), where the law has one: every state
//     tested here (normal spring and dashpot, elastic-plastic stick and slip, velocity-reversal
//     slide and stick, planes and circles);
//   - and a perturbed tangent fails.
// The model: the two-bar HEX8 scene, one element per bar, every translation an unknown.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <Tpetra_Core.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "steel_bars_xml.hpp"
#include "contact/ShockLaw.hpp"
#include "fd_tangent.hpp"
#include "fem/Components.hpp"
#include "input/Validation.hpp"
#include "input/XmlInput.hpp"
#include "mesh/BarImpactMesh.hpp"
#include "mesh/ExodusMeshWriter.hpp"
#include "physics/DirectLinks.hpp"
#include "physics/Model.hpp"
#include "physics/ModelInput.hpp"

namespace choc {
namespace {

using test::Dense;

// ---------------------------------------------------------------------------------------
// The model: bars along z, 0.1 m each, 1e-5 m apart, one HEX8 each (16 nodes, 48 unknowns).

// Built once for the suite, dropped at its end (a Tpetra map must not outlive Kokkos).
std::unique_ptr<Model>& modelHolder() {
  static std::unique_ptr<Model> m;
  return m;
}

Model& model() {
  std::unique_ptr<Model>& m = modelHolder();
  if (m) return *m;
  auto comm = Tpetra::getDefaultComm();
  // ctest runs each test in a process of its own, several at a time: the first test to build the
  // model names its directory (a shared scene.exo was read half-written by another test).
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string dir =
      std::string(CHOC_BINARY_DIR) + "/test-scratch/link-tangents/" + (info ? info->name() : "suite");
  std::filesystem::create_directories(dir);
  BarImpactOptions o;
  o.dimension = 3;
  o.axis = 'z';
  o.length1 = o.length2 = 0.1;
  o.along1 = o.along2 = 1;
  o.gap = 1e-5;
  const std::string mesh = dir + "/scene.exo", file = dir + "/input.xml";
  if (comm->getRank() == 0) {
    writeExodusMesh(generateBarImpactMesh(o), mesh);
    std::ofstream(file) << R"(<ParameterList name="links">
  <ParameterList name="Mesh"><Parameter name="File" type="string" value=")" << mesh << R"("/></ParameterList>
  <ParameterList name="Model">
    <Parameter name="Active Components" type="string" value="DX DY DZ"/>
    <Parameter name="Partition" type="string" value="numbering"/>
)" << test::steelBarsMaterialAndBlocksXml() << R"(  </ParameterList>
  <ParameterList name="Analyses"/>
</ParameterList>
)";
  }
  comm->barrier();
  auto input = readXmlParameters(file);
  validate(*input, topLevelParameters(), InputLocation{file, ""});
  m = std::make_unique<Model>(*input, file, comm);
  return *m;
}

// ---------------------------------------------------------------------------------------
// 3 x 3 algebra (row-major) for the law's closed-form derivative.

using Mat3 = std::array<double, 9>;
Mat3 zero3() { return Mat3{}; }
Mat3 identity3() { return Mat3{1, 0, 0, 0, 1, 0, 0, 0, 1}; }
Mat3 outer(const Vec3& a, const Vec3& b) {
  Mat3 m{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[3 * i + j] = a[i] * b[j];
  return m;
}
Mat3 add(const Mat3& a, const Mat3& b, double sb = 1.0) {
  Mat3 m{};
  for (int k = 0; k < 9; ++k) m[k] = a[k] + sb * b[k];
  return m;
}
Mat3 scale(const Mat3& a, double s) { return add(zero3(), a, s); }
Mat3 mul(const Mat3& a, const Mat3& b) {
  Mat3 m{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) m[3 * i + j] += a[3 * i + k] * b[3 * k + j];
  return m;
}
Vec3 transposeTimes(const Mat3& a, const Vec3& v) {  // a^T v
  Vec3 r{0, 0, 0};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[j] += a[3 * i + j] * v[i];
  return r;
}
Vec3 times(const Vec3& v, double s) { return {v[0] * s, v[1] * s, v[2] * s}; }
Vec3 plus(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 unitOf(const Vec3& v) { return times(v, 1.0 / norm(v)); }

// d(force on node 2)/d(d) and /d(w) of the law, from its equations (page shock-links):
// F = F_n m + F_t, F_n = -Kn delta - Cn w.m, m the shape's normal (dm/dd = G), and F_t the
// elastic-plastic return map or the velocity-reversal law.
struct LawJacobian {
  Mat3 dd{}, dw{};
};

LawJacobian analyticJacobian(const ShockLawParameters& p, const ShockLawState& st, const Vec3& d, const Vec3& w,
                             double dt) {
  const ShockGeometry geo = shockGeometry(p, d);
  const Vec3& m = geo.normal;
  Mat3 G = zero3();
  if (p.shape == ObstacleShape::BiCercle || p.shape == ObstacleShape::BiCercInt) {
    const Vec3& e1 = p.frame.e1;
    const Vec3 dp = plus(d, times(e1, -dot(d, e1)));
    const double r = norm(dp);
    G = scale(add(add(identity3(), outer(e1, e1), -1.0), outer(m, m), -1.0), 1.0 / r);
    if (p.shape == ObstacleShape::BiCercInt) G = scale(G, -1.0);
  }
  const double rate = dot(w, m);
  const double Fn = -p.normalStiffness * geo.gap - p.normalDamping * rate;
  // dFn/dd = -Kn m - Cn G^T w, dFn/dw = -Cn m (as vectors).
  const Vec3 dFnd = plus(times(m, -p.normalStiffness), times(transposeTimes(G, w), -p.normalDamping));
  const Vec3 dFnw = times(m, -p.normalDamping);
  LawJacobian J;
  J.dd = add(outer(m, dFnd), scale(G, Fn));
  J.dw = outer(m, dFnw);
  if (!p.tangential()) return J;
  const Mat3 Pm = add(identity3(), outer(m, m), -1.0);
  const Vec3 wt = plus(w, times(m, -rate));
  // d wt/dd = -(m.w) G - m (G^T w)^T, d wt/dw = Pm.
  const Mat3 dwtd = add(scale(G, -rate), outer(m, transposeTimes(G, w)), -1.0);
  const Mat3 dwtw = Pm;
  const double limit = p.friction * Fn;
  Mat3 dftd, dftw;
  if (p.frictionLaw == FrictionLaw::ElasticPlastic) {
    const Vec3 s0 = st.closed ? st.tangentialSpring : Vec3{0, 0, 0};
    const Vec3 sp = plus(s0, times(wt, dt));  // s' = s0 + wt dt, s = Pm s'
    const Vec3 s = plus(sp, times(m, -dot(sp, m)));
    const Mat3 dspd = scale(dwtd, dt), dspw = scale(dwtw, dt);
    const Mat3 dsd = add(add(mul(Pm, dspd), scale(G, -dot(m, sp))), outer(m, transposeTimes(G, sp)), -1.0);
    const Mat3 dsw = mul(Pm, dspw);
    const Vec3 T = times(plus(times(s, p.tangentialStiffness), times(wt, p.tangentialDamping)), -1.0);
    const Mat3 dTd = scale(add(scale(dsd, p.tangentialStiffness), scale(dwtd, p.tangentialDamping)), -1.0);
    const Mat3 dTw = scale(add(scale(dsw, p.tangentialStiffness), scale(dwtw, p.tangentialDamping)), -1.0);
    if (p.friction > 0 && norm(T) > limit) {  // slip: mu Fn T / |T|
      const Vec3 t = unitOf(T);
      const Mat3 Q = scale(add(identity3(), outer(t, t), -1.0), limit / norm(T));
      dftd = add(mul(Q, dTd), outer(t, times(dFnd, p.friction)));
      dftw = add(mul(Q, dTw), outer(t, times(dFnw, p.friction)));
    } else {
      dftd = dTd, dftw = dTw;
    }
  } else {
    const bool wasSliding = st.closed ? st.sliding : true;
    const Vec3 last = st.closed ? st.tangentialVelocity : Vec3{0, 0, 0};
    const double speed = norm(wt);
    if (wasSliding && dot(wt, last) >= 0.0 && speed > 1e-6 && p.friction > 0) {  // -mu Fn wt / |wt|
      const Vec3 t = unitOf(wt);
      const Mat3 Q = scale(add(identity3(), outer(t, t), -1.0), -limit / speed);
      dftd = add(mul(Q, dwtd), outer(t, times(dFnd, -p.friction)));
      dftw = add(mul(Q, dwtw), outer(t, times(dFnw, -p.friction)));
    } else {  // Fslip - Kt Pm (d - d_slip) - Ct wt
      const Vec3 moved = plus(d, times(st.slipPosition, -1.0));
      const Mat3 dmovedd = add(add(Pm, scale(G, -dot(m, moved))), outer(m, transposeTimes(G, moved)), -1.0);
      dftd = add(scale(dmovedd, -p.tangentialStiffness), scale(dwtd, -p.tangentialDamping));
      dftw = scale(dwtw, -p.tangentialDamping);
    }
  }
  J.dd = add(J.dd, dftd);
  J.dw = add(J.dw, dftw);
  return J;
}

// ---------------------------------------------------------------------------------------
// The cases: one shape, closed at a penetration of 2e-6 m, approaching at 0.01 m/s and sliding
// tangentially at 0.05 m/s, in an obstacle frame in general position.

constexpr double kKn = 1e8, kPenetration = 2e-6, kDt = 1e-5;
constexpr double kVelocityFactor = 0.5 / (0.25 * kDt);  // gamma / (beta h): dv/du

enum class Variant { Spring, Dashpot, ElasticPlasticStick, ElasticPlasticSlip, ReversalSlide, ReversalStick };
const char* variantName(Variant v) {
  switch (v) {
    case Variant::Spring: return "spring";
    case Variant::Dashpot: return "spring and dashpot";
    case Variant::ElasticPlasticStick: return "elastic-plastic friction, sticking";
    case Variant::ElasticPlasticSlip: return "elastic-plastic friction, sliding";
    case Variant::ReversalSlide: return "velocity reversal, sliding";
    case Variant::ReversalStick: return "velocity reversal, sticking";
  }
  return "?";
}
const std::vector<Variant> kVariants = {Variant::Spring,           Variant::Dashpot,
                                        Variant::ElasticPlasticStick, Variant::ElasticPlasticSlip,
                                        Variant::ReversalSlide,    Variant::ReversalStick};

struct LinkCase {
  ShockLawParameters law;
  ShockLawState state;
  Vec3 d{}, w{};  // the relative position and velocity at the state
};

// The relative position d of a closed link of `shape` (side: which of the two planes), its
// distances on the law.
LinkCase linkCase(ObstacleShape shape, Variant v, double side) {
  LinkCase c;
  ShockLawParameters& p = c.law;
  p.shape = shape;
  p.frame = obstacleFrame({1, 2, -2}, 0.3);
  const Vec3 &e1 = p.frame.e1, &e2 = p.frame.e2, &e3 = p.frame.e3;
  p.normalStiffness = kKn;
  switch (shape) {
    case ObstacleShape::BiPlanY:
    case ObstacleShape::BiPlanZ: {
      p.dist1 = 4e-6, p.dist2 = 6e-6;
      const Vec3& e = shape == ObstacleShape::BiPlanY ? e2 : e3;
      const Vec3& o = shape == ObstacleShape::BiPlanY ? e3 : e2;
      c.d = plus(plus(times(e, side * (1e-5 - kPenetration)), times(e1, 3e-3)), times(o, -2e-3));
      break;
    }
    case ObstacleShape::PlanY:
    case ObstacleShape::PlanZ: {
      p.dist1 = 4e-6, p.dist2 = 6e-6;
      const Vec3& e = shape == ObstacleShape::PlanY ? e2 : e3;
      const Vec3& o = shape == ObstacleShape::PlanY ? e3 : e2;
      c.d = plus(plus(times(e, -(1e-5 - kPenetration)), times(e1, 3e-3)), times(o, -2e-3));
      break;
    }
    case ObstacleShape::BiCercle:
    case ObstacleShape::BiCercInt: {
      const bool inner = shape == ObstacleShape::BiCercInt;
      p.dist1 = inner ? 2e-3 : 4e-3, p.dist2 = inner ? 12e-3 : 6e-3;
      const double r = inner ? 1e-2 + kPenetration : 1e-2 - kPenetration;
      const double phi = side > 0 ? 0.7 : 2.5;
      c.d = plus(times(plus(times(e2, std::cos(phi)), times(e3, std::sin(phi))), r), times(e1, 5e-3));
      break;
    }
  }
  const Vec3 m = shockGeometry(p, c.d).normal;
  const Vec3 ta = e1, tb = unitOf(Vec3{m[1] * e1[2] - m[2] * e1[1], m[2] * e1[0] - m[0] * e1[2],
                                       m[0] * e1[1] - m[1] * e1[0]});
  c.w = plus(plus(times(m, -0.01), times(ta, 0.04)), times(tb, 0.03));
  const Vec3 wt = plus(times(ta, 0.04), times(tb, 0.03));
  if (v != Variant::Spring) p.normalDamping = 2e3;  // +20 N while approaching
  if (v == Variant::Spring || v == Variant::Dashpot) return c;
  // Fn = 200 + 20 N: the cone mu Fn = 66 N.
  p.tangentialStiffness = 5e7, p.tangentialDamping = 100, p.friction = 0.3;
  ShockLawState& s = c.state;
  s.closed = true;
  switch (v) {
    case Variant::ElasticPlasticStick: s.tangentialSpring = plus(times(ta, -1e-7), times(tb, 5e-8)); break;  // ~6 N
    case Variant::ElasticPlasticSlip: s.tangentialSpring = plus(times(ta, -8e-6), times(tb, 5e-6)); break;  // ~470 N
    case Variant::ReversalSlide:
      p.frictionLaw = FrictionLaw::VelocityReversal;
      s.sliding = true;
      s.tangentialVelocity = wt;
      break;
    case Variant::ReversalStick:
      p.frictionLaw = FrictionLaw::VelocityReversal;
      s.sliding = false;
      s.tangentialVelocity = times(wt, -1.0);
      s.slipForce = plus(times(ta, 10.0), times(tb, -8.0));
      s.slipPosition = plus(c.d, plus(times(ta, -1e-7), times(tb, 2e-7)));  // ~11 N of spring
      break;
    default: break;
  }
  return c;
}

// The link of a case on the model: node A (bar 1) and node C (bar 2) or, without node 2, node
// A against a fixed obstacle; the state u0 (and v0) giving the case's d and w.
struct LinkSetup {
  std::unique_ptr<DirectLinks> links;
  double velocityFactor = kVelocityFactor;  // dv/du of the residual and the tangent
  std::vector<double> u0, v0;
  std::array<long long, 6> dofs{};  // DX DY DZ of node 1, node 2 (-1: none)
};

LinkSetup setup(const LinkCase& c, bool twoNodes) {
  Model& m = model();
  const Mesh& mesh = m.mesh();
  const int nodeA = m.nodeSet("N1", "node 1").nodes[0], nodeC = m.nodeSet("C", "node 2").nodes[0];
  LinkSetup s;
  const int nU = int(m.map()->getGlobalNumElements());
  s.u0.assign(size_t(nU), 0.0);
  s.v0.assign(size_t(nU), 0.0);
  for (int k = 0; k < nU; ++k) s.u0[size_t(k)] = 1e-6 * std::sin(1.7 * k), s.v0[size_t(k)] = 0.01 * std::cos(2.3 * k);
  ShockLink l;
  l.name = "stop";
  l.path = "Analyses/test/Shock Links/stop";
  l.node1 = nodeA;
  l.node2 = twoNodes ? nodeC : -1;
  l.law = c.law;
  l.state = c.state;
  l.x1 = mesh.coords[size_t(nodeA)];
  for (int k = 0; k < 3; ++k) {
    s.dofs[size_t(k)] = m.dof(nodeA, DX + k);
    s.dofs[size_t(3 + k)] = twoNodes ? m.dof(nodeC, DX + k) : -1;
  }
  // The link's initial positions make d at u0, whose entries stay of 1e-6 m (the steps of the
  // differences are then of the scale, not of the node's displacement).
  Vec3 u1, u2{0, 0, 0}, v1;
  for (int k = 0; k < 3; ++k) u1[k] = s.u0[size_t(s.dofs[size_t(k)])], v1[k] = s.v0[size_t(s.dofs[size_t(k)])];
  for (int k = 0; k < 3 && twoNodes; ++k) u2[k] = s.u0[size_t(s.dofs[size_t(3 + k)])];
  for (int k = 0; k < 3; ++k) {  // x2 + u2 - (x1 + u1) = d
    l.x2[k] = l.x1[k] + u1[k] + c.d[k] - u2[k];
    if (twoNodes) s.v0[size_t(s.dofs[size_t(3 + k)])] = c.w[k] + v1[k];  // v2 - v1 = w
    else s.v0[size_t(s.dofs[size_t(k)])] = -c.w[k];                       // -v1 = w
  }
  s.links = std::make_unique<DirectLinks>(std::vector<ShockLink>{l}, m, m.map());
  s.links->beginStep(kDt);
  return s;
}

// The residual the links add at u, with v = v0 + (dv/du) (u - u0).
test::Residual linkResidual(LinkSetup& s) {
  return [&s](const std::vector<double>& u) {
    std::vector<double> v(u.size());
    for (size_t k = 0; k < u.size(); ++k) v[k] = s.v0[k] + s.velocityFactor * (u[k] - s.u0[k]);
    const RCP<const Map> map = model().map();
    Vector out(map);
    out.putScalar(0.0);
    s.links->addForces(*test::tpetraOf(u, map), *test::tpetraOf(v, map), out);
    return test::valuesOf(out);
  };
}

Dense linkTangent(LinkSetup& s) {
  linkResidual(s)(s.u0);  // the tangent is of the last evaluation
  const int nU = int(s.u0.size());
  Dense J(nU, nU);
  for (const MatrixEntry& e : s.links->tangent(s.velocityFactor)) J(int(e.row), int(e.col)) += e.value;
  return J;
}

// The closed form on the DOFs: R_a = -s_a F (s = -1 on node 1, +1 on node 2), d moving by
// s_b du_b: dR_a/du_b = -s_a s_b (dF/dd + (dv/du) dF/dw).
Dense analyticTangent(const LinkSetup& s, const LinkCase& c) {
  const LawJacobian L = analyticJacobian(c.law, c.state, c.d, c.w, kDt);
  const Mat3 Jt = add(L.dd, L.dw, s.velocityFactor);
  const int nU = int(s.u0.size());
  Dense J(nU, nU);
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k) {
          const long long row = s.dofs[size_t(3 * a + r)], col = s.dofs[size_t(3 * b + k)];
          if (row >= 0 && col >= 0) J(int(row), int(col)) += (a == b ? -1.0 : 1.0) * Jt[size_t(3 * r + k)];
        }
  return J;
}

// Every variant of `shape`, on two nodes (both sides of the planes, two points of the circles)
// and against a fixed obstacle, with dv/du = gamma / (beta h) (2e6 /s: the velocity terms
// dominate) and 0 (the position terms alone): the state is what the case says (closed, sliding
// or not), the assembled tangent matches central differences of the residual and the closed
// form, and a perturbed tangent fails.
void expectLinkTangents(ObstacleShape shape) {
  if (Tpetra::getDefaultComm()->getSize() != 1) GTEST_SKIP() << "a one-rank test";
  test::TangentCheckOptions opt;
  opt.scale = 2e-5;                // h = 1.2e-10 m, dv = 2.4e-5 m/s
  opt.residualScale = kKn * 0.02;  // the positions (0.01 m) the relative position is made of
  double worst = 0.0, worstClosedForm = 0.0, worstAgainstClosedForm = 0.0;
  for (Variant v : kVariants)
    for (const auto& [twoNodes, side] : {std::make_pair(true, 1.0), std::make_pair(true, -1.0), std::make_pair(false, 1.0)})
      for (double factor : {kVelocityFactor, 0.0}) {
        const LinkCase c = linkCase(shape, v, side);
        LinkSetup s = setup(c, twoNodes);
        s.velocityFactor = factor;
        const std::string what = std::string(obstacleShapeNames()[size_t(int(shape))]) + ", " + variantName(v) +
                                 ", " + (twoNodes ? "two nodes" : "fixed obstacle") + (side < 0 ? ", other side" : "") +
                                 (factor > 0 ? ", dv/du = 2e6" : ", dv/du = 0");
        const test::Residual R = linkResidual(s);
        const Dense J = linkTangent(s);
        // The state is the case's.
        ShockLawState st = c.state;
        const ShockResponse r = evaluateShock(c.law, c.d, c.w, kDt, st, false);
        ASSERT_TRUE(r.normalForce > 0) << what;
        EXPECT_NEAR(r.gap, -kPenetration, 1e-12) << what;
        EXPECT_EQ(r.sliding, v == Variant::ElasticPlasticSlip || v == Variant::ReversalSlide) << what;
        EXPECT_EQ(s.links->tangentKey()[0] & 1, 1) << what;  // pressing
        test::TangentCheck fd;
        EXPECT_TRUE(test::tangentMatches(R, J, s.u0, opt, &fd)) << what;
        const Dense A = analyticTangent(s, c);
        const auto closedForm = test::matricesMatch(J, A, 1e-6);
        EXPECT_TRUE(closedForm) << what;
        EXPECT_TRUE(test::tangentMatches(R, A, s.u0, opt)) << what << " (the closed form)";
        EXPECT_TRUE(test::tangentMismatches(R, test::perturbed(J), s.u0, opt)) << what;
        worst = std::max(worst, fd.relativeError);
        worstClosedForm = std::max(worstClosedForm, test::checkTangent(R, A, s.u0, opt).relativeError);
        worstAgainstClosedForm = std::max(worstAgainstClosedForm, test::relativeDifference(J, A));
        if (!fd.passed || !closedForm) std::cout << "  [" << what << "] " << fd.message() << "; " << closedForm.message() << "\n";
      }
  std::cout << "  " << obstacleShapeNames()[size_t(int(shape))]
            << ": largest relative error of the assembled tangent against central differences " << worst
            << ", of the closed form against them " << worstClosedForm
            << "; the assembled tangent against the closed form " << worstAgainstClosedForm << "\n";
}

class LinkTangents : public ::testing::Test {
 protected:
  static void TearDownTestSuite() { modelHolder().reset(); }
};

TEST_F(LinkTangents, BiPlanY) { expectLinkTangents(ObstacleShape::BiPlanY); }
TEST_F(LinkTangents, BiPlanZ) { expectLinkTangents(ObstacleShape::BiPlanZ); }
TEST_F(LinkTangents, BiCercle) { expectLinkTangents(ObstacleShape::BiCercle); }
TEST_F(LinkTangents, BiCercInt) { expectLinkTangents(ObstacleShape::BiCercInt); }
TEST_F(LinkTangents, PlanY) { expectLinkTangents(ObstacleShape::PlanY); }
TEST_F(LinkTangents, PlanZ) { expectLinkTangents(ObstacleShape::PlanZ); }

}  // namespace
}  // namespace choc
