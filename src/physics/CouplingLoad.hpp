// The load on a distributing coupling (Model/Couplings/<name>, Type = distributing: RBE3-like),
// Analyses/<name>/Coupling Loads/<load>: a force F at the current centroid c of the coupling's n
// nodes and a moment M, spread over the nodes without stiffening them,
//
//   f_i = F / n + a x r_i,   r_i = x_i - c,   J a = M,   J = sum_i (|r_i|^2 I - r_i r_i^T),
//
// the forces of least squares (equal weights) whose resultant is F and whose moment about c is
// M, however the nodes have moved: a pure couple stays a pure couple (the end-moment elastica).
// F and M keep their directions in space. With x the current positions its derivative, the load
// stiffness's blocks, is (sum_j r_j = 0 removes the centroid's motion from J's)
//
//   df_i/dx_k = [a]x (delta_ik - 1/n) + [r_i]x J^-1 B_k,   B_k = 2 a r_k^T - (r_k . a) I - r_k a^T,
//
// checked against central differences (physics.CouplingLoad.*). The nodes may not lie on one
// line when M is not 0 (J singular: refused where the load is read).
#pragma once
#include <string>
#include <vector>

#include "physics/StateLoad.hpp"

namespace choc {

// f (3 per node) and, when K is given, df/dx (3n x 3n) at the positions x. Throws
// std::invalid_argument when M is not 0 and J is singular (the nodes on a line).
void couplingForce(const std::vector<Point3>& x, const Vec3& F, const Vec3& M, std::vector<double>& f,
                   DenseMatrix* K);

class CouplingLoad : public StateLoad {
 public:
  // nodes: the coupling's; K: the model's stiffness, whose graph couples them (Model/Couplings).
  CouplingLoad(std::string name, const std::vector<int>& nodes, const Mesh& mesh, Vec3 force, Vec3 moment,
               double rampTime, const DofMap& dofs, int components, const CrsMatrix& K);

 protected:
  void groupForce(const Group& g, const std::vector<Point3>& x, std::vector<double>& f, DenseMatrix* K) const override;

 private:
  Vec3 force_, moment_;
};

}  // namespace choc
