// The geometry of an isoparametric element at one natural point: shape functions, their
// gradients in physical axes, det J and the mapped point. 2D topologies map (xi, eta) to the
// (x, y) plane of the node coordinates (z is ignored).
#pragma once
#include <string>
#include <vector>

#include "fem/ShapeFunctions.hpp"

namespace choc {

struct IsoparametricPoint {
  std::vector<double> N;     // N_a
  std::vector<Point3> dNdx;  // dN_a/dx_i for i < parametric dimension, others zero
  double detJ = 0.0;
  Point3 x = {0, 0, 0};  // sum N_a x_a (z = 0 for 2D topologies)
};

// Evaluates the map of the element with nodes x (nodeCount(t) points) at the natural point
// xi. Throws std::invalid_argument "inverted or degenerate <TOPO> element: Jacobian
// determinant <value> <= 0 at natural point (...)" when det J <= 0, and when x has the wrong
// number of nodes.
void evaluateIsoparametric(SolidShape t, const std::vector<Point3>& x, const Point3& xi,
                           IsoparametricPoint& p);

// det J at xi without the sign check (throws only for a wrong node count).
double jacobianDeterminant(SolidShape t, const std::vector<Point3>& x, const Point3& xi);

// Throws the "inverted or degenerate <TOPO> element: ..." std::invalid_argument.
[[noreturn]] void throwInverted(SolidShape t, double det, const Point3& xi);

// "(xi, eta)" or "(xi, eta, zeta)" as in the error messages.
std::string naturalPointText(SolidShape t, const Point3& xi);

}  // namespace choc
