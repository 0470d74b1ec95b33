// Closest-point search on a master surface in its current configuration. The faces' bounding
// boxes, widened by the search distance (the reach), are binned on a uniform grid whose cell is
// the largest widened box; a point's candidates are the faces binned in its cell, and any face
// within the reach of the point is among them. Each candidate is projected (Gauss-Newton on its
// parameters); among the faces that contain their projection, the nearest wins, provided its
// |gap| is within the reach. moveTo() places the faces' nodes and rebuilds the bins.
#pragma once
#include <functional>
#include <unordered_map>
#include <vector>

#include "contact/ContactFaces.hpp"

namespace choc {

struct SurfaceHit {
  int face = -1;              // index into faces()
  double xi = 0, eta = 0;     // the projection's parameters
  std::vector<double> N;      // the face's shape functions there
  Point3 normal{};            // outward unit normal there
  double gap = 0;             // (x - x_m) . n [m], positive when open
};

class SurfaceSearch {
 public:
  SurfaceSearch(std::vector<Face> faces, double reach);
  const std::vector<Face>& faces() const { return faces_; }
  // Every face node at position(node); rebuilds the bins.
  void moveTo(const std::function<Point3(int)>& position);
  // The nearest face whose closest point to x lies within its parameter domain widened by
  // `widen`, with |gap| <= reach; false when there is none.
  bool closest(const Point3& x, SurfaceHit& hit, double widen = 1e-8) const;
  // The closest point of x on face `face` alone, provided it lies within the face's parameter
  // domain widened by `widen` and |gap| <= reach; false otherwise.
  bool onFace(int face, const Point3& x, SurfaceHit& hit, double widen) const;
  // The faces whose widened boxes may overlap the box [lo, hi] (those binned in the cells it
  // covers), ascending.
  std::vector<int> candidates(const Point3& lo, const Point3& hi) const;
  long long projections() const { return projections_; }  // projections made so far (cost)

 private:
  long long key(const Point3& x) const;
  bool projectOn(int k, const Point3& x, double widen, SurfaceHit& hit, double& dist) const;
  void rebuild();
  std::vector<Face> faces_;
  double reach_ = 0, cell_ = 1;
  Point3 origin_{};
  std::unordered_map<long long, std::vector<int>> bins_;
  mutable long long projections_ = 0;
};

}  // namespace choc
