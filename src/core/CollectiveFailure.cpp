#include "core/CollectiveFailure.hpp"

#include <vector>

#include <Teuchos_CommHelpers.hpp>

namespace choc {

std::string collectiveFailure(const Comm& comm, const std::string& localFailure) {
  const int size = comm.getSize();
  if (size == 1) return localFailure;
  const int mine = localFailure.empty() ? size : comm.getRank();
  int first = size;
  Teuchos::reduceAll<int, int>(comm, Teuchos::REDUCE_MIN, mine, Teuchos::outArg(first));
  if (first == size) return "";
  int length = comm.getRank() == first ? static_cast<int>(localFailure.size()) : 0;
  Teuchos::broadcast<int, int>(comm, first, Teuchos::outArg(length));
  std::vector<char> text(localFailure.begin(), localFailure.end());
  text.resize(static_cast<std::size_t>(length));
  if (length > 0) Teuchos::broadcast<int, char>(comm, first, length, text.data());
  return std::string(text.begin(), text.end());
}

}  // namespace choc
