// The surfaces of the contact pairs with 'Search' = current: for each such pair its master
// faces (a SurfaceSearch), and the reference positions and DOFs of every node of its master and
// slave side sets. place() takes the displacements of those DOFs (gathered on every rank) and
// moves the faces to the current configuration; find() then projects a slave node's current
// position onto its pair's master surface: the face it is paired with while the projection
// stays within it (widened by kKeepFaceWiden), else the closest face containing the projection,
// or, when the projection falls in no face (a node over the kink between two faces of a convex
// surface), the nearest face whose domain widened by 0.05 in its parameters contains it.
// A mortar pair is integrated again on the current faces (slaveFaces, masterSearch).
#pragma once
#include <map>
#include <memory>
#include <vector>

#include "contact/ContactPairing.hpp"
#include "contact/SurfaceSearch.hpp"
#include "core/TpetraTypes.hpp"
#include "fem/DofMap.hpp"

namespace choc {

class FollowedSurfaces {
 public:
  FollowedSurfaces(const Mesh& mesh, const DofMap& dofs, const std::vector<PairDefinition>& pairs);
  bool empty() const { return dofs_.empty(); }
  bool follows(int pair) const { return searches_.count(pair) > 0; }
  const std::vector<GO>& dofs() const { return dofs_; }  // sorted, distinct
  // values[k]: the displacement of dofs()[k]; moves the master faces (and rebuilds their bins)
  // only when `search` (a slip update needs positions, not a search).
  void place(const std::vector<double>& values, bool search);
  Point3 position(int node) const;          // current (after place), else reference
  double displacement(GO dof) const;        // of the last place()
  // current: the face the node is paired with (-1: none), kept while the projection stays
  // within its domain widened by kKeepFaceWiden: a node over the edge between two faces would
  // otherwise change face whenever round-off or a tangential motion of 1e-5 of a face moves it
  // across (two meshed spheres whose nodes face each other: a new contact graph, and a new
  // factorisation, at every step).
  static constexpr double kKeepFaceWiden = 1e-3;
  bool find(int pair, const Point3& x, SurfaceHit& hit, int current = -1) const;
  // Mortar pairs: their slave faces at the current positions, and their master faces (moved
  // and binned by the last place with a search).
  bool mortar(int pair) const { return slaveFaces_.count(pair) > 0; }
  std::vector<Face> slaveFaces(int pair) const;
  const SurfaceSearch& masterSearch(int pair) const { return *searches_.at(pair); }
  const Face& face(int pair, int f) const { return searches_.at(pair)->faces()[f]; }
  long long projections() const;

 private:
  std::map<int, std::unique_ptr<SurfaceSearch>> searches_;  // by pair index
  std::map<int, std::vector<Face>> slaveFaces_;              // mortar pairs: reference slave faces
  std::map<int, Point3> reference_;                         // node -> reference position
  std::map<int, std::array<long long, 3>> nodeDofs_;        // node -> DOF per component (-1)
  std::vector<GO> dofs_;
  std::vector<double> values_;
};

}  // namespace choc
