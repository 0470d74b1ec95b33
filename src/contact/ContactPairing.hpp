// Node-to-face pairing: each node of the slave side set is projected onto the faces of the
// master side set (QUAD4, QUAD8, TRI3 or TRI6: the faces of HEX8, HEX20, TET4, TET10; closest
// point by Gauss-Newton on the face's parameters); the face containing the projection with the
// smallest distance wins. The
// faces need not match node for node. Gives, per slave node, the master face nodes and their
// shape-function weights at the projection, the master's outward unit normal there, the
// reference gap g0 = (x_s - x_m) . n (positive when open) and the slave node's tributary
// area (integral of its shape function over the slave faces; for quadratic faces, whose corner
// integrals are zero or negative, the HRZ-lumped face mass: positive, same total). This is the
// pairing at t = 0; a pair with 'Search' = current is paired again before every step on the
// current configuration (ContactManager::beginStep, SurfaceSearch).
#pragma once
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/ContactFaces.hpp"
#include "contact/RigidObstacle.hpp"
#include "contact/SurfaceSearch.hpp"
#include "mesh/Mesh.hpp"

namespace choc {

struct PairDefinition {
  std::string name;           // e.g. "interface" (history columns '<name>:force', '<name>:gap')
  std::string masterSideSet;  // e.g. CNT_POU1
  std::string slaveSideSet;   // e.g. CNT_POU2
  double searchDistance = 0;  // largest |g0| accepted [m]
  bool followMotion = false;  // 'Search' = current: paired again before every step
  bool mortar = false;        // 'Discretization' = mortar (pairMortar)
  double friction = 0;        // Coulomb coefficient mu of the pair (0: frictionless)
  bool hasObstacle = false;   // the master is a rigid obstacle (masterSideSet empty)
  bool axisymmetric = false;  // slave areas of the whole ring: edge length weighted by 2 pi r
  RigidObstacle obstacle{};
  std::string slaveNodeSet;   // instead of a side set, against an obstacle: nodes without area
  // Node to node (a shock link's plane in the direct transient): each node of slaveNodeSet
  // with the nearest of masterNodeSet, gap = n . (x_s - x_m) - offset, n fixed.
  std::string masterNodeSet;
  Vec3 nodeNormal{0, 0, 0};
  double nodeOffset = 0;
};

struct SlaveProjection {
  int pair = 0;
  int slaveNode = -1;
  int masterFace = -1;              // index into the master side set (-1: an obstacle)
  std::vector<int> masterNodes;     // nodes of that face (Exodus side order)
  std::vector<double> weights;      // the face's shape functions at the projection
  double xi = 0, eta = 0;           // projection parameters in [-1, 1]^2
  Point3 normal{};                  // master outward unit normal at the projection
  double gap0 = 0;                  // reference gap [m]
  double area = 0;                  // slave tributary area [m^2]
  // Mortar: the gap's derivative by the positions of the nodes it depends on (node, dg/dx);
  // the constraint's row. Empty: the row is normal . (u_s - sum_i weights_i u_i).
  std::vector<std::pair<int, Point3>> gapGradient;
};

struct PairingResult {
  std::vector<SlaveProjection> projections;  // paired slave nodes, ascending node number
  std::vector<int> unpaired;                 // slave nodes projecting onto no master face
};

// Throws std::invalid_argument naming the side set when it is missing, not made of faces of
// solids (QUAD4, QUAD8, TRI3, TRI6), or when no slave node pairs.
PairingResult pairNodeToFace(const Mesh& mesh, const PairDefinition& def, int pairIndex);
// Every node of the slave side set against the pair's rigid obstacle at t = 0 (no master
// nodes; normal and gap from the obstacle's geometry). Throws std::invalid_argument as above,
// or when a node lies where the obstacle's normal is undefined.
PairingResult pairNodeToObstacle(const Mesh& mesh, const PairDefinition& def, int pairIndex);
// Mortar with dual multipliers (contact/MortarSegments.hpp): for each slave node j, over the
// overlaps of its slave faces with the master faces, D_j = int Phi_j, M_jm = int Phi_j N_m and
// G_j = int Phi_j nu_j . (x_s - x_m), nu_j the opposite of the slave surface's averaged normal
// at j. The projection's weights are M_jm / D_j (summing to 1, over every master node the
// dual function reaches), its normal nu_j, its gap G_j / D_j and its area D_j: the constraint
// g_j(u) = G_j / D_j + nu_j . (u_j - sum_m M_jm / D_j u_m), whose multiplier is the node's force
// D_j times the dual pressure. Exact (biorthogonal) where the master covers the node's slave
// faces; a node whose covered D_j is below a quarter of int N_j (a slave surface overhanging
// the master) is left unpaired. Throws std::invalid_argument for quadratic slave faces, or when
// no slave face overlaps a master face within the search distance.
PairingResult pairMortar(const Mesh& mesh, const PairDefinition& def, int pairIndex);
// The same on given slave faces and master faces binned for search (a followed pair's current
// configuration); throws nothing when no node pairs. A followed pair keeps its unpaired nodes
// as projections without master nodes.
PairingResult mortarPairing(const std::vector<Face>& slave, const SurfaceSearch& master,
                            const PairDefinition& def, int pairIndex);
// Each slave node with the nearest master node (one to one; std::invalid_argument otherwise).
PairingResult pairNodeToNode(const Mesh& mesh, const PairDefinition& def, int pairIndex);

}  // namespace choc
