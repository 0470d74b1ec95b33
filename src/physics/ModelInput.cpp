#include "physics/ModelInput.hpp"

#include "input/ParameterSpec.hpp"

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

// sigma_y = (A + B alpha^n)(1 + C ln(max(rate / rate_0, 1)))(1 - T*^m) (FlowStress.hpp).
void declareJohnsonCookParameters(ParameterList& mat) {
  declareDouble(mat, "Johnson-Cook A", 0.0, "'Johnson-Cook': A, the initial yield stress [Pa] (required, > 0)",
                Range::nonNegative());
  declareDouble(mat, "Johnson-Cook B", 0.0, "'Johnson-Cook': B, the hardening coefficient [Pa]", Range::nonNegative());
  declareDouble(mat, "Johnson-Cook n", 1.0, "'Johnson-Cook': n, the hardening exponent, in (0, 1]",
                Range::positive());
  declareDouble(mat, "Johnson-Cook C", 0.0, "'Johnson-Cook': C, the strain-rate coefficient [-]",
                Range::nonNegative());
  declareDouble(mat, "Reference Strain Rate", 1.0,
                "'Johnson-Cook': the plastic strain rate below which the flow stress is the quasi-static "
                "one [1/s]",
                Range::positive());
  declareDouble(mat, "Johnson-Cook m", 1.0, "'Johnson-Cook': m, the thermal-softening exponent [-]",
                Range::positive());
  declareDouble(mat, "Reference Temperature", 20.0,
                "'Johnson-Cook': T_0, the temperature of the quasi-static flow stress (any temperature "
                "unit, the same for the three temperatures)");
  declareDouble(mat, "Melting Temperature", 0.0,
                "'Johnson-Cook': T_m, where the flow stress vanishes (required, above T_0)");
  declareDouble(mat, "Initial Temperature", 20.0, "'Johnson-Cook': the temperature at the start (below T_m)");
  declareDouble(mat, "Specific Heat", 0.0,
                "'Johnson-Cook': c [J/(kg K)] (required with heating): the plastic work's heat raises the "
                "temperature by chi dW_p / (rho c)",
                Range::nonNegative());
  declareDouble(mat, "Taylor-Quinney Coefficient", 0.9,
                "'Johnson-Cook': chi, the share of the plastic work that becomes heat (0: isothermal)",
                Range::closed(0.0, 1.0));
}

// eps_f = (D1 + D2 exp(D3 sigma*)) (1 + D4 ln rate*) (1 + D5 T*), D = sum d alpha / eps_f
// (JohnsonCookDamage.hpp).
void declareDamageParameters(ParameterList& mat) {
  declareChoice(mat, "Damage", "none", {"none", "Johnson-Cook"},
                "'Johnson-Cook' materials: 'Johnson-Cook' accumulates Johnson and Cook's damage D = sum "
                "d alpha / eps_f, eps_f = (D1 + D2 exp(D3 sigma*)) (1 + D4 ln rate*) (1 + D5 T*), sigma* the "
                "stress triaxiality, rate* and T* the flow stress's; reported (the DAMAGE element variable, "
                "the log when D first reaches 1), not coupled: no softening, no element erosion");
  const char* terms[5][2] = {{"D1", "the failure strain's constant term [-] (>= 0)"},
                             {"D2", "the triaxiality term's factor [-] (>= 0; D1 + D2 > 0)"},
                             {"D3", "the triaxiality exponent's factor [-] (usually negative)"},
                             {"D4", "the strain-rate coefficient [-] (>= 0)"},
                             {"D5", "the temperature coefficient [-] (>= 0)"}};
  for (const auto& t : terms)  // D3 any sign; the others >= 0 (JohnsonCookDamage.hpp)
    declareDouble(mat, std::string("Johnson-Cook ") + t[0], 0.0, std::string("'Damage' = 'Johnson-Cook': ") + t[1],
                  std::string(t[0]) == "D3" ? Range::any() : Range::nonNegative());
}

void declareMaterialParameters(ParameterList& model) {
  ParameterList& mat = declareNamedSublists(model, "Materials", "isotropic elastic materials, by name");
  declareRequiredDouble(mat, "Young's Modulus", "E [Pa]", Range::positive());
  declareDouble(mat, "Poisson's Ratio", 0.0, "nu [-]", {-1.0, 0.5, true, true});
  declareRequiredDouble(mat, "Density", "rho [kg/m^3]", Range::positive());
  declareChoice(mat, "Model", "linear elastic",
                {"linear elastic", "Saint Venant-Kirchhoff", "neo-Hookean", "J2 plasticity", "Johnson-Cook"},
                "the material law: 'linear elastic' (small strain: blocks with 'Strain' = 'small'); "
                "in finite strain ('Strain' = 'finite'), 'Saint Venant-Kirchhoff' (S = lambda tr(E) I "
                "+ 2 mu E, E the Green-Lagrange strain: exact for large rotations, for moderate "
                "strains) or compressible 'neo-Hookean' (W = mu/2 (I1 - 3) - mu ln J + lambda/2 "
                "(ln J)^2); mu and lambda are the Lame constants of E and nu. 'J2 plasticity' (von "
                "Mises, isotropic hardening: linear or a flow curve; direct transients) and 'Johnson-Cook' "
                "(J2 with the Johnson-Cook flow stress, its strain rate and adiabatic heating) on either "
                "kinematics: additive split in small strain, multiplicative with Hencky elasticity in "
                "finite strain");
  declareDouble(mat, "Yield Stress", 0.0,
                "'J2 plasticity': the initial yield stress sigma_y [Pa] (required, > 0, with that model)",
                Range::nonNegative());
  declareDouble(mat, "Hardening Modulus", 0.0,
                "'J2 plasticity': the linear isotropic hardening H = d sigma_y / d alpha [Pa], alpha "
                "the equivalent plastic strain (0: perfectly plastic)",
                Range::nonNegative());
  declareDouble(mat, "Kinematic Hardening Modulus", 0.0,
                "'J2 plasticity' and 'Johnson-Cook' on small-strain blocks: linear kinematic hardening "
                "(Prager-Ziegler), the yield surface's centre moving with the flow, d beta = 2/3 H_k d eps_p "
                "[Pa] (0: none; the Bauschinger effect of cyclic loading); refused on finite-strain blocks",
                Range::nonNegative());
  declareString(mat, "Flow Curve", "",
                "'J2 plasticity': the flow stress as a piecewise-linear curve 'alpha_0 sigma_0 alpha_1 "
                "sigma_1 ...' of equivalent plastic strain [-] and stress [Pa] (alpha_0 = 0, alpha "
                "increasing, sigma non-decreasing, constant beyond the last point), instead of 'Yield "
                "Stress' and 'Hardening Modulus'");
  declareJohnsonCookParameters(mat);
  declareDamageParameters(mat);
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
