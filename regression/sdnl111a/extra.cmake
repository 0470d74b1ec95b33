# The three obstacle shapes reduce to the same axial gap: their histories agree to round-off
# (the frames differ by cos(90 deg) ~ 6e-17, so 1e-12 of peak is generous round-off). The energy
# balance is left out: a difference of energies far above it, it carries their round-off
# magnified by that ratio against its own peak (1.4e-12 with OpenBLAS' summation order).
foreach(shape plans_y cercle)
  add_test(NAME regression.sdnl111a.shapes.${shape}
           COMMAND python3 ${CMAKE_SOURCE_DIR}/tools/oracles/compare_histories.py
                   ${out}/serial/plans_z.history.csv ${out}/serial/${shape}.history.csv
                   --rtol-peak 1e-12
                   --columns "A:DX,A:VX,C:DX,energy:kinetic,energy:strain,energy:contact,energy:dissipated,energy:total,shock:force,shock:gap,shock:status")
  set_tests_properties(regression.sdnl111a.shapes.${shape} PROPERTIES DEPENDS regression.sdnl111a)
endforeach()
# The report (tools/report/make_report.py) on this case's serial results: it runs, its table holds
# every check row, the plots exist and its Python exact-solution errors agree with choc's.
add_test(NAME regression.sdnl111a.report
         COMMAND python3 ${CMAKE_SOURCE_DIR}/tools/report/test_report.py ${dir} ${out}/serial ${out}/report)
set_tests_properties(regression.sdnl111a.report PROPERTIES DEPENDS regression.sdnl111a TIMEOUT 120)
# The Exodus files as ParaView reads them (tools/report/paraview_check.py): time steps, vector
# grouping, node sets, A's DISP_X against the history. Skipped (77) when pvbatch is absent.
add_test(NAME regression.sdnl111a.paraview
         COMMAND /bin/sh -c "command -v pvbatch >/dev/null 2>&1 || { echo 'pvbatch not found: skipped'; exit 77; }; exec pvbatch \"$0\" \"$@\""
                 ${CMAKE_SOURCE_DIR}/tools/report/paraview_check.py ${out}/serial
                 --input ${CMAKE_SOURCE_DIR}/input/sdnl111a.xml)
set_tests_properties(regression.sdnl111a.paraview PROPERTIES DEPENDS regression.sdnl111a
                     SKIP_RETURN_CODE 77 TIMEOUT 300)
