// Node checks and quadrature weights of the isoparametric continuum elements.
#include "fem/SolidGeometry.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace choc {

namespace {

constexpr double kPi = 3.14159265358979323846;

void checkAxisymmetricNodes(SolidShape t, const std::vector<Point3>& x) {
  for (size_t a = 0; a < x.size(); ++a)
    if (!(x[a][0] >= 0.0)) {
      std::ostringstream msg;
      msg << "axisymmetric elements need x = r >= 0: node " << a + 1 << " of a " << topologyName(t)
          << " element has r = " << x[a][0];
      throw std::invalid_argument(msg.str());
    }
}

}  // namespace

// Checks the nodes before any integration: axisymmetric radii, and for the quadratic
// topologies det J at the corner nodes. A folded quadratic element (two corners swapped, say)
// can have det J > 0 at every quadrature point but not at its corners. det J = 0 at a corner
// (collapsed or quarter-point elements) is accepted up to round-off.
void validateSolidNodes(SolidShape t, Kinematics k, const std::vector<Point3>& x) {
  if (k == Kinematics::Axisymmetric) checkAxisymmetricNodes(t, x);
  if (!isQuadratic(t)) return;
  const std::vector<Point3>& xi = nodeNaturalCoordinates(t);
  std::vector<double> det(cornerCount(t));
  double scale = 0.0;
  for (int a = 0; a < cornerCount(t); ++a) {
    det[a] = jacobianDeterminant(t, x, xi[a]);
    scale = std::max(scale, std::fabs(det[a]));
  }
  for (int a = 0; a < cornerCount(t); ++a)
    if (det[a] < -1e-10 * scale) throwInverted(t, det[a], xi[a]);
}

// Evaluates the map at quadrature point q of `rule` and returns w_q dV_q.
double solidVolumeWeight(SolidShape t, Kinematics k, const std::vector<Point3>& x,
                         const QuadratureRule& rule, int q, IsoparametricPoint& p) {
  evaluateIsoparametric(t, x, rule.points[q], p);
  double w = rule.weights[q] * p.detJ;
  if (k != Kinematics::Axisymmetric) return w;
  const double r = p.x[0];
  if (!(r > 0.0)) {
    std::ostringstream msg;
    msg << "axisymmetric elements need x = r >= 0: radius " << r << " at natural point "
        << naturalPointText(t, rule.points[q]) << " of a " << topologyName(t)
        << " element (r must be positive inside the element)";
    throw std::invalid_argument(msg.str());
  }
  return w * 2 * kPi * r;
}

void checkSolidKinematics(SolidShape t, Kinematics k) {
  const bool threeD = parametricDimension(t) == 3;
  if (threeD == (k == Kinematics::ThreeD)) return;
  std::ostringstream msg;
  msg << "element topology " << topologyName(t) << " is " << (threeD ? "3D" : "2D")
      << " and cannot be used with " << toString(k) << " kinematics; "
      << (threeD ? "use 3D kinematics" : "use plane strain or axisymmetric kinematics");
  throw std::invalid_argument(msg.str());
}

}  // namespace choc
