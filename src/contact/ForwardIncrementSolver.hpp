// The forward-increment pressures of exactly enforced contact in an explicit step (Carpenter,
// Taylor and Katona 1991): the explicit solver layer of contact, apart from the geometry and
// the active set. For constraints s with terms (k, c_sk) over the contact DOFs k, the gaps g_s
// of the predicted positions, the inverse masses w_k of those DOFs and the factor h2 by which
// an acceleration moves a position, the pressures lambda solve the complementarity problem
//   g_s + sum_k c_sk h2 w_k sum_r c_rk lambda_r >= 0,   lambda_s >= 0,   complementary,
// by projected Gauss-Seidel on h2 B M^-1 B^T (one sweep when no two constraints share a DOF:
// against obstacles). Converged when no sweep changes a gap by more than 1e-12 of the largest
// |g_s|. Bilateral (unilateral = false): lambda of either sign with every g_s brought to 0
// (Gauss-Seidel on the same matrix).
// Contact DOFs that a rigid body moves (RigidContactBodies) have no inverse mass of their own
// (w_k = 0): a force c on such a DOF k (component e_k, lever arm r_k from the body's centre)
// moves the body by h2 (c e_k / m) and turns it by h2 I^-1 (r_k x c e_k), which moves every DOF
// j of the body by e_j . (dV + dW x r_j): per constraint and body, F = sum c e_k and
// T = sum c r_k x e_k, and the body's part of h2 B M^-1 B^T is h2 (F'.F / m + T'. I^-1 T)
// (1/m per axis: 0 along a held component).
#pragma once
#include <array>
#include <utility>
#include <vector>

#include "core/Vec3.hpp"

namespace choc {

// A contact DOF moved by a rigid body: the body, the DOF's component (0-2) and its lever arm
// x - c from the body's centre of mass, now.
struct RigidContactDof {
  int body = -1;  // -1: not a rigid body's
  int component = 0;
  Vec3 lever{};
};

// Per contact DOF its body (or none), and each body's inverse mass along each axis (0 along a
// held component of its motion) and inverse inertia tensor (space frame, row-major, now; 0 for a
// held rotation).
struct RigidContactBodies {
  std::vector<RigidContactDof> dofs;
  std::vector<Vec3> inverseMass;
  std::vector<std::array<double, 9>> inverseInertia;
};

struct ForwardIncrementResult {
  std::vector<double> lambda;  // per constraint, >= 0
  int sweeps = 0;
  bool converged = false;
};

// terms[s]: (index into the contact DOFs, coefficient) of constraint s; gaps[s]; inverseMass[k].
ForwardIncrementResult solveForwardIncrement(const std::vector<std::vector<std::pair<int, double>>>& terms,
                                             const std::vector<double>& gaps,
                                             const std::vector<double>& inverseMass, double h2,
                                             int maxSweeps = 1000, bool unilateral = true,
                                             const RigidContactBodies* rigid = nullptr);

}  // namespace choc
