// The massless directions of a mass matrix that is singular along the contact normals ('Contact
// Mass' = normal, fem/NormalMassRemoval.hpp): the orthogonal rotation Q, block diagonal by node,
// whose first columns at a contact node are its constrained directions and the rest complete
// them within the node's unknowns (the axes elsewhere). In the rotated DOFs x_r = Q^T x the
// directions are DOFs of their own: Q^T M Q has zero rows there, which the massless machinery of
// the redistributed mass (zero rows of M: MasslessInitialAcceleration.hpp, the reported
// velocities of DirectStepView) then treats as it treats those. The rotated DOF takes the global
// id of the node's component in the same position.
#pragma once
#include <vector>

#include "core/TpetraTypes.hpp"
#include "fem/DofMap.hpp"
#include "mesh/Mesh.hpp"

namespace choc {

struct MasslessBasis {
  RCP<const CrsMatrix> rotation;  // Q (null: the axes; the massless DOFs are M's zero rows)
  std::vector<char> mask;         // per local rotated DOF: carries no inertia
  long long global = 0;           // massless rotated DOFs on all ranks
};

// directions: per mesh node, its orthonormal constrained directions within its unknowns
// (contact/ContactNormalDirections.hpp). Collective.
MasslessBasis masslessBasis(const std::vector<std::vector<Point3>>& directions, const DofMap& dofs,
                            const RCP<const Map>& map);

// Q^T A Q (fill-completed on A's maps).
RCP<CrsMatrix> rotatedMatrix(const CrsMatrix& Q, const CrsMatrix& A);
// A's entries in the masked rows and columns set to 0 exactly (after a rotation, the round-off
// of Q^T M Q along the normals).
void zeroMasslessEntries(CrsMatrix& A, const std::vector<char>& mask);
// out = Q^T x (toRotated) or Q x.
void rotate(const CrsMatrix& Q, const Vector& x, Vector& out, bool toRotated);

}  // namespace choc
