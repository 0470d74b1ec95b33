// Impact statistics of a transient's interactions (the shock links of a modal transient): per
// impact its start and end (the instants the normal force crosses 'Force Threshold', by
// linear interpolation between states; on the gap itself when the threshold is 0), the
// instant and value of the peak force (the vertex of the parabola through the largest sample
// and its neighbours), the contact duration, the impulse (trapezoidal), the impact velocity
// (the gap rate d(gap)/dt at the last state before the impact: negative when closing; for a
// contact pair, whose gap rate is the backward difference of its smallest gap, the secant over
// the interval where the impact starts when it starts at the first state) and the
// wear work (integral of tangential force x slip speed); per interaction the number of impacts,
// (a force below 1e-6 of the largest so far counts as none: round-off of exactly enforced contact)
// the largest and mean peak force, the total impulse and wear work. Two contacts separated by
// less than 'Minimum Rest Time' are one impact. Written to <analysis>.impacts.csv when the run
// ends (".incomplete" when it fails), summarised in the log, and given to the checks (type
// 'Impact') as statistics "<name>:impact <k>:<quantity>" and "<name>:<quantity>".
#pragma once
#include <map>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "observers/HistoryObserver.hpp"
#include "observers/TransientObserver.hpp"

namespace choc {

void declareImpactStatistics(Teuchos::ParameterList& analysis);

struct Impact {
  double start = 0, end = 0, peakTime = 0, peakForce = 0, impulse = 0, velocity = 0, wear = 0;
  bool open = false;  // still in contact when the run ended
};

// The statistic names an 'Impact' check may ask for.
const std::vector<std::string>& impactQuantities();         // per impact
const std::vector<std::string>& impactSummaryQuantities();  // per interaction

// 'Impact Statistics', read once.
struct ImpactSettings {
  double forceThreshold = 0.0;   // an impact lasts while the normal force exceeds this [N]
  double minimumRestTime = 0.0;  // two contacts closer than this [s] are one impact
};
ImpactSettings readImpactSettings(const Teuchos::ParameterList& analysis);

class ImpactObserver : public TransientObserver {
 public:
  ImpactObserver(std::string csvPath, const ImpactSettings& settings, HistoryObserver& history,
                 const StateArchive* resume);
  void step(TransientView& view) override;
  void substep(TransientView& view, double time) override;
  void end(bool ok) override;
  void archive(StateArchive& a) const override;

 private:
  void sampleAt(TransientView& view, double time);
  struct Track {  // one interaction
    std::vector<Impact> impacts;
    bool active = false;
    bool havePrevious = false;
    bool rateKnown = true;  // rate0 is a rate, not a placeholder (first state of a differenced gap)
    double t0 = 0, f0 = 0, g0 = 0, rate0 = 0, p0 = 0;  // the previous state (p: wear power)
    double tm = 0, fm = 0;                             // the state before it
    double largest = 0;                                // largest force so far
    double gapScale = 0;                               // largest |gap| so far
  };
  void sample(Track& k, double t, const ImpactSample& s);
  // The phases of sample(): an impact under way or one that starts, the instants a contact
  // closes and opens (interpolated from the previous state), the state kept for the next.
  void continueImpact(Track& k, double t, const ImpactSample& s, bool on, double power, double tol);
  void startImpact(Track& k, double t, const ImpactSample& s, double power, double tol);
  double closingTime(const Track& k, double t, const ImpactSample& s, double tol) const;
  double openingTime(const Track& k, double t, const ImpactSample& s, double tol) const;
  static void remember(Track& k, double t, const ImpactSample& s, double power, bool rateKnown);
  std::map<std::string, double> statistics() const;
  void write(bool complete) const;
  std::string csvPath_;
  double threshold_, rest_;
  HistoryObserver& history_;
  std::vector<std::string> names_;
  std::vector<Track> tracks_;
};

}  // namespace choc
