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
add_test(NAME cli.rigid_velocity
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/scripts/rigid_velocity.py
                 $<TARGET_FILE:choc> ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/work/rigid_velocity)
set_tests_properties(cli.rigid_velocity PROPERTIES TIMEOUT 120 LABELS cli)

# Finite strain: a free cube spun about its axis turns ten times rigidly but for its
# centrifugal stretch, by central differences and by average acceleration, on 1 and 2 ranks;
# the small-strain model fails the same scene (scripts/tumbling_block.py).
add_test(NAME cli.tumbling_block
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/scripts/tumbling_block.py
                 $<TARGET_FILE:choc> ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/work/tumbling_block)
set_tests_properties(cli.tumbling_block PROPERTIES TIMEOUT 300 LABELS cli)

# SDNL111 C's 3D bars in finite strain (Saint Venant-Kirchhoff) give the small-strain motion of
# A to the order of the strain, 1/5064 (scripts/finite_small_sdnl111c.py).
add_test(NAME cli.finite_small_sdnl111c
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/scripts/finite_small_sdnl111c.py
                 $<TARGET_FILE:choc> ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/work/finite_small_sdnl111c)
set_tests_properties(cli.finite_small_sdnl111c PROPERTIES TIMEOUT 300 LABELS cli)
