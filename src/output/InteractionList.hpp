// Several sets of interactions reported as one (a direct transient with contact pairs and
// shock links): their columns, variables and impacts one after the other, in the order given.
#pragma once
#include <vector>

#include "output/InteractionOutput.hpp"

namespace choc {

class InteractionList : public InteractionOutput {
 public:
  // The parts (not owned; null entries are skipped).
  explicit InteractionList(std::vector<const InteractionOutput*> parts);
  bool empty() const { return parts_.empty(); }
  // The only part when there is one (no copying), else this list; null when there is none.
  const InteractionOutput* simplest() const;

  std::vector<std::string> historyColumns() const override;
  std::vector<double> historyValues() const override;
  std::vector<std::string> nodalFieldNames() const override;
  std::vector<std::vector<double>> nodalFields() const override;
  std::vector<std::string> globalNames() const override;
  std::vector<double> globalValues() const override;
  std::string progressNote() const override;
  std::vector<std::string> impactNames() const override;
  std::vector<ImpactSample> impactSamples() const override;

 private:
  std::vector<const InteractionOutput*> parts_;
};

}  // namespace choc
