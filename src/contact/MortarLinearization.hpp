// The exact derivatives of the mortar gap (ContactPairing.hpp, pairMortar) with respect to the
// positions of the nodes it depends on, by forward automatic differentiation (core/Dual.hpp)
// of the same integration (MortarIntegration.hpp): the overlap's clipping, the projections,
// the dual basis and the slave normals all move with the nodes (Popp, Gee and Wall 2009 derive
// these by hand). For slave node j,
//     g_j = G_j / D_j,   G_j = int Phi_j nu_j . (x_s - x_m),   D_j = int Phi_j,
// nu_j the opposite of the normalised sum S_j of its faces' unit normals at j, so
//     dg_j = (dG_j|nu + dnu_j . Gv_j) / D_j - g_j dD_j / D_j,   Gv_j = int Phi_j (x_s - x_m),
//     dnu_j . Gv_j = w_j . dS_j,   w_j = -(Gv_j - (s_j . Gv_j) s_j) / |S_j|,  s_j = S_j / |S_j|.
// Where the faces touch (x_s = x_m) only dG_j|nu survives: the row nu_j (u_j - sum M_jm/D_j u_m).
#pragma once
#include <map>
#include <vector>

#include "contact/ContactFaces.hpp"

namespace choc {

// A derivative with respect to node positions: node -> d(.)/dx_node.
using NodeGradient = std::map<int, Point3>;

// What one slave face's overlap with one master face adds, per node a of the slave face:
// d(int Phi_a), d(int Phi_a nu_a . (x_s - x_m)) with nu_a held, and int Phi_a (x_s - x_m).
struct OverlapDerivatives {
  std::vector<NodeGradient> dD, dG;
  std::vector<Point3> Gv;
};

// nu: the contact normal of each node of the slave face. Empty vectors when the faces do not
// overlap (as mortarPoints).
OverlapDerivatives overlapDerivatives(const Face& slave, const Face& master, const std::vector<Point3>& nu,
                                      bool axisymmetric);

// Adds d(w . n_a)/dx over the nodes of face f to `out`, n_a = nodeNormal(f, a).
void addNormalDerivative(const Face& f, int a, const Point3& w, NodeGradient& out);

}  // namespace choc
