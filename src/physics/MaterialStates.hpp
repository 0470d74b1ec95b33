// The material points' states of the element-by-element blocks (FiniteStrainForce), every
// element's in one array, in two copies with the lifecycle of restart/SteppedState.hpp: the
// committed copy (the last accepted step's) that every evaluation starts from, and the trial
// copy the last internal force wrote (its u's). commit() makes that trial the committed state
// (the steppers call it right after the force at the accepted u), revert() drops it. The
// committed increments' dissipated work is summed in dissipatedWork(); the committed states and
// that work are in the checkpoint, stored by global element number, so a run restarts on any
// number of ranks. At each commit the alarms are reported once on the log: a point's damage
// reaching 1 (failure predicted) and points at their melting temperature.
#pragma once
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/TpetraTypes.hpp"
#include "fem/FiniteStrainSolid.hpp"
#include "restart/SteppedState.hpp"

namespace choc {

struct Mesh;

class MaterialStates : public SteppedState {
 public:
  MaterialStates(RCP<const Comm> comm, std::vector<std::string> blockNames) : comm_(std::move(comm)),
                                                                              blockNames_(std::move(blockNames)) {}
  // An element of this rank: its virgin state appended; returns its offset in the arrays.
  size_t add(const FiniteStrainSolid& kernel, int number, int block, bool owner);
  // Every element's place in the archive's global array (by global element number), once every
  // element was added.
  void layout(const Mesh& mesh, const std::vector<std::shared_ptr<const FiniteStrainSolid>>& kernels);
  bool any() const { return any_; }
  const double* committed() const { return committed_.data(); }
  // The trial copy the next internal force writes.
  double* trial() { return trial_.data(); }
  const double* trial() const { return trial_.data(); }
  // The time of the committed state (the start, until a step is committed): an increment's
  // duration for rate-dependent laws is its time minus this.
  double committedTime() const { return committedTime_; }
  void startAt(double t) {
    if (!timeKnown_) committedTime_ = t, timeKnown_ = true;
  }
  // The internal force wrote the trial at time t (valid: on every element), the owners'
  // dissipated work of its increment being `work` (this rank).
  void trialWritten(bool valid, double t, double work) { trialValid_ = valid, trialTime_ = t, trialWork_ = work; }
  double dissipatedWork() const { return dissipatedWork_; }
  void commit() override;
  void revert() override { trialValid_ = false; }
  void archive(StateArchive& a) const override;
  void restore(const StateArchive& a) override;

 private:
  struct Element {
    const FiniteStrainSolid* kernel;
    int number, block;
    bool owner;
    size_t offset;
  };
  std::string describe(const Element& e, const std::string& what) const;
  void reportPredictedFailure();
  double largestCommittedDamage() const;
  void reportMelting();
  // The committed points at or above their melting temperature, over every rank (collective), and
  // the lowest-numbered element holding one (-1: none).
  std::pair<long, int> committedMelting() const;

  RCP<const Comm> comm_;
  std::vector<std::string> blockNames_;
  std::vector<Element> elements_;
  std::vector<double> committed_, trial_;
  bool any_ = false;      // some element keeps state
  bool thermal_ = false;  // a block's points carry a temperature
  bool damage_ = false;   // a block accumulates damage
  bool trialValid_ = false;
  double trialWork_ = 0.0;       // the owners' dissipated work of the trial increment (this rank)
  double dissipatedWork_ = 0.0;  // the committed increments', all ranks [J]
  double committedTime_ = 0.0, trialTime_ = 0.0;
  bool timeKnown_ = false;
  bool failurePredicted_ = false;  // a point's damage reached 1 (logged once)
  bool meltingReported_ = false;   // a point reached its melting temperature (logged once)
  std::vector<size_t> globalOffset_;  // per global element: its state's offset in the archive (-1: none)
  size_t globalSize_ = 0;
};

}  // namespace choc
