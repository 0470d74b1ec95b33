// The material points' states, their lifecycle and their alarms (MaterialStates.hpp).
#include "physics/MaterialStates.hpp"

#include <algorithm>
#include <limits>

#include <Teuchos_CommHelpers.hpp>

#include "core/CollectiveFailure.hpp"
#include "core/Format.hpp"
#include "core/Log.hpp"
#include "mesh/Mesh.hpp"

namespace choc {

size_t MaterialStates::add(const FiniteStrainSolid& kernel, int number, int block, bool owner) {
  const size_t offset = committed_.size();
  committed_.resize(offset + size_t(kernel.stateSize()));
  kernel.initialState(committed_.data() + offset);
  elements_.push_back({&kernel, number, block, owner, offset});
  return offset;
}

// Every element's state's offset in the archive's global array (element order).
void MaterialStates::layout(const Mesh& mesh, const std::vector<std::shared_ptr<const FiniteStrainSolid>>& kernels) {
  trial_ = committed_;
  const int numElements = mesh.numElements();
  globalOffset_.assign(size_t(numElements), size_t(-1));
  for (int ge = 0; ge < numElements; ++ge) {
    const auto [b, e] = mesh.locateElement(ge);
    const int n = kernels[size_t(b)] ? kernels[size_t(b)]->stateSize() : 0;
    if (n == 0) continue;
    any_ = true;
    thermal_ = thermal_ || kernels[size_t(b)]->thermal();
    damage_ = damage_ || kernels[size_t(b)]->damaged();
    globalOffset_[size_t(ge)] = globalSize_;
    globalSize_ += size_t(n);
  }
}

std::string MaterialStates::describe(const Element& e, const std::string& what) const {
  return "element " + std::to_string(e.number + 1) + " of block '" + blockNames_[size_t(e.block)] + "': " + what;
}

void MaterialStates::commit() {
  if (!any_ || !trialValid_) return;
  committed_.swap(trial_);  // the force wrote every element's trial state: no copy needed
  committedTime_ = trialTime_;
  double work = 0.0;
  Teuchos::reduceAll<int, double>(*comm_, Teuchos::REDUCE_SUM, trialWork_, Teuchos::outArg(work));
  dissipatedWork_ += work;
  trialValid_ = false;
  if (damage_ && !failurePredicted_) reportPredictedFailure();
  if (thermal_ && !meltingReported_) reportMelting();
}

std::pair<long, int> MaterialStates::committedMelting() const {
  long mine = 0, count = 0;
  int firstMine = std::numeric_limits<int>::max(), first = firstMine;
  for (const Element& e : elements_) {
    if (!e.owner) continue;
    const int n = e.kernel->pointsAtMelting(committed_.data() + e.offset);
    mine += n;
    if (n > 0) firstMine = std::min(firstMine, e.number);
  }
  const Comm& comm = *comm_;
  Teuchos::reduceAll<int, long>(comm, Teuchos::REDUCE_SUM, mine, Teuchos::outArg(count));
  Teuchos::reduceAll<int, int>(comm, Teuchos::REDUCE_MIN, firstMine, Teuchos::outArg(first));
  return {count, count > 0 ? first : -1};
}

// The first committed state in which Johnson-Cook points reach their melting temperature (the flow
// stress is zero there: the metal flows as a liquid would without a viscosity): one line on the
// log with the count of such points, the first element and the time.
void MaterialStates::reportMelting() {
  const auto [count, first] = committedMelting();
  if (count == 0) return;
  meltingReported_ = true;
  std::string line;
  for (const Element& e : elements_)
    if (e.owner && e.number == first)
      line = format("warning: %ld Johnson-Cook point(s) reached the melting temperature at t = %.6g s, the first in ",
                    count, committedTime_) +
             describe(e, "their flow stress is below 1 % of the cold one (1 - T*^m <= 0.01): the solid model holds "
                         "below melting");
  line = collectiveFailure(*comm_, line);
  if (isRootRank()) log() << line << "\n";
}

// The first committed state in which a point's damage reaches 1: one line on the log naming the
// element (the lowest-numbered among those whose largest point damage is the largest of all).
void MaterialStates::reportPredictedFailure() {
  const double largest = largestCommittedDamage();
  if (!(largest >= 1.0)) return;
  failurePredicted_ = true;
  const Comm& comm = *comm_;
  int first = std::numeric_limits<int>::max(), mine = first;
  for (const Element& e : elements_)
    if (e.owner && e.kernel->largestDamage(committed_.data() + e.offset) == largest) mine = std::min(mine, e.number);
  Teuchos::reduceAll<int, int>(comm, Teuchos::REDUCE_MIN, mine, Teuchos::outArg(first));
  std::string line;
  for (const Element& e : elements_)
    if (e.owner && e.number == first)
      line = format("damage: Johnson-Cook's D reached %.4g at t = %.6g s in ", largest, committedTime_) +
             describe(e, "failure predicted there (reported only: no softening, no erosion)");
  line = collectiveFailure(comm, line);
  if (isRootRank()) log() << line << "\n";
}

// The largest point damage of the committed states over every rank (collective).
double MaterialStates::largestCommittedDamage() const {
  double local = 0.0, largest = 0.0;
  for (const Element& e : elements_)
    if (e.owner) local = std::max(local, e.kernel->largestDamage(committed_.data() + e.offset));
  Teuchos::reduceAll<int, double>(*comm_, Teuchos::REDUCE_MAX, local, Teuchos::outArg(largest));
  return largest;
}

// Each element's committed state by its owner, summed over the ranks into one array in global
// element order.
void MaterialStates::archive(StateArchive& a) const {
  if (!any_) return;
  std::vector<double> local(globalSize_, 0.0), global(globalSize_, 0.0);
  for (const Element& e : elements_) {
    if (!e.owner) continue;
    const size_t n = size_t(e.kernel->stateSize());
    std::copy_n(committed_.begin() + long(e.offset), n, local.begin() + long(globalOffset_[size_t(e.number)]));
  }
  if (!local.empty())
    Teuchos::reduceAll<int, double>(*comm_, Teuchos::REDUCE_SUM, int(local.size()), local.data(),
                                    global.data());
  a.putVector("internal/plasticState", global);
  a.putDouble("internal/plasticWork", dissipatedWork_);
  a.putDouble("internal/plasticTime", committedTime_);
}

void MaterialStates::restore(const StateArchive& a) {
  if (!any_) return;
  const std::vector<double> global = a.getVector<double>("internal/plasticState", globalSize_);
  for (const Element& e : elements_)
    std::copy_n(global.begin() + long(globalOffset_[size_t(e.number)]), size_t(e.kernel->stateSize()),
                committed_.begin() + long(e.offset));
  dissipatedWork_ = a.getDouble("internal/plasticWork");
  committedTime_ = a.getDouble("internal/plasticTime");
  // A failure the run before the checkpoint logged is not logged again.
  failurePredicted_ = damage_ && largestCommittedDamage() >= 1.0;
  meltingReported_ = thermal_ && committedMelting().first > 0;
  timeKnown_ = true;
  trialValid_ = false;
}

}  // namespace choc
