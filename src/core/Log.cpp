#include "core/Log.hpp"

#include <iostream>
#include <mpi.h>

namespace choc {

namespace {
class NullBuffer : public std::streambuf {
 protected:
  int overflow(int c) override { return c; }
};
}  // namespace

bool isRootRank() {
  int init = 0;
  MPI_Initialized(&init);
  if (!init) return true;
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank == 0;
}

std::ostream& log() {
  static NullBuffer nullBuffer;
  static std::ostream nullStream(&nullBuffer);
  return isRootRank() ? std::cout : nullStream;
}

}  // namespace choc
