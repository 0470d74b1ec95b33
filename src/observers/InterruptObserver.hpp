// SIGINT/SIGTERM stop a transient at a recorded state: every `every` states the flag set by
// the signal handler is tested (reduced over the ranks: every rank must test at the same
// states), and Interrupted is thrown so that the other observers abandon their files.
#pragma once
#include <mpi.h>

#include <string>

#include "observers/TransientObserver.hpp"
#include "output/Interrupt.hpp"

namespace choc {

class InterruptObserver : public TransientObserver {
 public:
  InterruptObserver(std::string what, MPI_Comm comm, long long every)
      : what_(std::move(what)), comm_(comm), every_(every) {}
  void step(TransientView& view) override {
    const StepPoint pt = view.point();
    if (pt.step % every_ == 0) throwIfInterrupted(what_, pt.time, comm_);
  }

 private:
  std::string what_;
  MPI_Comm comm_;
  long long every_;
};

}  // namespace choc
