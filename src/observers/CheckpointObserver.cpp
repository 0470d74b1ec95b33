#include "observers/CheckpointObserver.hpp"

#include <csignal>
#include <cstdlib>

#include <Teuchos_DefaultMpiComm.hpp>

#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "core/Log.hpp"
#include "observers/HistoryObserver.hpp"
#include "output/Interrupt.hpp"
#include "restart/CheckpointFile.hpp"
#include "core/CollectiveFailure.hpp"

namespace choc {


namespace {

// Test hook: CHOC_TEST_SIGNAL_AT_STEP=[ANALYSIS:]N acts as a SIGTERM received during nominal
// step N (of analysis ANALYSIS only, when given), so the restart tests stop a run at chosen
// states (before, during and after a contact).
long long testSignalStep(const std::string& what) {
  const char* e = std::getenv("CHOC_TEST_SIGNAL_AT_STEP");
  if (!e) return -1;
  const std::string v = e;
  const auto colon = v.rfind(':');
  if (colon != std::string::npos && what.find("'" + v.substr(0, colon) + "'") == std::string::npos) return -1;
  return std::atoll(v.c_str() + (colon == std::string::npos ? 0 : colon + 1));
}

}  // namespace

CheckpointObserver::CheckpointObserver(std::string what, MPI_Comm comm, long long every,
                                       CheckpointPlan plan, const ObserverSet& outputs,
                                       const HistoryObserver* history)
    : what_(std::move(what)), comm_(comm), every_(every), plan_(std::move(plan)), outputs_(outputs),
      last_(std::chrono::steady_clock::now()), testStep_(testSignalStep(what_)), history_(history) {}

void CheckpointObserver::step(TransientView& view) {
  const StepPoint pt = view.point();
  if (pt.boundary && pt.nominal == testStep_) setInterruptForTesting(SIGTERM);
  if (!pt.boundary || (pt.step % every_ != 0 && !pt.last)) return;  // and always at the end
  const CheckpointSettings& s = plan_.settings;
  // [signal, wall time due, a result not written], agreed by every rank.
  int flags[3] = {interruptSignal(), 0, history_ && !history_->pendingFailure().empty()};
  if (s.intervalSeconds > 0)
    flags[1] = std::chrono::duration<double>(std::chrono::steady_clock::now() - last_).count() >=
               s.intervalSeconds;
  int size = 1;
  MPI_Comm_size(comm_, &size);
  if (size > 1) MPI_Allreduce(MPI_IN_PLACE, flags, 3, MPI_INT, MPI_MAX, comm_);
  if (flags[2] != 0) {
    const Teuchos::MpiComm<int> comm(comm_);
    throw OutputError(collectiveFailure(comm, history_ ? history_->pendingFailure() : std::string()));
  }
  const bool due = flags[0] != 0 || flags[1] != 0 ||
                   (s.intervalSteps > 0 && pt.nominal > 0 && pt.nominal % s.intervalSteps == 0);
  if (due && !pt.last && pt.step > 0) write(pt);
  if (flags[0] != 0) {
    std::string m = interruptedMessage(flags[0], what_, pt.time);
    if (!pt.last && pt.step > 0) m += "; continue it with --restart " + plan_.path;
    throw Interrupted(flags[0], m);
  }
}

void CheckpointObserver::write(const StepPoint& pt) {
  StateArchive a;
  plan_.identity.save(a);
  a.putDouble("point/time", pt.time);
  a.putInt("point/step", pt.step);
  a.putInt("point/nominal", pt.nominal);
  plan_.archiveRun(a);  // collective
  std::string failure;
  try {
    outputs_.archive(a);  // local: file positions (flushed)
    if (isRootRank()) writeCheckpointFile(plan_.path, a);
  } catch (const std::exception& e) {
    failure = e.what();
  }
  const Teuchos::MpiComm<int> comm(comm_);
  failure = collectiveFailure(comm, failure);
  if (!failure.empty()) throw OutputError(failure);
  last_ = std::chrono::steady_clock::now();
  log() << format("  checkpoint at t = %.6e s (step %lld): %s\n", pt.time, pt.nominal, plan_.path.c_str());
}

}  // namespace choc
