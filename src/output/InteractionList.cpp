#include "output/InteractionList.hpp"

namespace choc {

namespace {

// The parts' lists f(part) one after the other.
template <class T, class F>
std::vector<T> joined(const std::vector<const InteractionOutput*>& parts, F f) {
  std::vector<T> out;
  for (const InteractionOutput* p : parts) {
    const std::vector<T> v = f(*p);
    out.insert(out.end(), v.begin(), v.end());
  }
  return out;
}

}  // namespace

InteractionList::InteractionList(std::vector<const InteractionOutput*> parts) {
  for (const InteractionOutput* p : parts)
    if (p) parts_.push_back(p);
}

const InteractionOutput* InteractionList::simplest() const {
  if (parts_.empty()) return nullptr;
  return parts_.size() == 1 ? parts_[0] : this;
}

std::vector<std::string> InteractionList::historyColumns() const {
  return joined<std::string>(parts_, [](const InteractionOutput& p) { return p.historyColumns(); });
}
std::vector<double> InteractionList::historyValues() const {
  return joined<double>(parts_, [](const InteractionOutput& p) { return p.historyValues(); });
}
std::vector<std::string> InteractionList::nodalFieldNames() const {
  return joined<std::string>(parts_, [](const InteractionOutput& p) { return p.nodalFieldNames(); });
}
std::vector<std::vector<double>> InteractionList::nodalFields() const {
  return joined<std::vector<double>>(parts_, [](const InteractionOutput& p) { return p.nodalFields(); });
}
std::vector<std::string> InteractionList::globalNames() const {
  return joined<std::string>(parts_, [](const InteractionOutput& p) { return p.globalNames(); });
}
std::vector<double> InteractionList::globalValues() const {
  return joined<double>(parts_, [](const InteractionOutput& p) { return p.globalValues(); });
}
std::vector<std::string> InteractionList::impactNames() const {
  return joined<std::string>(parts_, [](const InteractionOutput& p) { return p.impactNames(); });
}
std::vector<ImpactSample> InteractionList::impactSamples() const {
  return joined<ImpactSample>(parts_, [](const InteractionOutput& p) { return p.impactSamples(); });
}

std::string InteractionList::progressNote() const {
  std::string s;
  for (const InteractionOutput* p : parts_) s += (s.empty() ? "" : "; ") + p->progressNote();
  return s;
}

}  // namespace choc
