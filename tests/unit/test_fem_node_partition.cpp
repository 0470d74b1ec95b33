// The nodes' partition among ranks (Zoltan2 RCB) and the DOF map numbered along it: parts
// are compact regions balanced by unknowns whatever the mesh's numbering, each rank owns a
// contiguous range of DOFs, and the map answers the same (node, component) questions.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "fem/DofMap.hpp"
#include "fem/NodePartition.hpp"
#include "mesh/BarImpactMesh.hpp"
#include "test_mesh_helpers.hpp"

namespace choc {
namespace {

Mesh bars() {
  BarImpactOptions o;
  o.dimension = 3;
  o.axis = 'z';
  o.along1 = o.along2 = 20;
  o.across1 = o.across2 = 2;
  return generateBarImpactMesh(o);
}

TEST(NodePartition, RcbCutsTheBarsIntoBalancedSlabs) {
  const Mesh m = bars();
  const std::vector<std::uint8_t> mask(m.numNodes(), 0b111);
  for (int parts : {2, 3, 4}) {
    const NodePartition p = partitionNodes(m, mask, parts);
    std::vector<int> sorted = p.order;
    std::sort(sorted.begin(), sorted.end());
    for (int i = 0; i < m.numNodes(); ++i) ASSERT_EQ(sorted[i], i);  // a permutation
    // The bars lie along z: each part is a slab [zmin, zmax] not overlapping the others.
    std::vector<double> lo(parts, 1e9), hi(parts, -1e9);
    for (int i = 0; i < m.numNodes(); ++i) {
      lo[p.partOf[i]] = std::min(lo[p.partOf[i]], m.coords[i][2]);
      hi[p.partOf[i]] = std::max(hi[p.partOf[i]], m.coords[i][2]);
    }
    std::vector<int> byZ(parts);
    std::iota(byZ.begin(), byZ.end(), 0);
    std::sort(byZ.begin(), byZ.end(), [&](int a, int b) { return lo[a] < lo[b]; });
    for (int k = 1; k < parts; ++k) EXPECT_LE(hi[byZ[k - 1]], lo[byZ[k]]) << parts << " parts";
    const PartitionQuality q = partitionQuality(m, mask, p);
    EXPECT_LE(q.imbalance, 1.1) << parts << " parts";  // a layer is 9 of 2 x 21 x 9 nodes
    // Two parts: one bar each (the cut falls in the gap, no element spans it); more parts cut
    // through a bar.
    if (parts == 2) EXPECT_EQ(q.sharedNodes, 0);
    else EXPECT_GT(q.sharedNodes, 0);
    for (int r = 0; r < parts; ++r)
      for (int k = p.rankBegin[r]; k < p.rankBegin[r + 1]; ++k) EXPECT_EQ(p.partOf[p.order[k]], r);
  }
}

TEST(NodePartition, DoesNotDependOnTheNumbering) {
  const Mesh m = bars();
  std::vector<int> perm;
  const Mesh r = renumberedMesh(m, 12345, &perm);
  const std::vector<std::uint8_t> mask(m.numNodes(), 0b111);
  const NodePartition a = partitionNodes(m, mask, 2), b = partitionNodes(r, mask, 2);
  int same = 0;
  for (int i = 0; i < m.numNodes(); ++i) same += a.partOf[i] == b.partOf[perm[i]];
  // The same slabs (possibly with the two part numbers swapped).
  EXPECT_TRUE(same == m.numNodes() || same == 0) << same << " of " << m.numNodes();
}

TEST(NodePartition, DofMapAlongThePartitionOrder) {
  const Mesh m = bars();
  std::vector<std::uint8_t> mask(m.numNodes(), 0b111);
  mask[5] = 0;       // a fixed node
  mask[7] = 0b100;   // DZ only
  const NodePartition p = partitionNodes(m, mask, 2);
  long long total = 0;
  for (auto x : mask) total += __builtin_popcount(x);
  std::vector<int> owners(total, -1);
  for (int rank = 0; rank < 2; ++rank) {
    const DofMap d(mask, p.order, p.rankBegin, rank);
    ASSERT_EQ(d.numGlobal(), total);
    for (int n = 0; n < m.numNodes(); ++n) {
      EXPECT_EQ(d.ownsNode(n), p.partOf[n] == rank);
      EXPECT_EQ(d.ownerOfNode(n), p.partOf[n]);
      for (int c = 0; c < 3; ++c) {
        const long long g = d.dof(n, c);
        if (!((mask[n] >> c) & 1)) {
          EXPECT_EQ(g, -1);
          continue;
        }
        const bool mine = g >= d.firstOwned() && g < d.firstOwned() + d.numOwned();
        EXPECT_EQ(mine, d.ownsNode(n)) << "node " << n;  // owned DOFs are the owned nodes'
        if (mine) owners[g] = rank;
      }
    }
  }
  for (long long g = 0; g < total; ++g) EXPECT_GE(owners[g], 0) << "DOF " << g << " has no owner";
}

}  // namespace
}  // namespace choc
