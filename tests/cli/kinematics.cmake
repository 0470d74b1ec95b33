# Plane strain and axisymmetry against 3D: SDNL111's bar wave on QUAD4 sections,
# plane strain and axisymmetric, and on HEX8 bars, lateral motion blocked. The three discrete
# systems reduce to the same 1D one (tensor-product shape functions; the section integrals of
# stiffness and mass factor out alike, r-weighted in axisymmetry), so their histories of A must
# agree to round-off: 1e-9 of the peak displacement. Meshes by gmsh (meshes/*.geo).
add_test(NAME cli.wave_2d_equals_3d
         COMMAND /usr/bin/python3 ${CMAKE_SOURCE_DIR}/tools/study/bar_convergence.py
                 --build ${CMAKE_BINARY_DIR} --out ${CMAKE_CURRENT_BINARY_DIR}/work/wave_2d_equals_3d --levels 25
                 --elements HEX8 QUAD4 --exact-reduction-tolerance 1e-9)
set_tests_properties(cli.wave_2d_equals_3d PROPERTIES TIMEOUT 120 LABELS cli)

# Initial Conditions with Field = 'Rigid Velocity' (V + omega x (x - Centre)): a free cube's
# kinetic energy and corner velocity at t = 0 exact to 1e-12, the same motion written about
# another point equal to 1e-12, 2 ranks equal to 1e-10, and its input errors
# (scripts/rigid_velocity.py).
choc_cli_script(rigid_velocity 120)

# Finite strain: a free cube spun about its axis turns ten times rigidly but for its
# centrifugal stretch, by central differences and by average acceleration, on 1 and 2 ranks,
# turned as a whole and with its nodes numbered backwards;
# the small-strain model fails the same scene (scripts/tumbling_block.py).
choc_cli_script(tumbling_block 300)

# SDNL111 C's 3D bars in finite strain (Saint Venant-Kirchhoff) give the small-strain motion of
# A to the order of the strain, 1/5064 (scripts/finite_small_sdnl111c.py).
choc_cli_script(finite_small_sdnl111c 300)

# Finite strain: a thick-walled neo-Hookean sphere inflated until its inner radius is 1.9 A,
# axisymmetric (QUAD8, 2, 4, 8 across the wall) and 3D (TET10 octant, two sizes), against the
# radial equilibrium of the same material (tools/oracles/thick_sphere.py, itself checked against
# the incompressible closed form): the errors fall at quadratic order and the finest mesh's is
# within twice its Richardson estimate (scripts/thick_sphere.py).
choc_cli_script(thick_sphere 450)

# Finite strain: a cantilever modelled with solids (L / h = 50, neo-Hookean, nu = 0) bent through
# 101 and 122 degrees by a dead end force at 135 degrees, HEX20 (8, 16, 32 along) and TET10 (16,
# 32, 64), against Reissner's geometrically exact beam (tools/oracles/elastica.py, itself checked
# against the elastica's closed forms): the tip converges at order >= 2 and the finest mesh is
# within twice its Richardson estimate plus beam theory's 2 (h/L)^2 (scripts/elastica.py).
choc_cli_script(elastica 400)
# The end-moment elastica (BENCHMARKS section 16): the same beam rolled into a ring by a pure end
# moment through a distributing coupling (input/elastica_moment.xml, 32 and 64 HEX20 along): the tip
# on the circle of radius EI/M within 0.5 % of L at every step, 1 and 2 ranks alike.
choc_cli_script(elastica_moment 300)

# Plasticity: a thick-walled elastic-perfectly plastic sphere (J2, small strain) pressurized until
# the plastic front reaches 0.8 of the wall, axisymmetric (QUAD8, 2 to 16 across) and 3D (TET10
# octant, two sizes), against Hill's closed form of the outer radius' motion
# (tools/oracles/plastic_sphere.py): the errors fall with the mesh, the finest is within twice its
# Richardson estimate, the energy balance closes with the plastic work, 2 ranks equal 1
# (scripts/plastic_sphere.py).
choc_cli_script(plastic_sphere 300)

# Plasticity in finite strain: the Taylor bar (copper, J2 with linear hardening, 227 m/s on a
# rigid wall, axisymmetric QUAD4 by central differences): no energy created, F-bar against the
# locking standard QUAD4, the final length and radius within the published values widened by the
# mesh's own error, 2 ranks equal 1; the face held on the wall, the radius extrapolated within
# 0.5 % of 7.22 mm (scripts/taylor_bar.py; 111 s alone).
choc_cli_script(taylor_bar 600)
# The Johnson-Cook Taylor bar (42CrMo4 at 287 m/s, adiabatic heating): length, diameter, largest
# plastic strain and temperature against the published values widened by the mesh's own error,
# the temperature as the plastic work's heat, 2 ranks equal 1 (scripts/taylor_bar_johnson_cook.py).
choc_cli_script(taylor_bar_johnson_cook 300)
# The Johnson-Cook bar in 3D (the quarter, HEX8 F-bar, n = 2 and 4): length, diameter, largest
# plastic strain and temperature on n = 4 against the published 3D values widened by the mesh's own
# error, the quarter against the axisymmetric bar of the same element size, no energy created, 2
# ranks equal 1 (scripts/taylor_bar_johnson_cook_3d.py).
choc_cli_script(taylor_bar_johnson_cook_3d 400)
# Johnson-Cook damage on the axisymmetric bar (5 x 51): not coupled (the histories equal the run without,
# byte for byte), a constant failure strain's D = alpha / D1 on every element, the log's line when
# D first reaches 1, 0 <= D <= alpha / D1 with 4340 steel's fit, 2 ranks equal 1
# (scripts/johnson_cook_damage.py).
choc_cli_script(johnson_cook_damage 120)
# F-bar in the implicit schemes (its consistent tangent): the Taylor bar held on the wall, its first
# 2 us by average acceleration against central differences within the implicit run's Richardson
# estimate, at most 4 Newton corrections per step, the standard QUAD4 locking, 2 ranks equal 1
# (scripts/fbar_implicit.py).
choc_cli_script(fbar_implicit 120)
# Plastic tetrahedra: TET4 locks on the Taylor bar (below the published radius by more than its
# mesh error); TET10 F-bar (P2/P0) by average acceleration against central differences, at most
# 4 Newton corrections per step, 2 ranks equal 1 (scripts/fbar_tets.py).
choc_cli_script(fbar_tets 300)
# The Taylor bar by HHT (alpha = -0.3, 0.1 us, F-bar's consistent tangent, the blocks' own mass): no
# energy created, the final radius and length within 0.5 % of central differences on the same mesh
# (scripts/taylor_bar_implicit.py); its first 4 us on 2 ranks and renumbered equal 1 rank.
choc_cli_script(taylor_bar_implicit 300)
# The 3D Taylor quarter by HHT with the contact velocity update (the bar's own lumped mass): no
# energy created (no step's rise above 1e-4 E0), at most 3 Newton corrections per step, the final
# radius and length within 0.5 % of central differences on the same mesh; 2 ranks equal 1
# (scripts/taylor_bar_3d_implicit.py).
choc_cli_script(taylor_bar_3d_implicit 900)
# The Taylor bar in 3D (HEX8 F-bar, coarse): the quarter against the axisymmetric bar of the same
# element size, 2 ranks equal 1, the whole bar turned as a rigid whole (scripts/taylor_bar_3d.py).
choc_cli_script(taylor_bar_3d 600)
# The one-point HEX8 with hourglass stiffness on the 3D Taylor bar: no energy created, hourglass
# energy below 10 % of the internal energy, radius and length against the axisymmetric F-bar bar of
# the same element size within its mesh error, 2 ranks equal 1, the turned bar
# (scripts/one_point_taylor.py).
choc_cli_script(one_point_taylor 600)
# Kinematic hardening (small strain): the thick sphere under monotone pressure (proportional paths)
# with its modulus isotropic or kinematic: the same displacements within the mesh's asymmetry, the
# same total energy, the back stress's share stored (scripts/kinematic_hardening.py).
choc_cli_script(kinematic_hardening 300)
# An elastic-plastic sphere on a rigid plane at 0.5, 10 and 100 times its yield velocity: elastic
# below yield, the restitution falling with the speed above Thornton's closed form, no energy
# created, 2 ranks equal 1 (scripts/plastic_impact.py).
choc_cli_script(plastic_impact 600)
# The same sphere by average acceleration for 10 us (implicit Lagrange contact on a yielding zone,
# the line search and converged-solve statuses of the plastic defaults) against central
# differences: contact force, plastic work and motion within 1 %; 2 ranks and a renumbered mesh
# equal 1 rank to 1e-6 of the peaks over its first 4 us; at the default Newton iterations
# a numerical failure naming them (scripts/plastic_impact_implicit.py).
choc_cli_script(plastic_impact_implicit 300)

# The contact velocity update on a consistent mass (the projection in M's norm): example 03 with
# one impact, no energy created, the kinetic energy taken within its bound
# (scripts/velocity_update_consistent.py).
choc_cli_script(velocity_update_consistent 120)
