# error_size.<defect>: a 200-state chart with one defect, used by a machine declared on its type
# and by one declared on bsc::chart_ref, fails to compile with exactly one error, of at most 60
# lines and 8 KB, that names the check and the culprit before its first error line
# (error_size/big_chart_error.py); error_size.several: three defects, three errors.
function(bsc_add_error_size_test name defect)
  add_test(NAME error_size.${name}
    COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/error_size/big_chart_error.py
      --compiler ${CMAKE_CXX_COMPILER} --include ${PROJECT_SOURCE_DIR}/include --defect ${defect})
  set_tests_properties(error_size.${name} PROPERTIES LABELS compile TIMEOUT 300)
endfunction()

foreach(defect IN ITEMS
    unreachable_state dead_end_state conflicting_transitions shadowed_transition
    transition_between_orthogonal_regions state_not_in_chart duplicate_state missing_initial_state
    multiple_initial_states initial_not_a_child eventless_livelock not_a_row guard_signature_not_supported
    action_signature_not_supported dead_transition empty_parallel_state dead_timeout
    local_target_outside_source event_in_two_families initial_action_without_initial_transition
    invalid_history_state targets_not_orthogonal initial_states_not_orthogonal invalid_deferral
    done_never_raised done_of_state_not_in_chart done_source_inactive guard_is_a_bool_value)
  bsc_add_error_size_test(${defect} ${defect})
endforeach()
bsc_add_error_size_test(several "dead_end_state+conflicting_transitions+eventless_livelock")
bsc_add_error_size_test(several_rows "shadowed_transition+dead_transition+action_signature_not_supported")
