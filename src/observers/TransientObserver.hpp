// Output of a transient through observers: begin before the first recorded state, step at
// every recorded state (the initial one included), end(ok) once, where files are finished
// (ok) or abandoned as *.incomplete.* (a failure or an interruption). ObserverSet::run wraps
// a time loop so that end(false) is called on every way out by an exception.
#pragma once
#include <exception>
#include <functional>
#include <memory>
#include <vector>

#include "core/Errors.hpp"
#include "observers/TransientView.hpp"
#include "restart/StateArchive.hpp"

namespace choc {

class TransientObserver {
 public:
  virtual ~TransientObserver() = default;
  virtual void begin(TransientView&) {}
  virtual void step(TransientView& view) = 0;
  // A sub-step of an explicit scheme inside a step, at `time` (its interactions current):
  // only what integrates over every computed state needs it (impact statistics).
  virtual void substep(TransientView& /*view*/, double /*time*/) {}
  virtual void end(bool /*ok*/) {}
  // The run stops on a numerical failure every rank agreed on (NumericalError: an inverted
  // element, Newton out of cuts, an unstable step), before end(false): the view still shows the
  // last accepted state, which an output may record (collective) so that the partial results
  // end where the run did.
  virtual void failed(TransientView& /*view*/) {}
  // What the observer carries between states (energy integrals, file positions), for a
  // checkpoint; called on every rank at the same state (it may be collective).
  virtual void archive(StateArchive& /*a*/) const {}
};

class ObserverSet {
 public:
  // Observers are called in the order they were added (the history first: the others
  // read the energies it recorded).
  void add(std::unique_ptr<TransientObserver> o) { observers_.push_back(std::move(o)); }
  void begin(TransientView& view) {
    for (auto& o : observers_) o->begin(view);
  }
  void step(TransientView& view) {
    for (auto& o : observers_) o->step(view);
  }
  void substep(TransientView& view, double time) {
    for (auto& o : observers_) o->substep(view, time);
  }
  void archive(StateArchive& a) const {
    for (const auto& o : observers_) o->archive(a);
  }
  // begin, the loop, end(true); end(false) and rethrow if anything throws.
  void run(TransientView& view, const std::function<void()>& loop) {
    try {
      begin(view);
      loop();
    } catch (const NumericalError&) {
      try {
        for (auto& o : observers_) o->failed(view);
      } catch (const std::exception&) {
        // the run's own failure is the one to report
      }
      for (auto& o : observers_) o->end(false);
      throw;
    } catch (...) {
      for (auto& o : observers_) o->end(false);
      throw;
    }
    // Every observer finishes its files, even after one failed to (a full disk at the impact
    // statistics): a complete file keeps its name; the first failure is then reported.
    std::exception_ptr first;
    for (auto& o : observers_) {
      try {
        o->end(true);
      } catch (...) {
        if (!first) first = std::current_exception();
      }
    }
    if (first) std::rethrow_exception(first);
  }

 private:
  std::vector<std::unique_ptr<TransientObserver>> observers_;
};

}  // namespace choc
