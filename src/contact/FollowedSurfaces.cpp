#include "contact/FollowedSurfaces.hpp"

#include <algorithm>

namespace choc {

FollowedSurfaces::FollowedSurfaces(const Mesh& mesh, const DofMap& dofs,
                                   const std::vector<PairDefinition>& pairs) {
  for (size_t p = 0; p < pairs.size(); ++p) {
    const PairDefinition& d = pairs[p];
    if (!d.followMotion || d.hasObstacle || !d.masterNodeSet.empty()) continue;
    std::vector<Face> master = facesOf(mesh, d.masterSideSet);
    for (const std::string& set : {d.masterSideSet, d.slaveSideSet})
      for (const Face& f : facesOf(mesh, set))
        for (int n : f.nodes) reference_[n] = mesh.coords[n];
    searches_[int(p)] = std::make_unique<SurfaceSearch>(std::move(master), d.searchDistance);
    if (d.mortar) slaveFaces_[int(p)] = facesOf(mesh, d.slaveSideSet);
  }
  for (const auto& [n, x] : reference_) {
    std::array<long long, 3>& nd = nodeDofs_[n];
    for (int c = 0; c < 3; ++c) {
      nd[c] = dofs.dof(n, c);
      if (nd[c] >= 0) dofs_.push_back(GO(nd[c]));
    }
  }
  std::sort(dofs_.begin(), dofs_.end());
  dofs_.erase(std::unique(dofs_.begin(), dofs_.end()), dofs_.end());
  values_.assign(dofs_.size(), 0.0);
}

double FollowedSurfaces::displacement(GO dof) const {
  const auto it = std::lower_bound(dofs_.begin(), dofs_.end(), dof);
  return it != dofs_.end() && *it == dof ? values_[it - dofs_.begin()] : 0.0;
}

Point3 FollowedSurfaces::position(int node) const {
  Point3 x = reference_.at(node);
  const std::array<long long, 3>& nd = nodeDofs_.at(node);
  for (int c = 0; c < 3; ++c)
    if (nd[c] >= 0) x[c] += displacement(GO(nd[c]));
  return x;
}

void FollowedSurfaces::place(const std::vector<double>& values, bool search) {
  values_ = values;
  if (!search) return;
  for (auto& [p, search] : searches_) search->moveTo([this](int n) { return position(n); });
}

std::vector<Face> FollowedSurfaces::slaveFaces(int pair) const {
  std::vector<Face> faces = slaveFaces_.at(pair);
  for (Face& f : faces)
    for (size_t a = 0; a < f.nodes.size(); ++a) f.x[a] = position(f.nodes[a]);
  return faces;
}

bool FollowedSurfaces::find(int pair, const Point3& x, SurfaceHit& hit, int current) const {
  const SurfaceSearch& s = *searches_.at(pair);
  return s.onFace(current, x, hit, kKeepFaceWiden) || s.closest(x, hit) || s.closest(x, hit, 0.05);
}

long long FollowedSurfaces::projections() const {
  long long n = 0;
  for (const auto& [p, s] : searches_) n += s->projections();
  return n;
}

}  // namespace choc
