// The contact tangents against central differences of their residuals (fd_tangent.hpp): each
// test checks that the tangent the Newton matrix receives passes at states exercising its
// branches, and that a perturbed tangent fails.
//
// The residual of a contact scene is the one the Newton system solves: at x = [u; lambda / S]
// the contact forces' share of the DOF rows (ContactManager::addForces: normal forces and
// Coulomb friction) and, with multipliers, the constraint rows (ContactActiveSet::rowResidual,
// which SaddlePointStrategy::rightHandSide negates). The tangent is the matrix EffectiveSystem::fill
// assembles (the contact block, k B^T B, -S B, the friction tangent) less aM M. Within a step
// the gaps are linear in u (g = g0 + B u, re-linearised before each step): the normal
// residuals are then piecewise linear and their differences exact; friction's slip is not.
// Such a test cannot see a row B that is not the gap's derivative (residual and matrix share
// it): the re-linearisation itself is checked on the geometry, the gap as a function of the
// positions against the row's coefficients: a curved obstacle's gap d(X + u) and normal
// n(X + u) after beginStep(u), the mortar gap G_j / D_j integrated on the moved faces and the
// node-to-face closest point's gap.
//
// Scenes: the two-bar scene (test_contact_helpers.hpp) turned by a rotation about a skew axis
// and shifted, so that every normal and tangent has three components; every component of
// every node is an unknown; K = I and M = kMass I (S = kMass with aM = 1, aK = 0).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "contact/ContactFaces.hpp"
#include "contact/ContactManager.hpp"
#include "contact/ContactPairing.hpp"
#include "contact/MortarLinearization.hpp"
#include "contact/MortarSegments.hpp"
#include "contact/ContactStrategies.hpp"
#include "physics/EffectiveSystem.hpp"
#include "contact/RigidObstacle.hpp"
#include "fd_tangent.hpp"
#include "test_contact_helpers.hpp"

namespace choc {
namespace {

using test::Dense;
using test::tangentMatches;
using test::tangentMismatches;

// ---------------------------------------------------------------------------------------
// Geometry: a rotation about a skew axis and a shift place the scene in general position.

struct Rotation {
  std::array<double, 9> q{};
  Vec3 operator()(const Vec3& v) const {
    return {q[0] * v[0] + q[1] * v[1] + q[2] * v[2], q[3] * v[0] + q[4] * v[1] + q[5] * v[2],
            q[6] * v[0] + q[7] * v[1] + q[8] * v[2]};
  }
};

Rotation rotation(Vec3 a, double angle) {  // Rodrigues
  const double l = norm(a);
  for (double& c : a) c /= l;
  const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
  Rotation r;
  r.q = {t * a[0] * a[0] + c,        t * a[0] * a[1] - s * a[2], t * a[0] * a[2] + s * a[1],
         t * a[0] * a[1] + s * a[2], t * a[1] * a[1] + c,        t * a[1] * a[2] - s * a[0],
         t * a[0] * a[2] - s * a[1], t * a[1] * a[2] + s * a[0], t * a[2] * a[2] + c};
  return r;
}

const Rotation kQ = rotation({0.3, -0.5, 0.8}, 0.7);
const Vec3 kShift{0.01, -0.02, 0.015};

Vec3 placedPoint(const Vec3& x) {
  const Vec3 y = kQ(x);
  return {y[0] + kShift[0], y[1] + kShift[1], y[2] + kShift[2]};
}

Mesh placed(Mesh m) {
  for (Point3& x : m.coords) x = placedPoint(x);
  return m;
}

RigidObstacle obstacle(RigidObstacle::Shape shape, Vec3 localPoint, Vec3 localDirection, double radius,
                       Vec3 localVelocity = {0, 0, 0}) {
  RigidObstacle o;
  o.shape = shape;
  o.point = placedPoint(localPoint);
  o.direction = kQ(localDirection);
  o.radius = radius;
  o.velocity = kQ(localVelocity);
  return validatedObstacle(o);
}

// A pair of the two-bar scene: `slave` against `master` (a side set), search distance 1e-3 m.
PairDefinition pairOf(const std::string& name, const std::string& master, const std::string& slave) {
  PairDefinition def;
  def.name = name;
  def.masterSideSet = master;
  def.slaveSideSet = slave;
  def.searchDistance = 1e-3;
  return def;
}

PairDefinition obstaclePair(const RigidObstacle& o, double friction = 0.0) {
  PairDefinition def = pairOf("wall", "", "CNT_POU2");
  def.hasObstacle = true;
  def.obstacle = o;
  def.friction = friction;
  return def;
}

// ---------------------------------------------------------------------------------------
// A contact scene: manager, saddle-point system and the residual/tangent pair of its x.

constexpr double kMass = 3e8;  // M = kMass I: S = kMass at aM = 1
constexpr double kDisplacementScale = 1e-5;
constexpr double kForceScale = 1e3;

RCP<CrsMatrix> diagonal(const RCP<const Map>& map, double value) {
  auto A = rcp(new CrsMatrix(map, 1));
  for (size_t l = 0; l < map->getNodeNumElements(); ++l) {
    const GO g = map->getGlobalElement(LO(l));
    A->insertGlobalValues(g, Teuchos::tuple<GO>(g), Teuchos::tuple<double>(value));
  }
  A->fillComplete();
  return A;
}

class Scene {
 public:
  // `local`: the scene before placement (its coordinates give the displacement fields).
  Scene(const Mesh& local, const std::vector<PairDefinition>& pairs, std::unique_ptr<ContactMethod> method)
      : local_(local), mesh_(placed(local)) {
    dofs_ = std::make_unique<DofMap>(std::vector<std::uint8_t>(size_t(mesh_.numNodes()), 7), 1, 0);
    map_ = rcp(new Map(Tpetra::global_size_t(dofs_->numGlobal()), 0, Tpetra::getDefaultComm()));
    contact_ = std::make_unique<ContactManager>(mesh_, *dofs_, map_, pairs, std::move(method));
    K_ = diagonal(map_, 1.0);
    M_ = diagonal(map_, kMass);
    if (contact_->method().hasMultipliers())
      strategy_ = std::make_unique<SaddlePointStrategy>(*contact_);
    else
      strategy_ = std::make_unique<PenaltyStrategy>(*contact_);
    system_ = std::make_unique<EffectiveSystem>(K_, M_, strategy_.get());
    system_->fill(1.0, 0.0);  // S = kMass
  }
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  ContactManager& contact() { return *contact_; }
  const Mesh& local() const { return local_; }
  const Mesh& mesh() const { return mesh_; }
  const DofMap& dofs() const { return *dofs_; }
  int nU() const { return int(dofs_->numGlobal()); }
  int nS() const { return contact_->numConstraints(); }
  bool multipliers() const { return strategy_->extendsSystem(); }
  int n() const { return nU() + (multipliers() ? nS() : 0); }

  // u from a displacement given per node in the local (unplaced) frame, turned into place.
  std::vector<double> displacement(const std::function<Vec3(int, const Point3&)>& f) const {
    std::vector<double> u(size_t(nU()), 0.0);
    for (int node = 0; node < mesh_.numNodes(); ++node) {
      const Vec3 v = kQ(f(node, local_.coords[size_t(node)]));
      for (int c = 0; c < 3; ++c) u[size_t(dofs_->dof(node, c))] = v[c];
    }
    return u;
  }
  RCP<Vector> vec(const std::vector<double>& u) const { return test::tpetraOf(u, map_); }

  // Statuses from the gaps at u, pressures zero (the saved state every evaluation starts from).
  void initialize(const std::vector<double>& u) { strategy_->initialize(*vec(u)); }
  void beginStep(const std::vector<double>& u, double t, double dt) { contact_->beginStep(*vec(u), t, dt); }

  // x = [u; lambda / S] (lambda of the saved state is zero).
  std::vector<double> state(const std::vector<double>& u, const std::vector<double>& lambda) const {
    std::vector<double> x = u;
    if (multipliers())
      for (double l : lambda) x.push_back(l / contact_->activeSet().scale);
    return x;
  }

  std::vector<double> residual(const std::vector<double>& x) {
    const auto u = vec(std::vector<double>(x.begin(), x.begin() + nU()));
    if (multipliers()) {
      strategy_->revert();
      contact_->activeSet().applyCorrection(std::vector<double>(x.begin() + nU(), x.end()));
    }
    Vector out(map_);
    out.putScalar(0.0);
    contact_->addForces(*u, out);
    std::vector<double> r = test::valuesOf(out);
    if (multipliers()) {
      const std::vector<double> g = contact_->gaps(*u);
      for (int s = 0; s < nS(); ++s) r.push_back(contact_->activeSet().rowResidual(size_t(s), g[size_t(s)]));
    }
    return r;
  }
  test::Residual residualFunction() {
    return [this](const std::vector<double>& x) { return residual(x); };
  }

  // The system's matrix at x (evaluated there first: the friction tangent is of the last
  // evaluation) less aM M.
  Dense tangent(const std::vector<double>& x) {
    residual(x);
    system_->fill(1.0, 0.0);
    Dense A = test::denseOf(*system_->matrix(), n(), n());
    for (int i = 0; i < nU(); ++i) A(i, i) -= kMass;
    return A;
  }

  test::TangentCheckOptions options() const {
    test::TangentCheckOptions o;
    o.scales.assign(size_t(n()), kDisplacementScale);
    for (int s = nU(); s < n(); ++s) o.scales[size_t(s)] = kForceScale / contact_->activeSet().scale;
    return o;
  }

  // Per constraint: 0 no friction force, 1 stick, 2 slip at the last evaluation.
  std::vector<int> frictionStatus() const {
    const std::vector<char> key = contact_->friction()->key();
    return std::vector<int>(key.begin(), key.begin() + nS());
  }

 private:
  Mesh local_, mesh_;
  std::unique_ptr<DofMap> dofs_;
  RCP<const Map> map_;
  std::unique_ptr<ContactManager> contact_;
  RCP<CrsMatrix> K_, M_;
  std::unique_ptr<ContactStrategy> strategy_;
  std::unique_ptr<EffectiveSystem> system_;
};

int count(const std::vector<int>& v, int value) { return int(std::count(v.begin(), v.end(), value)); }

// The interface of the two bars: bar 1's face CNT_POU1 (the slave) 1e-5 above bar 2's CNT_POU2
// (the master, its outward normal +z locally); 3 x 3 slave faces on 2 x 2 master faces, so
// that slave nodes project inside master faces with weights of every size.
constexpr double kGap = 1e-5;
Mesh barScene() { return test::barContactScene(3, 2, kGap); }
bool onBar1(const Point3& X) { return X[2] > 0.5 * kGap; }

// Bar 1 pressed into bar 2, more at x = 0 than at x = 0.02 (where it is open): locally
// u_z = -2e-5 + 1.2e-5 x / 0.02 on bar 1 (gaps -1e-5, -6e-6, -2e-6 and +2e-6 across its four
// columns of nodes), small lateral motion `lateral(X)` of its nodes, and a small motion of
// bar 2's nodes.
std::vector<double> pressed(const Scene& sc, const std::function<Vec3(const Point3&)>& lateral) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  return sc.displacement([&](int, const Point3& X) {
    const Vec3 r{noise(rng), noise(rng), noise(rng)};
    if (onBar1(X)) {
      const Vec3 l = lateral(X);
      return Vec3{l[0], l[1], -2e-5 + 1.2e-5 * X[0] / 0.02 + 2e-7 * r[2]};
    }
    return Vec3{1e-8 * r[0], 1e-8 * r[1], 2e-7 * r[2]};
  });
}

// Lateral motions of a face's nodes on a grid of `spacing`: size `small` where the node's
// grid indices sum to an even number, `large` elsewhere (a checkerboard), in directions that
// vary from node to node.
std::function<Vec3(const Point3&)> lateralMotion(double small, double large, double spacing) {
  return [=](const Point3& X) {
    const int i = int(std::lround(X[0] / spacing)), j = int(std::lround(X[1] / spacing));
    const double a = 2.4 * (4 * i + j) + 0.3, size = (i + j) % 2 == 0 ? small : large;
    return Vec3{size * std::cos(a), size * std::sin(a), 0.0};
  };
}
constexpr double kSlaveSpacing = 0.02 / 3, kObstacleFaceSpacing = 0.01;

// Pressures: 2e3 N x (1 + a node-dependent fraction) on the active nodes, and 37 N on the
// inactive ones (their rows read lambda = 0: the check covers them too).
std::vector<double> pressures(Scene& sc) {
  std::vector<double> l(size_t(sc.nS()));
  for (int s = 0; s < sc.nS(); ++s) l[size_t(s)] = sc.contact().status()[size_t(s)] ? 2e3 * (1 + 0.1 * s) : 37.0;
  return l;
}

// Both assertions of a tangent test: the real tangent passes, the perturbed one fails.
void expectTangent(Scene& sc, const std::vector<double>& x, const char* what) {
  const Dense J = sc.tangent(x);
  test::TangentCheck c;
  EXPECT_TRUE(tangentMatches(sc.residualFunction(), J, x, sc.options(), &c)) << what;
  std::cout << "  [" << what << "] " << c.message() << "\n";
  EXPECT_TRUE(tangentMismatches(sc.residualFunction(), test::perturbed(J), x, sc.options())) << what;
}

bool oneRank() { return Tpetra::getDefaultComm()->getSize() == 1; }

// ---------------------------------------------------------------------------------------
// Normal contact: penalty and the augmented Lagrangian.

// The scenes of the normal-contact tests: node to face, a sphere and a moving cylinder (both
// linearised at the last accepted state u_n before the step, then evaluated at u).
struct NormalCase {
  const char* name;
  std::vector<PairDefinition> pairs;
};

std::vector<NormalCase> normalCases() {
  return {
      {"node to face", {pairOf("ifc", "CNT_POU2", "CNT_POU1")}},
      // Bar 2's face (slave) under a sphere of radius 2 m touching it at its centre: the
      // centre node penetrates most, the corners stay open.
      {"sphere", {obstaclePair(obstacle(RigidObstacle::Shape::Sphere, {0.01, 0.01, 2.0 + 1e-5}, {0, 0, 1}, 2.0))}},
      {"moving cylinder",
       {obstaclePair(obstacle(RigidObstacle::Shape::Cylinder, {0.01, 0.01, 1.0 + 1e-5}, {1, 0.2, 0}, 1.0,
                              {0.3, -0.1, 0.05}))}},
  };
}

// u for a normal-contact case: bar 1 pressed into bar 2 (node to face), or bar 2 pushed up
// into the obstacle by 5e-5 (its centre penetrates by 4e-5, the corners stay open).
std::vector<double> normalState(const Scene& sc, const NormalCase& c) {
  if (!c.pairs[0].hasObstacle) return pressed(sc, lateralMotion(1e-6, 2e-6, kSlaveSpacing));
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  return sc.displacement([&](int, const Point3& X) {
    const Vec3 r{noise(rng), noise(rng), noise(rng)};
    return onBar1(X) ? Vec3{0, 0, 0} : Vec3{1e-6 * r[0], 1e-6 * r[1], 5e-5 + 2e-7 * r[2]};
  });
}

void expectMixedStatuses(Scene& sc, const char* what) {
  const int active = sc.contact().activeCount();
  EXPECT_GT(active, 0) << what;
  EXPECT_LT(active, sc.nS()) << what << ": the test wants inactive nodes too";
}

TEST(ContactTangents, PenaltyNodeToFaceAndCurvedObstacles) {
  if (!oneRank()) GTEST_SKIP() << "a one-rank test";
  for (const NormalCase& c : normalCases()) {
    Scene sc(barScene(), c.pairs, makePenaltyContact(1e9, 1e-12));
    const std::vector<double> un(size_t(sc.nU()), 0.0);
    sc.beginStep(un, 1e-4, 1e-5);  // curved obstacles: linearised at u_n
    const std::vector<double> u = normalState(sc, c);
    sc.initialize(u);
    expectMixedStatuses(sc, c.name);
    expectTangent(sc, u, c.name);
  }
}

TEST(ContactTangents, AugmentedLagrangianWithPressures) {
  if (!oneRank()) GTEST_SKIP() << "a one-rank test";
  for (const NormalCase& c : normalCases()) {
    Scene sc(barScene(), c.pairs, makeAugmentedLagrangianContact(5e8, 1e-12));
    const std::vector<double> un(size_t(sc.nU()), 0.0);
    sc.beginStep(un, 1e-4, 1e-5);
    const std::vector<double> u = normalState(sc, c);
    sc.initialize(u);
    expectMixedStatuses(sc, c.name);
    ASSERT_TRUE(sc.multipliers());
    expectTangent(sc, sc.state(u, pressures(sc)), c.name);
  }
}

// ---------------------------------------------------------------------------------------
// Coulomb friction.

std::unique_ptr<ContactMethod> method(const std::string& name) {
  if (name == "Penalty") return makePenaltyContact(1e9, 1e-12);
  if (name == "Continuous") return makeAugmentedLagrangianContact(5e8, 1e-12);
  return makeLagrangeContact(1e-12);
}

// Node to face with friction mu = 0.3 and k_t = 1e9 N/m: the step starts at u_n = 0, the
// iterate u moves bar 1's nodes laterally by `small` or `large` (a checkerboard). Normal
// forces of the active nodes: 2e3 to 1e4 N (penalty), 2e3 N and more (multipliers): the stick
// band mu f_N / k_t is 6e-7 m at least, 4.5e-6 m at most.
void frictionNodeToFace(const std::string& name, double small, double large, bool sliding) {
  PairDefinition def = pairOf("ifc", "CNT_POU2", "CNT_POU1");
  def.friction = 0.3;
  Scene sc(barScene(), {def}, method(name));
  sc.contact().friction()->setTangentialStiffness(1e9);
  sc.beginStep(std::vector<double>(size_t(sc.nU()), 0.0), 1e-4, 1e-5);
  const std::vector<double> u = pressed(sc, lateralMotion(small, large, kSlaveSpacing));
  sc.initialize(u);
  expectMixedStatuses(sc, name.c_str());
  const std::vector<double> x = sc.state(u, pressures(sc));
  sc.residual(x);
  const std::vector<int> st = sc.frictionStatus();
  EXPECT_EQ(count(st, 1) + count(st, 2), sc.contact().activeCount()) << name;
  if (sliding) {
    EXPECT_GT(count(st, 1), 0) << name;
    EXPECT_GT(count(st, 2), 0) << name;
  } else {
    EXPECT_EQ(count(st, 2), 0) << name;
  }
  expectTangent(sc, x, (name + (sliding ? ", sliding and sticking" : ", sticking")).c_str());
}

TEST(ContactTangents, FrictionStickNodeToFace) {
  if (!oneRank()) GTEST_SKIP() << "a one-rank test";
  // Every active node sticks (lateral motions of 1e-7 and 3e-7 m): the tangent k_t c_a c_b P.
  for (const std::string name : {"Penalty", "Continuous", "Lagrange"}) frictionNodeToFace(name, 1e-7, 3e-7, false);
}

TEST(ContactTangents, FrictionSlipNodeToFace) {
  if (!oneRank()) GTEST_SKIP() << "a one-rank test";
  // Half the nodes slide (5e-5 m), the others stick (1e-7 m): the slip tangent
  // mu f_N k_t / |F*| (P - t t^T) with d f_N / du (penalty, augmented) and d f_N / d lambda
  // (Lagrange, augmented), next to sticking nodes.
  for (const std::string name : {"Penalty", "Continuous", "Lagrange"}) frictionNodeToFace(name, 1e-7, 5e-5, true);
}

// Against obstacles: a plane moving at 2e-3 m/s along its surface (the relative motion carries
// -V dt) and a sphere of radius 4 m, whose normal turns from step to step: two steps, the
// second from the first one's accepted friction forces, projected on the turned tangent planes.
TEST(ContactTangents, FrictionAgainstObstacles) {
  if (!oneRank()) GTEST_SKIP() << "a one-rank test";
  const RigidObstacle plane =
      obstacle(RigidObstacle::Shape::Plane, {0.01, 0.01, 1e-5}, {0, 0, -1}, 0.0, {2e-3, -1e-3, 0});
  const RigidObstacle sphere = obstacle(RigidObstacle::Shape::Sphere, {0.01, 0.01, 4.0 + 1e-5}, {0, 0, 1}, 4.0);
  for (const auto& [what, o] : {std::make_pair("plane", plane), std::make_pair("sphere", sphere)})
    for (const std::string name : {"Penalty", "Lagrange"}) {
      Scene sc(barScene(), {obstaclePair(o, 0.3)}, method(name));
      sc.contact().friction()->setTangentialStiffness(1e9);
      // Bar 2 pushed up by 2.5e-5 (plane: every node in contact; sphere: not the corners),
      // sliding by 5e-5 m or sticking (1e-7 m) on a checkerboard of its 3 x 3 nodes.
      auto state = [&](double scale) {
        const auto lateral = lateralMotion(scale * 1e-7, scale * 5e-5, kObstacleFaceSpacing);
        return sc.displacement([&](int node, const Point3& X) {
          if (onBar1(X)) return Vec3{0, 0, 0};
          const Vec3 l = lateral(X);
          return Vec3{l[0], l[1], 2.5e-5 + 1e-7 * std::sin(3.0 * node)};
        });
      };
      const std::vector<double> u0(size_t(sc.nU()), 0.0), u1 = state(1.0), u2 = state(1.6);
      const std::string label = std::string(what) + ", " + name;
      // Step 1, accepted at u1 with its friction forces.
      sc.beginStep(u0, 1e-4, 1e-5);
      sc.initialize(u1);
      const std::vector<double> x1 = sc.state(u1, pressures(sc));
      sc.residual(x1);
      expectTangent(sc, x1, (label + ", first step").c_str());
      sc.residual(x1);
      sc.contact().commitMotion(*sc.vec(u1));
      // Step 2 from u1 (the sphere's normals turn), evaluated at u2.
      sc.beginStep(u1, 1.1e-4, 1e-5);
      sc.initialize(u2);
      const std::vector<double> x2 = sc.state(u2, pressures(sc));
      sc.residual(x2);
      const std::vector<int> st = sc.frictionStatus();
      EXPECT_GT(count(st, 1), 0) << label;
      EXPECT_GT(count(st, 2), 0) << label;
      expectTangent(sc, x2, (label + ", second step").c_str());
    }
}

// ---------------------------------------------------------------------------------------
// Curved obstacles: the re-linearisation before each step.

// Sphere and cylinder (radius 0.05 m, their normals turn over the face) near bar 2's face.
std::vector<std::pair<const char*, RigidObstacle>> curvedObstacles() {
  return {{"sphere", obstacle(RigidObstacle::Shape::Sphere, {0.012, 0.007, 0.05 + 1e-5}, {0, 0, 1}, 0.05,
                              {0.2, 0.1, -0.05})},
          {"cylinder", obstacle(RigidObstacle::Shape::Cylinder, {0.01, 0.013, 0.05 + 1e-5}, {1, 0.4, 0.1}, 0.05,
                                {-0.1, 0.3, 0.02})}};
}

// A state of bar 2 (moved 1e-4 m with some shear) at t = 1e-3 s.
std::vector<double> curvedState(const Scene& sc) {
  return sc.displacement([](int, const Point3& X) {
    return onBar1(X) ? Vec3{0, 0, 0} : Vec3{3e-5 + 2e-3 * X[1], -2e-5 + 1e-3 * X[0], 1e-4 + 5e-4 * X[0]};
  });
}

// The gap a constraint gives at u right after beginStep(u): d(X + u), the obstacle's distance;
// its coefficients B must be the distance's gradient, n(X + u).
TEST(ContactTangents, CurvedObstacleGapGradient) {
  if (!oneRank()) GTEST_SKIP() << "a one-rank test";
  const double t = 1e-3;
  for (const auto& [what, o] : curvedObstacles()) {
    Scene sc(barScene(), {obstaclePair(o)}, makePenaltyContact(1e9, 1e-12));
    const int nS = sc.nS(), nU = sc.nU();
    auto gaps = [&](const std::vector<double>& u) {
      sc.beginStep(u, t, 1e-5);
      return sc.contact().gaps(*sc.vec(u));
    };
    const std::vector<double> u = curvedState(sc);
    gaps(u);
    Dense B(nS, nU);
    for (int s = 0; s < nS; ++s)
      for (const auto& [dof, coeff] : sc.contact().constraints()[size_t(s)].terms) B(s, int(dof)) += coeff;
    // The gap is the distance itself (to round-off).
    const std::vector<double> g = gaps(u);
    for (int s = 0; s < nS; ++s) {
      const ContactConstraint& c = sc.contact().constraints()[size_t(s)];
      Point3 x = c.reference;
      for (int d = 0; d < 3; ++d) x[d] += u[size_t(sc.dofs().dof(c.geometry.slaveNode, d))];
      EXPECT_NEAR(g[size_t(s)], distanceTo(o, x, t).gap, 1e-16) << what;
    }
    test::TangentCheckOptions opt;
    opt.scale = 1e-4;
    opt.residualScale = 0.1;  // the positions the distances are computed from
    test::TangentCheck c;
    EXPECT_TRUE(tangentMatches(gaps, B, u, opt, &c)) << what;
    std::cout << "  [" << what << " gap gradient] " << c.message() << "\n";
    EXPECT_TRUE(tangentMismatches(gaps, test::perturbed(B), u, opt)) << what;
  }
}

// The coefficients after beginStep(u) as functions of u: the normal turns at the obstacle's
// curvature, dn/dx = (I - n n^T) / |x - c| (sphere), (I - a a^T - n n^T) / |r| (cylinder of
// axis a, r the radial part of x - c).
TEST(ContactTangents, CurvedObstacleNormalTurning) {
  if (!oneRank()) GTEST_SKIP() << "a one-rank test";
  const double t = 1e-3;
  for (const auto& [what, o] : curvedObstacles()) {
    Scene sc(barScene(), {obstaclePair(o)}, makePenaltyContact(1e9, 1e-12));
    const int nS = sc.nS(), nU = sc.nU();
    auto normals = [&](const std::vector<double>& u) {
      sc.beginStep(u, t, 1e-5);
      std::vector<double> n;
      for (const ContactConstraint& c : sc.contact().constraints())
        for (int d = 0; d < 3; ++d) n.push_back(c.terms[size_t(c.componentTerm[d])].second);
      return n;
    };
    const std::vector<double> u = curvedState(sc);
    normals(u);  // the state the closed form is taken at
    Dense H(3 * nS, nU);
    const Vec3 centre{o.point[0] + o.velocity[0] * t, o.point[1] + o.velocity[1] * t, o.point[2] + o.velocity[2] * t};
    for (int s = 0; s < nS; ++s) {
      const ContactConstraint& c = sc.contact().constraints()[size_t(s)];
      Vec3 rel{};
      for (int d = 0; d < 3; ++d) rel[d] = c.reference[d] + u[size_t(sc.dofs().dof(c.geometry.slaveNode, d))] - centre[d];
      const Vec3& a = o.direction;
      const bool cyl = o.shape == RigidObstacle::Shape::Cylinder;
      const double along = cyl ? dot(rel, a) : 0.0;
      for (int d = 0; d < 3; ++d) rel[d] -= along * a[d];
      const double rho = norm(rel);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          const double n_i = rel[i] / rho, n_j = rel[j] / rho;
          const double v = ((i == j ? 1.0 : 0.0) - (cyl ? a[i] * a[j] : 0.0) - n_i * n_j) / rho;
          H(3 * s + i, int(sc.dofs().dof(c.geometry.slaveNode, j))) = v;
        }
    }
    test::TangentCheckOptions opt;
    opt.scale = 1e-4;
    opt.residualScale = 1.0;
    test::TangentCheck c;
    EXPECT_TRUE(tangentMatches(normals, H, u, opt, &c)) << what;
    std::cout << "  [" << what << " normal turning] " << c.message() << "\n";
    EXPECT_TRUE(tangentMismatches(normals, test::perturbed(H), u, opt)) << what;
    // The turning that a normal frozen over the step leaves out: a dropped term fails.
    EXPECT_TRUE(tangentMismatches(normals, Dense(3 * nS, nU), u, opt)) << what;
  }
}

// ---------------------------------------------------------------------------------------
// Mortar: the gap G_j / D_j integrated on the moved faces against the constraint row
// nu_j . (u_j - sum_m M_jm / D_j u_m).

// The gaps of `mesh` (the state) by the pairing of `def` (mortar, or node to face) as
// functions of the displacements x of the nodes of both contact surfaces (every other node
// leaves them unchanged), against the rows makeContactConstraint builds from the projections:
// both assertions, or (expectPass false) the measurement alone.
void expectGapRows(const Mesh& mesh, const PairDefinition& def, const std::string& what, bool expectPass = true) {
  const DofMap dofs(std::vector<std::uint8_t>(size_t(mesh.numNodes()), 7), 1, 0);
  std::vector<int> nodes;
  for (const std::string& set : {def.slaveSideSet, def.masterSideSet})
    for (const Face& f : facesOf(mesh, set)) nodes.insert(nodes.end(), f.nodes.begin(), f.nodes.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  std::vector<int> column(size_t(dofs.numGlobal()), -1);  // DOF -> column of x
  for (size_t k = 0; k < nodes.size(); ++k)
    for (int d = 0; d < 3; ++d) column[size_t(dofs.dof(nodes[k], d))] = int(3 * k) + d;
  const std::vector<double> x0(3 * nodes.size(), 0.0);
  auto pairing = [&](const std::vector<double>& x) {
    Mesh moved = mesh;
    for (size_t k = 0; k < nodes.size(); ++k)
      for (int d = 0; d < 3; ++d) moved.coords[size_t(nodes[k])][d] += x[3 * k + size_t(d)];
    return def.mortar ? pairMortar(moved, def, 0) : pairNodeToFace(moved, def, 0);
  };
  const PairingResult at = pairing(x0);
  const size_t nS = at.projections.size();
  EXPECT_TRUE(at.unpaired.empty()) << what;
  auto gaps = [&](const std::vector<double>& x) {
    const PairingResult r = pairing(x);
    std::vector<double> g;
    for (const SlaveProjection& p : r.projections) g.push_back(p.gap0);
    EXPECT_EQ(g.size(), nS) << what;
    g.resize(nS, 0.0);
    return g;
  };
  Dense B(int(nS), int(x0.size()));
  for (size_t s = 0; s < nS; ++s) {
    const SlaveProjection& p = at.projections[s];
    for (const auto& [dof, coeff] : makeContactConstraint(mesh.coords[size_t(p.slaveNode)], dofs, p, true).terms)
      B(int(s), column[size_t(dof)]) += coeff;
  }
  test::TangentCheckOptions opt;
  opt.scale = 1e-4;          // h = 6e-10 m: a node moving by h adds slivers of O(h) to the overlaps
  opt.residualScale = 0.05;  // the coordinates the gaps are computed from
  test::TangentCheck c;
  const auto ok = tangentMatches(gaps, B, x0, opt, &c);
  std::cout << "  [" << what << "] " << c.message() << "\n";
  if (expectPass) {
    EXPECT_TRUE(ok) << what;
    EXPECT_TRUE(tangentMismatches(gaps, test::perturbed(B), x0, opt)) << what;
  }
}

TEST(ContactTangents, MortarGapDerivativeIsTheConstraintRow) {
  if (!oneRank()) GTEST_SKIP() << "a one-rank test";
  // The bars' faces touching (zero gap), fine slave on a coarse master and the reverse (dual
  // functions reaching master nodes of several faces), in general position; at rest and after
  // a motion that keeps them touching: a rigid turn of 0.3 rad, a translation and a uniform
  // strain of 1e-3 (an affine map of the whole scene).
  for (const auto& [across1, across2] : {std::make_pair(3, 2), std::make_pair(2, 3)}) {
    const Mesh local = test::barContactScene(across1, across2, 0.0);
    const Mesh mesh = placed(local);
    PairDefinition def = pairOf("ifc", "CNT_POU2", "CNT_POU1");
    def.mortar = true;
    const std::string scene = std::to_string(across1) + "x" + std::to_string(across1) + " slave faces on " +
                              std::to_string(across2) + "x" + std::to_string(across2) + " master faces";
    expectGapRows(mesh, def, "mortar, " + scene + ", at rest");
    // The motion is applied to the mesh itself: the gaps depend on X + u only, and the steps of
    // the differences are then the interface's (not 6e-6 of the rigid motion's 0.3 m).
    const Rotation turn = rotation({-0.2, 0.9, 0.4}, 0.3);
    Mesh moved = mesh;
    for (Point3& X : moved.coords) {
      const Vec3 y = turn(Vec3{X[0] * (1 + 1e-3), X[1] * (1 - 5e-4) + 1e-3 * X[0], X[2] * (1 + 2e-3)});
      for (int d = 0; d < 3; ++d) X[d] = y[d] + 1e-3 * (d + 1);
    }
    expectGapRows(moved, def, "mortar, " + scene + ", turned and strained");
  }
}

// The bars' scene with bar 1's face (across1 x across1 faces) `gap` above bar 2's (across2 x
// across2), turned by 1e-2 rad about (1, 0.5, 0) around the section's centre and scaled by
// `shrink` across it.
Mesh tiltedBars(int across1, int across2, double gap, double shrink) {
  Mesh m = test::barContactScene(across1, across2, gap);
  const Rotation tilt = rotation({1, 0.5, 0}, 1e-2);
  for (Point3& X : m.coords)
    if (X[2] > 0.5 * gap) {
      const Vec3 y = tilt(Vec3{shrink * (X[0] - 0.01), shrink * (X[1] - 0.01), X[2] - gap});
      X = Vec3{y[0] + 0.01, y[1] + 0.01, y[2] + gap};
    }
  return placed(m);
}

// Node to face, for comparison: the closest point's gap (x_s - x_m(xi*)) . n, its row
// n . (u_s - sum_i N_i(xi*) u_i) is its exact derivative at any gap (the projection's own
// motion is along the face, orthogonal to n), here with bar 1's face tilted by 1e-2 rad 2e-4 m
// above bar 2's and shrunk to 0.8 of its section (every slave node projects inside a face),
// at rest and turned and strained.
TEST(ContactTangents, NodeToFaceGapDerivativeIsTheConstraintRow) {
  if (!oneRank()) GTEST_SKIP() << "a one-rank test";
  const Mesh mesh = tiltedBars(3, 2, 2e-4, 0.8);
  const PairDefinition def = pairOf("ifc", "CNT_POU2", "CNT_POU1");
  expectGapRows(mesh, def, "node to face, slave tilted by 1e-2 rad, at rest");
  const Rotation turn = rotation({-0.2, 0.9, 0.4}, 0.3);
  Mesh moved = mesh;
  for (Point3& X : moved.coords) {
    const Vec3 y = turn(Vec3{X[0] * (1 + 1e-3), X[1] * (1 - 5e-4) + 1e-3 * X[0], X[2] * (1 + 2e-3)});
    for (int d = 0; d < 3; ++d) X[d] = y[d] + 1e-3 * (d + 1);
  }
  expectGapRows(moved, def, "node to face, slave tilted by 1e-2 rad, turned and strained");
}

// Off the touching state: bar 1's face tilted by 1e-2 rad against bar 2's, a mean gap of
// 2e-4 m, the faces apart everywhere. The row used to be nu_j (u_j - sum_m M_jm / D_j u_m) with
// nu_j, D_j, M_jm and the overlap held (relative error 1.2 theta: 1.2e-2 here); it is now the
// gap's exact derivative (MortarLinearization.hpp), coupling the neighbouring slave nodes
// through nu_j, the dual basis and the overlap.
TEST(ContactTangents, MortarGapDerivativeWithTiltedFaces) {
  if (!oneRank()) GTEST_SKIP() << "a one-rank test";
  for (const auto& [across1, across2] : {std::make_pair(3, 2), std::make_pair(2, 3)}) {
    PairDefinition def = pairOf("ifc", "CNT_POU2", "CNT_POU1");
    def.mortar = true;
    expectGapRows(tiltedBars(across1, across2, 2e-4, 1.0), def, "mortar, slave tilted by 1e-2 rad");
  }
}

// The tilted pair's gaps after a motion eps d of both surfaces' nodes, against the linearised
// gaps g(x) + eps B d: the remainder falls as eps^2 with the exact row (the step's gap is right
// to second order in its motion, as Newton needs), and only as eps with the row of the
// projection's normal and weights (the former row, here rebuilt with gapGradient cleared).
// Bar 1's face is shrunk to 0.8 of the section, so that no edge of its faces lies on an edge of
// bar 2's: the overlaps keep their shape under the motion (no kink).
TEST(ContactTangents, TiltedMortarGapIsLinearisedToSecondOrder) {
  if (!oneRank()) GTEST_SKIP() << "a one-rank test";
  const Mesh mesh = tiltedBars(3, 2, 2e-4, 0.8);
  PairDefinition def = pairOf("ifc", "CNT_POU2", "CNT_POU1");
  def.mortar = true;
  const DofMap dofs(std::vector<std::uint8_t>(size_t(mesh.numNodes()), 7), 1, 0);
  const PairingResult at = pairMortar(mesh, def, 0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<double> d(size_t(dofs.numGlobal()));
  for (double& v : d) v = unit(rng);
  // The largest remainder over the slave nodes after the motion eps d, with or without the
  // exact row.
  auto remainder = [&](double eps, bool exact) {
    Mesh moved = mesh;
    for (int n = 0; n < mesh.numNodes(); ++n)
      for (int c = 0; c < 3; ++c) moved.coords[size_t(n)][c] += eps * d[size_t(dofs.dof(n, c))];
    const PairingResult after = pairMortar(moved, def, 0);
    EXPECT_EQ(after.projections.size(), at.projections.size());
    double worst = 0;
    for (size_t s = 0; s < at.projections.size() && s < after.projections.size(); ++s) {
      SlaveProjection p = at.projections[s];
      if (!exact) p.gapGradient.clear();
      double bd = 0;
      for (const auto& [dof, coeff] : makeContactConstraint(mesh.coords[size_t(p.slaveNode)], dofs, p, true).terms)
        bd += coeff * d[size_t(dof)];
      worst = std::max(worst, std::abs(after.projections[s].gap0 - p.gap0 - eps * bd));
    }
    return worst;
  };
  const double eps = 2e-6;  // 3e-4 of a slave face, far above the gaps' round-off (1e-19 m)
  const double exact1 = remainder(eps, true), exact2 = remainder(eps / 2, true);
  const double held1 = remainder(eps, false), held2 = remainder(eps / 2, false);
  std::cout << "  remainder at eps, eps/2: exact row " << exact1 << ", " << exact2 << " (ratio " << exact1 / exact2
            << "); held row " << held1 << ", " << held2 << " (ratio " << held1 / held2 << ")\n";
  // Ratios of 4 and 2 up to the next order's share (the motion is 3e-4 of a face).
  EXPECT_NEAR(exact1 / exact2, 4.0, 0.1);
  EXPECT_NEAR(held1 / held2, 2.0, 0.05);
  EXPECT_LT(exact1, 0.1 * held1);
}

}  // namespace
}  // namespace choc
