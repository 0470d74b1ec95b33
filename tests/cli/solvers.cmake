# The 'auto' linear solver (src/solvers/SolverChoice.hpp) on the scale scene's bars at 9,648
# unknowns: CG + Jacobi stated in the log when mass-dominated, the histories equal Direct's to
# 1e-7 of their peaks; Direct stated when stiffness-dominated (dt = 1e-5 s).
add_test(NAME cli.linear_solver_auto
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/scripts/linear_solver_auto.py
                 $<TARGET_FILE:choc> ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/work/linear_solver_auto)
set_tests_properties(cli.linear_solver_auto PROPERTIES TIMEOUT 120 LABELS cli)
