#include "fem/NodalBlocks.hpp"

#include <algorithm>

#include "fem/Components.hpp"

namespace choc {

namespace {

// The rotation about axis a as (translation component, coefficient of which coordinate):
// w = e_a x r gives w_b = -r_c and w_c = r_b for (a, b, c) cyclic.
struct RotationAxis {
  int axis, b, c;
};
constexpr RotationAxis kAxes[3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}};

bool used(const std::vector<int>& slotOf, int comp) { return slotOf[comp] >= 0; }

}  // namespace

NodalBlocks nodalBlocks(const DofMap& dofs, const std::vector<Vec3>& coords) {
  NodalBlocks nb;
  const int n = dofs.numNodes();
  std::uint8_t any = 0;
  for (int node = 0; node < n; ++node) any |= dofs.freeMask(node);
  std::vector<int> slotOf(kNumComponents, -1);
  for (int c = 0; c < kNumComponents; ++c)
    if ((any >> c) & 1u) {
      slotOf[c] = nb.blockSize++;
      nb.components.push_back(c);
    }
  nb.blockRowOfDof.assign(dofs.numGlobal(), -1);
  const std::vector<int> order = dofs.order();
  long long block = 0;
  for (int p = 0; p < n; ++p) {
    const int node = order[p];
    if (dofs.freeMask(node) == 0) continue;
    const bool owned = p >= dofs.ownedPositionBegin() && p < dofs.ownedPositionEnd();
    if (owned) {
      if (nb.numOwnedBlocks == 0) nb.firstOwnedBlock = block;
      ++nb.numOwnedBlocks;
      nb.ownedCoordinates.push_back(coords[node]);
    }
    for (int s = 0; s < nb.blockSize; ++s) {
      const long long d = dofs.dof(node, nb.components[s]);
      if (d >= 0) nb.blockRowOfDof[d] = block * nb.blockSize + s;
      if (owned) nb.ownedDofOfRow.push_back(d);
    }
    ++block;
  }
  nb.numGlobalBlocks = block;
  if (nb.numOwnedBlocks == 0) nb.firstOwnedBlock = block;
  return nb;
}

int NodalBlocks::numRigidModes() const {
  std::vector<int> slotOf(kNumComponents, -1);
  for (int s = 0; s < blockSize; ++s) slotOf[components[s]] = s;
  int m = 0;
  for (int c = DX; c <= DZ; ++c) m += used(slotOf, c);
  for (const RotationAxis& r : kAxes) m += used(slotOf, r.b) && used(slotOf, r.c);
  return m;
}

std::vector<double> NodalBlocks::rigidBodyModes() const {
  std::vector<int> slotOf(kNumComponents, -1);
  for (int s = 0; s < blockSize; ++s) slotOf[components[s]] = s;
  Vec3 centre{0.0, 0.0, 0.0};
  for (const Vec3& x : ownedCoordinates)
    for (int k = 0; k < 3; ++k) centre[k] += x[k] / std::max(1, numOwnedBlocks);
  const long long rows = numOwnedRows();
  std::vector<double> modes((size_t)numRigidModes() * rows, 0.0);
  int m = 0;
  for (int c = DX; c <= DZ; ++c) {
    if (!used(slotOf, c)) continue;
    for (int i = 0; i < numOwnedBlocks; ++i) modes[m * rows + (long long)i * blockSize + slotOf[c]] = 1.0;
    ++m;
  }
  for (const RotationAxis& r : kAxes) {
    if (!(used(slotOf, r.b) && used(slotOf, r.c))) continue;
    for (int i = 0; i < numOwnedBlocks; ++i) {
      const Vec3& x = ownedCoordinates[i];
      double* row = &modes[m * rows + (long long)i * blockSize];
      row[slotOf[r.b]] = -(x[r.c] - centre[r.c]);
      row[slotOf[r.c]] = x[r.b] - centre[r.b];
      if (used(slotOf, DRX + r.axis)) row[slotOf[DRX + r.axis]] = 1.0;
    }
    ++m;
  }
  return modes;
}

}  // namespace choc
