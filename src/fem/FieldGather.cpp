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
