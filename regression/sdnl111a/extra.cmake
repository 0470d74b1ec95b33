# The three obstacle shapes reduce to the same axial gap: their histories agree to round-off
# (the frames differ by cos(90 deg) ~ 6e-17, so 1e-12 of peak is generous round-off).
foreach(shape plans_y cercle)
  add_test(NAME regression.sdnl111a.shapes.${shape}
           COMMAND python3 ${CMAKE_SOURCE_DIR}/tools/compare_histories.py
                   ${out}/serial/plans_z.history.csv ${out}/serial/${shape}.history.csv
                   --rtol-peak 1e-12)
  set_tests_properties(regression.sdnl111a.shapes.${shape} PROPERTIES DEPENDS regression.sdnl111a)
endforeach()
