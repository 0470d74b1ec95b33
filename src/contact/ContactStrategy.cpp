#include "contact/ContactStrategy.hpp"

#include <stdexcept>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

namespace choc {

void ContactStrategy::initialize(const Vector& u) {
  const std::vector<double> g = geometry_.gaps(u);
  ContactActiveSet& set = geometry_.activeSet();
  for (size_t s = 0; s < g.size(); ++s) {
    set.lambda[s] = 0.0;
    set.status[s] = geometry_.method().isActive(g[s], 0.0, false);
  }
  ++set.version;
  set.commit();
}

StatusUpdate ContactStrategy::updateStatus(const Vector& u) {
  const std::vector<double> g = geometry_.gaps(u);
  ContactActiveSet& set = geometry_.activeSet();
  const auto& constraints = geometry_.constraints();
  StatusUpdate up;
  int changedLocal = 0;
  for (size_t s = 0; s < g.size(); ++s) {
    const bool now = geometry_.method().isActive(g[s], set.lambda[s], set.status[s]);
    if (now == bool(set.status[s])) continue;
    changedLocal = 1;
    (now ? up.entered : up.left)++;
    const std::string name = "pair '" + geometry_.pair(constraints[s].geometry.pair).name + "'";
    if (up.where.find(name) == std::string::npos)
      up.where += (up.where.empty() ? "" : ", ") + name + " (node " +
                  std::to_string(constraints[s].geometry.slaveNode + 1) + ")";
    set.status[s] = now;
    if (!now) set.lambda[s] = 0.0;
  }
  // Every rank computed the same statuses from the same gaps; agree anyway.
  int changed = 0;
  Teuchos::reduceAll<int, int>(*geometry_.comm(), Teuchos::REDUCE_MAX, changedLocal, Teuchos::outArg(changed));
  up.changed = changed != 0;
  if (up.changed) ++set.version;
  up.active = set.activeCount();
  return up;
}

void ContactStrategy::addCouplings(const Map& dofMap, GO nU, std::map<LO, std::vector<GO>>& extra) const {
  const bool extended = extendsSystem();
  for (int s = 0; s < geometry_.numConstraints(); ++s) {
    const auto& terms = geometry_.constraints()[s].terms;
    for (const auto& term : terms) {
      const LO l = dofMap.getLocalElement(term.first);
      if (l == Teuchos::OrdinalTraits<LO>::invalid()) continue;
      for (const auto& t : terms) extra[l].push_back(t.first);
      if (extended) extra[l].push_back(nU + s);
    }
    if (extended && multiplierRow(s) >= 0)
      for (const auto& t : terms) extra[multiplierRow(s)].push_back(t.first);
  }
}

void ContactStrategy::addConstraintEntries(int s, const Map& dofMap, GO /*nU*/, std::vector<MatrixEntry>& out) const {
  const double k = geometry_.method().stiffness();
  if (!geometry_.activeSet().status[s] || k == 0.0) return;
  const auto& terms = geometry_.constraints()[s].terms;
  for (const auto& [di, bi] : terms) {
    if (dofMap.getLocalElement(di) == Teuchos::OrdinalTraits<LO>::invalid()) continue;
    for (const auto& [dj, bj] : terms) out.push_back({di, dj, k * bi * bj});
  }
}

std::vector<MatrixEntry> ContactStrategy::entries(const Map& dofMap, GO nU) const {
  std::vector<MatrixEntry> out;
  for (int s = 0; s < geometry_.numConstraints(); ++s) addConstraintEntries(s, dofMap, nU, out);
  if (geometry_.hasFriction())
    for (const MatrixEntry& e : geometry_.friction()->tangent(nU)) out.push_back(e);
  return out;
}

std::vector<char> ContactStrategy::statusKey() const {
  std::vector<char> key = geometry_.activeSet().status;
  const int g = geometry_.geometryVersion();  // the coefficients of curved obstacles' rows
  const char* b = reinterpret_cast<const char*>(&g);
  key.insert(key.end(), b, b + sizeof g);
  const std::vector<char> friction = geometry_.hasFriction() ? geometry_.friction()->key() : std::vector<char>{};
  key.insert(key.end(), friction.begin(), friction.end());
  return key;
}

void ContactStrategy::rightHandSide(const CrsMatrix& /*W*/, const Vector& r, const Vector& /*u*/, MultiVector& b) {
  auto rd = r.getData();
  auto bd = b.getDataNonConst(0);
  for (size_t i = 0; i < r.getLocalLength(); ++i) bd[i] = -rd[i];
}

void ContactStrategy::takeSolution(const CrsMatrix& /*W*/, const MultiVector& x, Vector& du) {
  auto xd = x.getData(0);
  auto d = du.getDataNonConst();
  for (size_t i = 0; i < du.getLocalLength(); ++i) d[i] = xd[i];
}

void ContactStrategy::addExplicitIncrement(const Vector&, const Vector&, const Vector&, double, double, Vector&,
                                           Vector&) {
  throw std::logic_error("this contact strategy has no explicit increments");
}

}  // namespace choc
