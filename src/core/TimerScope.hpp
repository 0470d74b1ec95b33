// A sub-timer of a Teuchos::StackedTimer started for the lifetime of a scope.
#pragma once
#include <Teuchos_StackedTimer.hpp>

namespace choc {

// Starts a sub-timer of a StackedTimer for the scope (no-op for a null timer).
class TimerScope {
 public:
  TimerScope(Teuchos::StackedTimer* t, const char* name) : t_(t), name_(name) {
    if (t_) t_->start(name_, false);
  }
  ~TimerScope() {
    if (t_) t_->stop(name_, false);
  }
  TimerScope(const TimerScope&) = delete;
  TimerScope& operator=(const TimerScope&) = delete;

 private:
  Teuchos::StackedTimer* t_;
  const char* name_;
};

}  // namespace choc
