# error_size.<defect>: a 200-state chart with one defect, used by a machine declared on its type
# and by one declared on bsc::chart_ref, fails to compile with exactly one error, of at most 60
# lines and 8 KB, that names the check and the culprit before its first error line and matches
# the defect's regex (error_size/big_chart_error.py); error_size.several: three defects, three
# errors. The defects, their regexes and their fixes are those of the catalogue,
# tests/defects/catalogue.py, that have a 200-state chart: every make_chart check. Each chart holds
# every defect's rows and states, fixed but for its own defects, so error_size.defect_free, the
# chart with every defect fixed, is the twin of each: it must compile (without warnings). These
# tests are the compile-fail tests of those checks; tests/compile_fail keeps the variants that the
# 200-state chart does not have (other rows, other causes).
function(bsc_add_error_size_test name defect)
  add_test(NAME error_size.${name}
    COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/error_size/big_chart_error.py
      --compiler ${CMAKE_CXX_COMPILER} --include ${PROJECT_SOURCE_DIR}/include --defect ${defect})
  set_tests_properties(error_size.${name} PROPERTIES LABELS compile TIMEOUT 300)
endfunction()

execute_process(
  COMMAND ${Python3_EXECUTABLE} ${bsc_defect_catalogue} big-chart
  OUTPUT_VARIABLE bsc_big_chart_defects OUTPUT_STRIP_TRAILING_WHITESPACE
  RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "tests/defects/catalogue.py cannot be read (see above)")
endif()
foreach(defect IN LISTS bsc_big_chart_defects)
  bsc_add_error_size_test(${defect} ${defect})
endforeach()
bsc_add_error_size_test(defect_free none)
bsc_add_error_size_test(several "dead_end_state+conflicting_transitions+eventless_livelock")
bsc_add_error_size_test(several_rows "shadowed_transition+dead_transition+action_signature_not_supported")
