// What the elements' validity checks share (ElementValidity.hpp): the shapes' derivatives at the
// checked points, det J of a map there, and the small strain and rotation at an element's centre.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "core/TpetraTypes.hpp"
#include "fem/Quadrature.hpp"
#include "fem/ShapeFunctions.hpp"

namespace choc {

// The natural derivatives dN_a/dxi at the points an element is checked at (a one-point element's
// corners, then the quadrature points), and N, dN at its centre: one table per shape, rule and
// formulation, made once. A one-point element's force sees only its mean gradient, so its corners
// are checked too; the other elements' points are those their force integrates (a quadratic
// element's corner may turn slightly negative in a large deformation while its points, where it
// is integrated, stay positive).
struct CheckPoints {
  int dim = 3, nodes = 0, corners = 0;
  std::vector<Point3> xi;                // the checked points
  std::vector<std::vector<Point3>> dN;  // per checked point, per node
  std::vector<double> centreN;
  std::vector<Point3> centreDN;
};

// The table of shape t with the points of `rule` (and its corners first when `corners`).
const CheckPoints& checkPoints(SolidShape t, const QuadratureRule& rule, bool corners);
// det J of the map of the nodes x at a point, J_ij = sum_a dN_a/dxi_i x_a,j (2 x 2 for planar shapes).
double mapDeterminant(const CheckPoints& t, const std::vector<Point3>& dN, const std::vector<Point3>& x, double J[3][3]);
// The small strain ||sym H|| and the rotation |skew H| at the element's centre, H = du/dX; ue in
// element DOF order (nc per node); axisymmetric: with the hoop strain u_r / r.
std::pair<double, double> smallStrainAtCentre(const CheckPoints& t, const std::vector<Point3>& X,
                                              const std::vector<double>& ue, int nc, bool axisymmetric);

// The worst value of a measure over elements, and the lowest-numbered element holding it.
struct ElementMeasure {
  double value = 0.0;
  int element = -1;  // global number, -1: none
};
// Keeps v of `element` when it is worse (the smallest or the largest), or equal on a lower element.
void keepWorst(ElementMeasure& m, double v, int element, bool smallest);
// The worst over the ranks, the same on every rank (collective).
ElementMeasure worstOverRanks(const Comm& comm, ElementMeasure local, bool smallest);

// The verdict on the worst small strain and rotation of the small-strain blocks: empty text below
// ElementValidity::kSmallStrainWarning; `failed` past kSmallStrainLimit; `strain`: the strain (not
// the rotation) is the worse of the two.
struct SmallStrainVerdict {
  bool failed = false, strain = true;
  std::string text;
};
SmallStrainVerdict smallStrainVerdict(double strain, bool hasStrain, double rotation, bool hasRotation);

}  // namespace choc
