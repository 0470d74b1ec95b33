#include "contact/SurfaceSearch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace choc {

namespace {

struct Box {
  Point3 lo{}, hi{};
};

Box widenedBox(const Face& f, double reach) {
  Box b{f.x[0], f.x[0]};
  for (const Point3& p : f.x)
    for (int d = 0; d < 3; ++d) {
      b.lo[d] = std::min(b.lo[d], p[d]);
      b.hi[d] = std::max(b.hi[d], p[d]);
    }
  for (int d = 0; d < 3; ++d) {
    b.lo[d] -= reach;
    b.hi[d] += reach;
  }
  return b;
}

constexpr long long kSpan = 1LL << 20;  // cells per direction the key can tell apart

long long packCell(long long i, long long j, long long k) {
  auto wrap = [](long long c) { return ((c % kSpan) + kSpan) % kSpan; };
  return (wrap(i) * kSpan + wrap(j)) * kSpan + wrap(k);
}

}  // namespace

SurfaceSearch::SurfaceSearch(std::vector<Face> faces, double reach)
    : faces_(std::move(faces)), reach_(reach) {
  rebuild();
}

void SurfaceSearch::moveTo(const std::function<Point3(int)>& position) {
  for (Face& f : faces_)
    for (size_t a = 0; a < f.nodes.size(); ++a) f.x[a] = position(f.nodes[a]);
  rebuild();
}

long long SurfaceSearch::key(const Point3& x) const {
  long long c[3];
  for (int d = 0; d < 3; ++d) c[d] = static_cast<long long>(std::floor((x[d] - origin_[d]) / cell_));
  return packCell(c[0], c[1], c[2]);
}

void SurfaceSearch::rebuild() {
  bins_.clear();
  std::vector<Box> boxes;
  cell_ = 0.0;
  for (const Face& f : faces_) {
    boxes.push_back(widenedBox(f, reach_));
    for (int d = 0; d < 3; ++d) cell_ = std::max(cell_, boxes.back().hi[d] - boxes.back().lo[d]);
  }
  if (!(cell_ > 0)) cell_ = 1.0;
  origin_ = boxes.empty() ? Point3{0, 0, 0} : boxes[0].lo;
  for (size_t k = 0; k < boxes.size(); ++k) {
    long long lo[3], hi[3];
    for (int d = 0; d < 3; ++d) {
      lo[d] = static_cast<long long>(std::floor((boxes[k].lo[d] - origin_[d]) / cell_));
      hi[d] = static_cast<long long>(std::floor((boxes[k].hi[d] - origin_[d]) / cell_));
    }
    for (long long i = lo[0]; i <= hi[0]; ++i)
      for (long long j = lo[1]; j <= hi[1]; ++j)
        for (long long l = lo[2]; l <= hi[2]; ++l) {
          std::vector<int>& bin = bins_[packCell(i, j, l)];
          if (bin.empty() || bin.back() != int(k)) bin.push_back(int(k));
        }
  }
}

std::vector<int> SurfaceSearch::candidates(const Point3& lo, const Point3& hi) const {
  long long a[3], b[3];
  for (int d = 0; d < 3; ++d) {
    a[d] = static_cast<long long>(std::floor((lo[d] - origin_[d]) / cell_));
    b[d] = static_cast<long long>(std::floor((hi[d] - origin_[d]) / cell_));
  }
  std::vector<int> out;
  for (long long i = a[0]; i <= b[0]; ++i)
    for (long long j = a[1]; j <= b[1]; ++j)
      for (long long l = a[2]; l <= b[2]; ++l)
        if (const auto it = bins_.find(packCell(i, j, l)); it != bins_.end())
          out.insert(out.end(), it->second.begin(), it->second.end());
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

bool SurfaceSearch::projectOn(int k, const Point3& x, double widen, SurfaceHit& hit, double& dist) const {
  const Face& f = faces_[k];
  double xi, eta;
  ++projections_;
  if (!projectOnFace(f, x, xi, eta) || !insideFace(f, xi, eta, widen)) return false;
  const FacePoint q = evaluateFace(f, xi, eta);
  const Point3 d = x - q.x;
  dist = std::sqrt(dot(d, d));
  Point3 n = cross(q.dxi, q.deta);
  const double len = std::sqrt(dot(n, n));
  for (double& v : n) v /= len;
  const double g = dot(d, n);
  if (std::abs(g) > reach_) return false;
  hit.face = k;
  hit.xi = xi;
  hit.eta = eta;
  hit.N = q.N;
  hit.normal = n;
  hit.gap = g;
  return true;
}

bool SurfaceSearch::closest(const Point3& x, SurfaceHit& hit, double widen) const {
  const auto it = bins_.find(key(x));
  if (it == bins_.end()) return false;
  double bestDist = std::numeric_limits<double>::infinity();
  bool found = false;
  for (int k : it->second) {  // ascending face index: ties go to the first face
    SurfaceHit h;
    double dist = 0.0;
    if (!projectOn(k, x, widen, h, dist) || !(dist < bestDist - 1e-15)) continue;
    bestDist = dist;
    found = true;
    hit = std::move(h);
  }
  return found;
}

bool SurfaceSearch::onFace(int face, const Point3& x, SurfaceHit& hit, double widen) const {
  if (face < 0 || face >= int(faces_.size())) return false;
  double dist = 0.0;
  return projectOn(face, x, widen, hit, dist);
}

}  // namespace choc
