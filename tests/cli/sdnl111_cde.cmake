# SDNL111 C, D, E (direct implicit transient with contact): each input must run to the end
# with every document row OK. E keeps the document's 0.03 % row at 4e-4 s, a known
# inconsistency (docs/verification/sdnl111e.md): that row alone may be NOOK (exit 3); the script checks
# that no other row is.
foreach(m c d e)
  add_test(NAME sdnl111${m}
           COMMAND ${CMAKE_COMMAND} -DCHOC=$<TARGET_FILE:choc>
                   -DINPUT=${CMAKE_SOURCE_DIR}/input/sdnl111${m}.xml
                   -DOUT=${CMAKE_BINARY_DIR}/results/sdnl111${m}
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/scripts/run_with_known_rows.cmake)
endforeach()
add_test(NAME sdnl111c.np2
         COMMAND mpirun --allow-run-as-root --oversubscribe --mca mpi_yield_when_idle 1 -np 2 $<TARGET_FILE:choc> run
                 ${CMAKE_SOURCE_DIR}/input/sdnl111c.xml -o ${CMAKE_BINARY_DIR}/results/sdnl111c_np2)
