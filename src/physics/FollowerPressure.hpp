// A pressure that follows the deformed faces (Pressures/<name>/Follower = true): it acts along
// the current normal on the current area of the faces of a side set,
//
//   f_a(u, t) = -lambda(t) sum_q w_q p(X_q) N_a(q) (x_,xi x x_,eta)(q) [2 pi r(q)],   x = X + u,
//
// with p(X) = Value + Gradient . X given at the reference position X of each quadrature point
// (so a point of the face keeps its pressure as it moves), lambda the ramp (LoadGroup::factor),
// the ring 2 pi r (current r) on axisymmetric edges, and x_,eta = e_z on planar edges. It is a
// load that depends on the state: the model's nonlinear force carries it (FiniteStrainForce:
// f_int(u) - f(u, t)) with its derivative, the load stiffness
//
//   K_ab = -df_a/dx_b = lambda sum_q w_q p N_a [ -dN_b/dxi [x_,eta]x + dN_b/deta [x_,xi]x
//                                               (+ 2 pi N_b n_A (x) e_r on axisymmetric edges) ],
//
// ([a]x the cross-product matrix), which is not symmetric. Its work goes to the energy balance
// by the trapezoidal rule on f(u, t) . du (LoadWork). A uniform follower pressure on a closed
// surface is conservative; a varying one (an end moment made of a linear pressure) need not be.
#pragma once
#include <array>
#include <string>
#include <vector>

#include <Tpetra_Import.hpp>

#include "contact/ContactFaces.hpp"
#include "core/TpetraTypes.hpp"
#include "fem/DenseMatrix.hpp"
#include "physics/StateLoad.hpp"

namespace choc {

class DofMap;

// p(X) = value + gradient . X [Pa], X the reference position.
struct PressureField {
  double value = 0.0;
  std::array<double, 3> gradient{};
  double at(const Point3& X) const { return value + gradient[0] * X[0] + gradient[1] * X[1] + gradient[2] * X[2]; }
};

// One face's follower force (the external force, per node 3 components) at the nodes' current
// positions x (the face's reference in `face`, for p), and when K is given dforce/dx (3n x 3n).
void followerFaceForce(const Face& face, const PressureField& p, const std::vector<Point3>& x, bool axisymmetric,
                       std::vector<double>& force, DenseMatrix* K);

class FollowerPressure : public StateLoad {
 public:
  // faces of the side set `name`; K: the model's stiffness (its row and column maps, whose
  // columns hold every DOF of a face touching a row this rank owns).
  FollowerPressure(std::string name, std::vector<Face> faces, PressureField p, double rampTime, bool axisymmetric,
                   const DofMap& dofs, int components, const CrsMatrix& K);

 protected:
  void groupForce(const Group& g, const std::vector<Point3>& x, std::vector<double>& f, DenseMatrix* K) const override;

 private:
  PressureField p_;
  bool axisymmetric_;
  std::vector<Face> faces_;
};

}  // namespace choc
