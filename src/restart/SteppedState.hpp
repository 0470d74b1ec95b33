// The one lifecycle of every state that follows the steps of a transient: the material points'
// (InternalForce), the contact statuses, multipliers and friction (ContactStrategy over ContactManager), the shock
// links' (DirectLinks, ModalLinks), and the operator and steppers that hold them. Named once:
//
//   trial     an evaluation at a trial u (a residual, a Newton iterate) computes the state at u
//             from the accepted one without replacing it (never in a const function);
//   commit()  the step is accepted: the last trial becomes the accepted state;
//   revert()  the step is cut or failed: the trial is dropped, the next evaluation starts again
//             from the accepted state;
//   archive(a) / restore(a)
//             the accepted state into a checkpoint's records, and back (restart: bit for bit).
//
// A motion that accumulates over accepted steps (a followed contact's slip path) is committed
// with the u it ended at (SecondOrderOperator::commitMotion).
#pragma once
#include "restart/StateArchive.hpp"

namespace choc {

class SteppedState {
 public:
  virtual ~SteppedState() = default;
  virtual void commit() {}
  virtual void revert() {}
  virtual void archive(StateArchive& /*a*/) const {}
  virtual void restore(const StateArchive& /*a*/) {}
};

}  // namespace choc
