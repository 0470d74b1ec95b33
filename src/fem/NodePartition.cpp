#include "fem/NodePartition.hpp"

#include <Teuchos_DefaultMpiComm.hpp>
#include <Zoltan2_BasicVectorAdapter.hpp>
#include <Zoltan2_PartitioningProblem.hpp>

#include <algorithm>
#include <bitset>
#include <stdexcept>

namespace choc {

namespace {

using ZoltanTypes = Zoltan2::BasicUserTypes<double, int, long long>;
using Adapter = Zoltan2::BasicVectorAdapter<ZoltanTypes>;

std::vector<int> rcbParts(const Mesh& mesh, const std::vector<std::uint8_t>& freeMask, int numParts) {
  const int n = mesh.numNodes();
  std::vector<long long> ids(n);
  std::vector<double> x(n), y(n), z(n), w(n);
  for (int i = 0; i < n; ++i) {
    ids[i] = i;
    x[i] = mesh.coords[i][0];
    y[i] = mesh.coords[i][1];
    z[i] = mesh.coords[i][2];
    w[i] = double(std::bitset<8>(freeMask[i]).count());
  }
  Adapter adapter(n, ids.data(), x.data(), y.data(), z.data(), 1, 1, 1, true, w.data(), 1);
  Teuchos::ParameterList params("partition");
  params.set("algorithm", "rcb");
  params.set("num_global_parts", numParts);
  params.set("imbalance_tolerance", 1.02);
  params.sublist("zoltan_parameters").set("DEBUG_LEVEL", "0");  // no parameter echo on stdout
  // On this process alone: every rank computes the same partition.
  Teuchos::RCP<const Teuchos::Comm<int>> self =
      Teuchos::rcp(new Teuchos::MpiComm<int>(Teuchos::opaqueWrapper(MPI_Comm(MPI_COMM_SELF))));
  Zoltan2::PartitioningProblem<Adapter> problem(&adapter, &params, self);
  problem.solve();
  const int* parts = problem.getSolution().getPartListView();
  if (!parts) throw std::runtime_error("Zoltan2 RCB returned no partition");
  std::vector<int> out(parts, parts + n);
  for (int p : out)
    if (p < 0 || p >= numParts) throw std::runtime_error("Zoltan2 RCB returned part " + std::to_string(p));
  return out;
}

}  // namespace

NodePartition partitionNodes(const Mesh& mesh, const std::vector<std::uint8_t>& freeMask, int numParts) {
  const int n = mesh.numNodes();
  NodePartition p;
  p.partOf = numParts > 1 ? rcbParts(mesh, freeMask, numParts) : std::vector<int>(n, 0);
  p.order.resize(n);
  for (int i = 0; i < n; ++i) p.order[i] = i;
  std::stable_sort(p.order.begin(), p.order.end(), [&](int a, int b) { return p.partOf[a] < p.partOf[b]; });
  p.rankBegin.assign(numParts + 1, n);
  for (int r = numParts - 1; r >= 0; --r) {
    p.rankBegin[r] = p.rankBegin[r + 1];
    while (p.rankBegin[r] > 0 && p.partOf[p.order[p.rankBegin[r] - 1]] >= r) --p.rankBegin[r];
  }
  p.rankBegin[0] = 0;
  return p;
}

PartitionQuality partitionQuality(const Mesh& mesh, const std::vector<std::uint8_t>& freeMask,
                                  const NodePartition& p) {
  PartitionQuality q;
  const int parts = static_cast<int>(p.rankBegin.size()) - 1;
  q.dofsPerPart.assign(parts, 0);
  for (int i = 0; i < mesh.numNodes(); ++i) q.dofsPerPart[p.partOf[i]] += std::bitset<8>(freeMask[i]).count();
  long long total = 0, most = 0;
  for (long long d : q.dofsPerPart) {
    total += d;
    most = std::max(most, d);
  }
  q.imbalance = total > 0 ? double(most) * parts / double(total) : 1.0;
  std::vector<char> shared(mesh.numNodes(), 0);
  for (const ElementBlock& b : mesh.blocks)
    for (int e = 0; e < b.numElements(); ++e) {
      const int* c = &b.connectivity[size_t(e) * b.nodesPerElement];
      bool spans = false;
      for (int k = 1; k < b.nodesPerElement; ++k) spans = spans || p.partOf[c[k]] != p.partOf[c[0]];
      if (spans)
        for (int k = 0; k < b.nodesPerElement; ++k) shared[c[k]] = 1;
    }
  for (char s : shared) q.sharedNodes += s;
  return q;
}

}  // namespace choc
