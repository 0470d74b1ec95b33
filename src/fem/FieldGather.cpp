#include "fem/FieldGather.hpp"

#include <mpi.h>

#include <Tpetra_MultiVector.hpp>

namespace choc {

std::vector<double> gatherAll(const MultiVector& v, size_t col, const DofMap& dofs) {
  std::vector<double> out(static_cast<size_t>(dofs.numGlobal()));
  auto local = v.getData(col);
  int init = 0;
  MPI_Initialized(&init);
  int size = 1;
  if (init) MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size == 1) {
    for (size_t i = 0; i < out.size(); ++i) out[i] = local[i];
    return out;
  }
  int mine = dofs.numOwned();
  std::vector<int> counts(size), displs(size);
  MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  for (int r = 1; r < size; ++r) displs[r] = displs[r - 1] + counts[r - 1];
  MPI_Allgatherv(local.getRawPtr(), mine, MPI_DOUBLE, out.data(), counts.data(), displs.data(),
                 MPI_DOUBLE, MPI_COMM_WORLD);
  return out;
}

std::vector<double> nodalComponent(const std::vector<double>& global, const DofMap& dofs, int comp) {
  std::vector<double> out(dofs.numNodes(), 0.0);
  for (int n = 0; n < dofs.numNodes(); ++n) {
    const long long d = dofs.dof(n, comp);
    if (d >= 0) out[n] = global[d];
  }
  return out;
}

}  // namespace choc

namespace choc {

std::vector<double> gatherRows(const MultiVector& V, const std::vector<long long>& dofs) {
  const size_t nv = V.getNumVectors();
  std::vector<double> local(dofs.size() * nv, 0.0), out(dofs.size() * nv, 0.0);
  auto map = V.getMap();
  for (size_t i = 0; i < dofs.size(); ++i) {
    if (dofs[i] < 0 || !map->isNodeGlobalElement(GO(dofs[i]))) continue;
    const LO lid = map->getLocalElement(GO(dofs[i]));
    for (size_t k = 0; k < nv; ++k) local[i * nv + k] = V.getData(k)[lid];
  }
  int init = 0;
  MPI_Initialized(&init);
  if (!init) return local;
  MPI_Allreduce(local.data(), out.data(), static_cast<int>(local.size()), MPI_DOUBLE, MPI_SUM,
                MPI_COMM_WORLD);
  return out;
}

}  // namespace choc
