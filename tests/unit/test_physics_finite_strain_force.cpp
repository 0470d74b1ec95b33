// The assembled finite-strain force (physics/FiniteStrainForce.hpp) of a whole model, with a
// follower pressure: its tangent against central differences of its internal force
// (tests/unit/fd_tangent.hpp) at a state bent and turned through 60 degrees, on the slender
// beam of input/elastica_beam.xml (HEX20, nu = 0). With nu = 0 the small-strain stiffness of
// these regular elements has exact zeros where the finite-strain tangent has entries (the
// couplings of u_x and u_y that a rotation brings back): the model's graph must hold every
// entry of a finite-strain element (BlockPhysics::fullPattern), or the tangent loses them and
// Newton converges linearly (measured: a factor 0.3 per iteration on this beam).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include <Teuchos_DefaultComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "contact/ContactFaces.hpp"
#include "fd_tangent.hpp"
#include "fem/Components.hpp"
#include "input/Validation.hpp"
#include "input/XmlInput.hpp"
#include "physics/FiniteStrainForce.hpp"
#include "physics/Model.hpp"
#include "physics/ModelInput.hpp"

namespace choc {
namespace {

struct Beam {
  std::unique_ptr<Model> model;
  std::string file = std::string(CHOC_SOURCE_DIR) + "/input/elastica_beam.xml";
};

Beam beamModel() {
  Beam b;
  auto input = readXmlParameters(b.file);
  validate(*input, topLevelParameters(), InputLocation{b.file, ""});
  b.model = std::make_unique<Model>(*input, b.file, Teuchos::DefaultComm<int>::getComm());
  return b;
}

// The beam rolled onto a circle of radius R (X -> R sin(X/R), R (1 - cos(X/R)) with the section
// carried along its normal), then turned by 60 degrees about z: large rotations and strains of
// about h / (2 R) = 1 %.
std::vector<double> bentAndTurned(const Model& m) {
  const double R = 1.0, turn = M_PI / 3;
  std::vector<double> u(size_t(m.map()->getGlobalNumElements()), 0.0);
  const Mesh& mesh = m.mesh();
  for (int n = 0; n < mesh.numNodes(); ++n) {
    const Point3& X = mesh.coords[size_t(n)];
    const double phi = X[0] / R, r = R - X[1];
    const double x = r * std::sin(phi), y = R - r * std::cos(phi);
    const double xt = std::cos(turn) * x - std::sin(turn) * y, yt = std::sin(turn) * x + std::cos(turn) * y;
    const double target[3] = {xt, yt, X[2]};
    for (int c = 0; c < 3; ++c) {
      const long long d = m.dof(n, c);
      if (d >= 0) u[size_t(d)] = target[c] - X[size_t(c)];
    }
  }
  return u;
}

TEST(FiniteStrainForce, TangentWithAFollowerPressureMatchesFiniteDifferencesOnABentTurnedBeam) {
  if (Teuchos::DefaultComm<int>::getComm()->getSize() != 1) GTEST_SKIP() << "dense check on one rank";
  Beam b = beamModel();
  Model& m = *b.model;
  auto force = std::make_shared<FiniteStrainForce>(m);
  PressureField p;
  p.value = 2e8;
  p.gradient = {0.0, 3e10, 0.0};
  auto follower = std::make_shared<FollowerPressure>("end", facesOf(m.mesh(), "END"), p, 10.0, false, m.dofs(), 3,
                                                     *m.stiffness());
  force->addStateLoad(follower);
  force->setTime(4.0);  // 0.4 of the ramp
  const int n = int(m.map()->getGlobalNumElements());
  const std::vector<double> u0 = bentAndTurned(m);
  test::Residual R = [&](const std::vector<double>& u) {
    auto uv = test::tpetraOf(u, m.map());
    Vector f(m.map());
    force->internalForce(*uv, f);
    return test::valuesOf(f);
  };
  auto uv = test::tpetraOf(u0, m.map());
  const test::Dense J = test::denseOf(*force->tangent(*uv), n, n);
  test::TangentCheckOptions o;
  o.scale = 0.01;  // the section's size: the length over which the force varies
  EXPECT_TRUE(test::tangentMatches(R, J, u0, o));
  // The same without the follower's load stiffness (the tangent of the elements alone) fails:
  // the check sees the follower's part.
  auto bare = std::make_shared<FiniteStrainForce>(m);
  const test::Dense Je = test::denseOf(*bare->tangent(*uv), n, n);
  EXPECT_TRUE(test::tangentMismatches(R, Je, u0, o));
}

}  // namespace
}  // namespace choc
