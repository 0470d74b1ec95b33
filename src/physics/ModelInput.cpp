#include "physics/ModelInput.hpp"

#include "input/ParameterSpec.hpp"
#include "materials/MaterialLaw.hpp"

namespace choc {

namespace {

void declareMeshParameters(ParameterList& top) {
  ParameterList& mesh = declareSublist(top, "Mesh", "the mesh");
  declareRequiredString(mesh, "File",
                        "mesh file, relative to the input file: Exodus II (see 'choc mesh') or "
                        "gmsh .msh (physical groups: blocks, side sets, node sets)");
  declareBool(mesh, "Merge Coincident Nodes", false,
              "join nodes of different elements that lie at the same place (within 1e-6 of the "
              "shortest element edge) but are not shared: parts meshed apart that should be one "
              "body. Without it such nodes are reported once on the log and left unconnected "
              "(right for contact surfaces that touch at the start)");
}

void declareMaterialParameters(ParameterList& model) {
  ParameterList& mat = declareNamedSublists(model, "Materials", "isotropic materials, by name");
  declareMaterialLaws(mat);
}

void declareSectionParameters(ParameterList& blk) {
  ParameterList& sec = declareSublist(blk, "Section", "beam section (BEAM2 blocks only)");
  declareDouble(sec, "Square Side", 0.0,
                "side of a square section; when > 0 it sets Area, Iy, Iz and the torsion "
                "constant (0.1406 a^4)",
                Range::nonNegative());
  declareDouble(sec, "Area", 0.0, "section area [m^2]", Range::nonNegative());
  declareDouble(sec, "Iy", 0.0, "second moment about the local y axis [m^4]", Range::nonNegative());
  declareDouble(sec, "Iz", 0.0, "second moment about the local z axis [m^4]", Range::nonNegative());
  declareDouble(sec, "Torsion Constant", 0.0, "Saint-Venant torsion constant J [m^4]",
                Range::nonNegative());
  declareDouble(sec, "Shear Coefficient", 5.0 / 6.0, "Timoshenko shear coefficient",
                {0.0, 1.0, true, false});
  declareString(sec, "Orientation", "0 0 0",
                "local y axis direction 'x y z'; '0 0 0' chooses global y (global z for beams "
                "along y)");
}

void declareBlockParameters(ParameterList& model) {
  ParameterList& blk = declareNamedSublists(model, "Blocks",
                                            "one entry per element block of the mesh, by name");
  declareRequiredString(blk, "Material", "name of an entry of Model/Materials");
  declareChoice(blk, "Mass", "consistent", {"consistent", "lumped"}, "mass matrix of the block");
  declareBool(blk, "Rigid", false,
              "true: the block moves as one rigid body (its mass, centre and inertia from its elements "
              "and density; its elements carry no stress; the forces on its nodes move it): explicit "
              "transients ('Scheme' = 'central differences'): in 3D, in plane strain (moving in its plane) "
              "or axisymmetric (sliding along the axis); nodes it shares with a deformable "
              "block (of solids) move with it, their mass from that block added to it; its nodes all "
              "free, no initial displacement (docs/theory/rigid-bodies.md; issue 74)");
  declareString(blk, "Held", "",
                "a rigid block's held motion: the components of its centre's velocity kept at 'Held "
                "Velocity' (some of DX DY DZ) and its rotation stopped (DRX DRY DRZ, together), from the "
                "start whatever the initial velocities; the hold's force and moment are the history's "
                "<block>:reactionX..MZ and its work goes to the energy balance. '' (the default): a free body");
  declareString(blk, "Held Velocity", "0 0 0",
                "the velocity [m/s] 'vx vy vz' at which the held components of a rigid block's centre "
                "move (0 along the components not held)");
  declareChoice(blk, "Strain", "small", {"small", "finite"},
                "kinematics of the block's solids: 'small' (linear strain, an assembled stiffness: "
                "a linear elastic material) or 'finite' (total Lagrangian: deformation gradient F, "
                "Green-Lagrange strain, second Piola-Kirchhoff stress; a hyperelastic material; "
                "direct transients only). Large rotations need 'finite': a small-strain body turned "
                "through a large angle is stressed by the rotation itself. Beams are small-strain");
  declareChoice(blk, "Formulation", "standard", {"standard", "F-bar", "one-point"},
                "the element formulation: 'standard' (full integration), or 'F-bar' for blocks in finite "
                "strain of HEX8, HEX20, TET10, QUAD4, QUAD8 or TRI6 elements (each element's volume change "
                "taken as its mean, so that plastic or nearly incompressible flow does not lock HEX8, "
                "QUAD4 or TET10; explicit and implicit, with its consistent tangent). TET4 and TRI3 "
                "have one point and lock: mesh plastic parts with TET10 or TRI6. 'one-point': HEX8 in 3D "
                "or QUAD4 in plane strain integrated at one point (the mean gradient: one material "
                "update per element, no locking) with hourglass stiffness ('Hourglass Coefficient'); "
                "blocks in finite strain or plastic");
  declareDouble(blk, "Hourglass Coefficient", 0.001,
                "'one-point' elements: the hourglass stiffness as a fraction of the fully integrated "
                "element's in its bending mode (lambda + 2 mu terms); its energy is part of the "
                "element's, and so of the energy balance (history column energy:hourglass). The "
                "default is the value measured closest to F-bar on the plastic Taylor bar; larger "
                "values stiffen plastic flow (docs/verification/taylor-bar.md)",
                Range{0.0, 1.0, true, false});
  declareSectionParameters(blk);
}

void declareDirichletParameters(ParameterList& model) {
  ParameterList& dir = declareNamedSublists(model, "Dirichlet",
                                            "homogeneous supports: components fixed to zero");
  declareRequiredString(dir, "Node Set", "node set of the mesh");
  declareRequiredString(dir, "Components", "fixed components, e.g. 'DX' or 'DX DY DZ' or 'all'");
}

void declareSpringParameters(ParameterList& model) {
  ParameterList& spr = declareNamedSublists(model, "Springs",
                                            "linear springs from each node of a node set to a fixed "
                                            "point (grounded), by name; in the stiffness of every analysis");
  declareRequiredString(spr, "Node Set", "node set of the mesh: one spring per node");
  declareRequiredString(spr, "Direction", "the springs' axis 'x y z' (normalised; e.g. '1 0 0')");
  declareRequiredDouble(spr, "Stiffness", "stiffness of each node's spring [N/m]", Range::positive());
}

void declareCouplingParameters(ParameterList& model) {
  ParameterList& cpl = declareNamedSublists(model, "Couplings",
                                            "couplings of a node set to its centroid, by name: the 'Coupling "
                                            "Loads' of a direct transient act on them");
  declareChoice(cpl, "Type", "distributing", {"distributing", "kinematic"},
                "'distributing' (RBE3-like): a force and moment spread over the nodes by equal weights in "
                "their current positions, without stiffening them; 'kinematic' (RBE2-like): the nodes move "
                "as one rigid body (their lumped mass its inertia; explicit 3D transients, as rigid blocks)");
  declareRequiredString(cpl, "Node Set", "the coupled nodes (each with every component free)");
  declareString(cpl, "Held", "", "a kinematic coupling's held motion, as a rigid block's 'Held'");
  declareString(cpl, "Held Velocity", "0 0 0", "a kinematic coupling's held speed, as a rigid block's 'Held Velocity'");
}

void declareModelParameters(ParameterList& top) {
  ParameterList& model = declareSublist(top, "Model", "materials, element blocks, supports");
  declareChoice(model, "Kinematics", "3D", {"3D", "plane strain", "axisymmetric"},
                "3D: solids (TET4, TET10, HEX8, HEX20) and beams (BEAM2) in space; plane strain: "
                "a unit-thickness section in the x-y plane (TRI3, TRI6, QUAD4, QUAD8; DX, DY); "
                "axisymmetric: the half-plane x = r >= 0, y = the axis (TRI3...QUAD8; DX radial, "
                "DY axial; masses, forces and energies of the whole 360-degree body)");
  declareString(model, "Active Components", "all",
                "nodal components that may be unknowns; every other component is fixed to zero "
                "on every node (e.g. 'DX' for an axial 1D model, 'DZ' for the 3D bars): names DX "
                "DY DZ DRX DRY DRZ, or 'all', 'translations', 'rotations'");
  declareChoice(model, "Partition", "rcb", {"rcb", "numbering"},
                "how the nodes are shared among MPI ranks: rcb: Zoltan2 recursive coordinate "
                "bisection weighted by unknowns (compact regions whatever the numbering); "
                "numbering: contiguous ranges of the mesh's node numbering");
  declareMaterialParameters(model);
  declareBlockParameters(model);
  declareDirichletParameters(model);
  declareSpringParameters(model);
  declareCouplingParameters(model);
}

}  // namespace

Teuchos::ParameterList topLevelParameters() {
  Teuchos::ParameterList top;
  declareString(top, "Title", "", "one line describing the input, printed in the log");
  declareMeshParameters(top);
  declareModelParameters(top);
  declareOpenSublist(top, "Analyses",
                     "the analyses to run, in order; each sublist has a 'Type' (see below)");
  return top;
}

}  // namespace choc
