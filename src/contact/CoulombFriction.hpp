// Coulomb friction of the contact pairs: a layer of its own over the contact manager's geometry
// (its constraints, pairs, contact DOFs, active set and method, read through references).
//
// Implicit: per active slave node, an elastic-plastic tangential law on the
// step's relative tangential motion on the current master surface, delta = P (r(u) - r(u_n)) with
// P = I - n n^T and r = u_s - sum_i w_i u_i (less the obstacle's motion): the trial force on the
// slave node F* = P F_n - k_t delta, kept while |F*| <= mu f_N (stick), returned onto the cone
// F = mu f_N F* / |F*| otherwise (slip), f_N the normal force of the current iterate. The force
// enters the residual with the normal one (the master nodes take -w_i F); its consistent tangent
// (with d f_N / du and d f_N / d lambda: not symmetric while sliding) is tangent(). Stick and slip
// are decided at every residual evaluation, inside the Newton loop that also carries the normal
// multipliers; an accepted step commits the forces and the work.
//
// Explicit: by forward increments at each sub-step, after the
// normal pressures (useForwardIncrements).
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "contact/ContactActiveSet.hpp"
#include "contact/ContactMethod.hpp"
#include "contact/ContactPairing.hpp"
#include "contact/CoulombLaw.hpp"
#include "contact/MatrixEntry.hpp"
#include "fem/DofMap.hpp"
#include "restart/StateArchive.hpp"

namespace choc {

struct ContactConstraint;

class CoulombFriction {
 public:
  // What friction reads of the contact manager: references to its members, valid while it lives.
  struct Geometry {
    const std::vector<ContactConstraint>& constraints;
    const std::vector<PairDefinition>& pairs;
    const std::vector<GO>& contactDofs;  // sorted distinct DOFs of every constraint
    const DofMap& dofs;
    RCP<const Map> map;
    const ContactActiveSet& set;
    const ContactMethod& method;
  };
  explicit CoulombFriction(Geometry g);

  // The relative-motion terms of every constraint, after each pairing.
  void index();
  void setTangentialStiffness(double kt) { kt_ = kt; }  // k_t [N/m] per slave node
  double tangentialStiffness() const { return kt_; }
  void useForwardIncrements(bool on) { increments_ = on; }

  // The implicit law at the contact DOFs' values x (gaps g): out -= the friction forces on the
  // rows this rank owns (a trial: the law's state of this evaluation kept for the tangent).
  void addForces(const std::vector<double>& x, const std::vector<double>& g, Vector& out);
  // Matrix entries of the tangent (d residual / d(u, lambda / scale)) at the last evaluation, on
  // the rows this rank owns; multiplierBase: the global id of constraint 0's multiplier row.
  std::vector<MatrixEntry> tangent(GO multiplierBase) const;
  // Per node: 0 no friction force, 1 stick, 2 slip at the last evaluation; then, while a node
  // slides, the evaluation count (the tangent changes with every iterate).
  std::vector<char> key() const;
  // Before a step to t of length dt: r(u_n) from the values of the step's start (asked only when
  // needed: implicit runs).
  void beginStep(double t, double dt, const std::function<std::vector<double>()>& startValues);
  // An accepted step ending at u (values and gaps of it, asked only when needed): its forces
  // become the accepted ones and the work less what the stick springs store is dissipated.
  void commitMotion(const std::function<std::vector<double>()>& values,
                    const std::function<std::vector<double>(const std::vector<double>&)>& gaps);
  // Explicit: the tangential forces of the sub-step from the values x at u to xStar at the
  // predicted positions (h the sub-step, h2 the acceleration's factor), w the inverse lumped
  // masses at the contact DOFs; adds M^-1 F to a. where() names the contact state for an error.
  void increment(const std::vector<double>& x, const std::vector<double>& xStar, double h, double h2,
                 const std::vector<double>& w, const Vector& inverseMass, Vector& a,
                 const std::function<std::string()>& where);

  // Accepted state: per node the friction force on the slave node [N] and stick/slip status,
  // the friction work dissipated since the start [J] (all pairs, one pair) and the stick
  // springs' energy [J].
  const std::vector<Vec3>& forces() const { return accepted_; }
  const std::vector<char>& status() const { return acceptedStatus_; }
  double dissipation() const { return dissipated_; }
  double dissipation(int pair) const { return pairWork_[size_t(pair)]; }
  double stickEnergy() const;
  void archive(StateArchive& a) const;
  void restore(const StateArchive& a);

 private:
  struct Term {
    int k;          // index into contactDofs
    int component;  // 0, 1, 2
    double coeff;   // 1 for the slave node, -w_i for a master node
    GO dof;
  };
  Vec3 relativeMotion(int s, const std::vector<double>& x, double t) const;
  void evaluate(const std::vector<double>& x, const std::vector<double>& g);
  std::vector<Vec3> tangentialForces(const std::vector<Vec3>& predicted, const std::vector<Vec3>& d,
                                     const std::vector<char>& acts, const std::vector<double>& w, double h2,
                                     double scale, const std::function<std::string()>& where) const;
  Geometry g_;
  double kt_ = 0.0;
  std::vector<std::vector<Term>> rel_;  // per constraint: r = u_s - sum_i w_i u_i
  std::vector<Vec3> accepted_, start_;  // F at the last accepted step (in the plane), r(u_n)
  // Explicit central differences: the tangential forces are decided at each sub-step; accepted_
  // holds the last sub-step's forces, start_ the relative positions they were decided at.
  bool increments_ = false;
  bool started_ = false;  // start_ holds the relative positions of a forward increment
  std::vector<char> acceptedStatus_;
  double dissipated_ = 0.0;
  std::vector<double> pairWork_;  // per pair: its part of dissipated_
  double time_ = 0.0;             // end of the current step
  // The last evaluation (the trial of the residual's addForces): the law's state per node
  // (CoulombLaw.hpp) and its normal force.
  std::vector<CoulombPoint> point_;
  std::vector<double> normalForce_;
  long long evaluations_ = 0;
  // Within a step: each node's last slip direction and how often an iterate reversed it. An
  // iterate that slides against the node's last slip direction jumped over the stick band
  // 2 mu f_N / k_t (the slip tangent has no stiffness along the slip: Newton crosses the band
  // from side to side). Such an iterate is evaluated as sticking (the force F* and the stick
  // stiffness, a linear law): the next iterate lands where the stick force balances, inside
  // the band if the node sticks. Twice per node and step at most, so that Newton converges on
  // the Coulomb law itself.
  std::vector<Vec3> lastDirection_;
  std::vector<int> reversals_;
};

}  // namespace choc
