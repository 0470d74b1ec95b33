# The 'auto' linear solver (src/solvers/SolverChoice.hpp) on the scale scene's bars at 9,648
# unknowns: CG + Jacobi stated in the log when mass-dominated, the histories equal Direct's to
# 1e-7 of their peaks; Direct stated when stiffness-dominated (dt = 1e-5 s).
add_test(NAME cli.linear_solver_auto
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/scripts/linear_solver_auto.py
                 $<TARGET_FILE:choc> ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/work/linear_solver_auto)
set_tests_properties(cli.linear_solver_auto PROPERTIES TIMEOUT 120 LABELS cli)

# The direct solver's kept factorisation through changes of contact status (Update Budget):
# Lagrange contact on the scale scene's bars at 9,648 unknowns, 100 steps: the histories of
# refactoring at every change to 1e-7 of their peaks with at most half the factorisations, on
# 1 and 2 ranks.
add_test(NAME cli.kept_factorization
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/scripts/kept_factorization.py
                 $<TARGET_FILE:choc> ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/work/kept_factorization)
set_tests_properties(cli.kept_factorization PROPERTIES TIMEOUT 180 PROCESSORS 2 LABELS cli)
# MUMPS on every rank: the scale scene's bars with Lagrange contact (1 and 2 ranks) and the
# sliding block with Coulomb friction give KLU2's histories to 1e-7 of their peaks.
add_test(NAME cli.mumps_contact
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/scripts/mumps_contact.py
                 $<TARGET_FILE:choc> ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/work/mumps_contact)
set_tests_properties(cli.mumps_contact PROPERTIES TIMEOUT 300 PROCESSORS 2 LABELS cli)

# Multigrid for elasticity in a stiffness-dominated transient (the scale scene's bars at 9,648
# unknowns, dt = 1e-4 s): at most 40 CG iterations per Newton solve, histories equal to the
# direct solver's to 1e-7 of their peaks on 1 and 2 ranks.
add_test(NAME cli.multigrid
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/scripts/multigrid.py
                 $<TARGET_FILE:choc> ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/work/multigrid)
set_tests_properties(cli.multigrid PROPERTIES TIMEOUT 300 PROCESSORS 2 LABELS cli)

# Contact pressures against rigid obstacles condensed out of the Newton system: CG + Jacobi, CG +
# Multigrid and GMRES give the direct saddle-point solve's histories to 1e-7 of their peaks on
# 1 and 2 ranks (the axisymmetric sphere on a plane, the compact block), the gap closed exactly.
add_test(NAME cli.condensed_contact
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/scripts/condensed_contact.py
                 $<TARGET_FILE:choc> ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/work/condensed_contact)
set_tests_properties(cli.condensed_contact PROPERTIES TIMEOUT 300 PROCESSORS 2 LABELS cli)

# Lagrange contact between meshed bodies by CG, the multipliers projected out
# (ContactProjection): the scale scene's bars at 9,648 unknowns (CG + Jacobi, CG + Multigrid, and
# 2 ranks) and SDNL111 on non-matching meshes (node to face and mortar) against the direct
# saddle-point solve, to 1e-7 of each peak; no preconditioner set-up at a change of status.
add_test(NAME cli.projected_contact
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/scripts/projected_contact.py
                 $<TARGET_FILE:choc> ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/work/projected_contact)
set_tests_properties(cli.projected_contact PROPERTIES TIMEOUT 300 PROCESSORS 2 LABELS cli)
