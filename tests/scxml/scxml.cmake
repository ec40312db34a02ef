# SCXML documents compiled by tools/bsc-scxml (docs/scxml.md):
#   scxml.w3c        the W3C SCXML 1.0 IRP suite (../shared/w3c-scxml-irp, or BSC_W3C_IRP_DIR): every
#                    mandatory automatic test that applies to bsc, compiled and run on both back
#                    ends, 0 failures (tests/scxml/w3c.py; skipped where the suite is not there)
#   scxml.table_up_to_date  docs/scxml.md's table of the suite is what w3c.py writes
#   scxml.round_trip  every example chart exported as SCXML and compiled back runs as the original
#   scxml.compiler   the compiler's errors name the file, line and element; a C++ error in an
#                    expression points at its SCXML line; findings allowed are warned about
# The suite's documents are transformed and compiled when CMake configures (w3c.py generate),
# again whenever the compiler, the transformation or the suite changes.
option(BSC_TEST_W3C "Build and run the W3C SCXML IRP suite" ON)
set(BSC_W3C_IRP_DIR "${PROJECT_SOURCE_DIR}/../shared/w3c-scxml-irp" CACHE PATH
  "The W3C SCXML IRP suite (manifest.xml, txml/)")

set(bsc_scxml_compiler ${PROJECT_SOURCE_DIR}/tools/bsc-scxml)
set(bsc_w3c_script ${CMAKE_CURRENT_SOURCE_DIR}/scxml/w3c.py)

if(BSC_TEST_W3C AND EXISTS "${BSC_W3C_IRP_DIR}/manifest.xml")
  set(bsc_w3c_dir ${CMAKE_CURRENT_BINARY_DIR}/w3c)
  execute_process(
    COMMAND ${Python3_EXECUTABLE} ${bsc_w3c_script} generate ${BSC_W3C_IRP_DIR} ${bsc_w3c_dir}
    RESULT_VARIABLE bsc_w3c_result)
  if(NOT bsc_w3c_result EQUAL 0)
    message(FATAL_ERROR "tests/scxml/w3c.py generate failed")
  endif()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
    ${bsc_scxml_compiler} ${bsc_w3c_script} ${BSC_W3C_IRP_DIR}/manifest.xml)
  file(STRINGS ${bsc_w3c_dir}/units.txt bsc_w3c_units)
  list(TRANSFORM bsc_w3c_units PREPEND ${bsc_w3c_dir}/)
  add_executable(w3c_suite ${bsc_w3c_units})
  target_include_directories(w3c_suite PRIVATE ${bsc_w3c_dir} ${CMAKE_CURRENT_SOURCE_DIR}/scxml)
  target_link_libraries(w3c_suite PRIVATE bsc::bsc)
  bsc_set_warnings(w3c_suite)
  add_test(NAME scxml.w3c COMMAND w3c_suite)
  set_tests_properties(scxml.w3c PROPERTIES LABELS scxml TIMEOUT 300)
  add_test(NAME scxml.table_up_to_date
    COMMAND ${Python3_EXECUTABLE} ${bsc_w3c_script} doc ${BSC_W3C_IRP_DIR} ${PROJECT_SOURCE_DIR}/docs/scxml.md --check)
  set_tests_properties(scxml.table_up_to_date PROPERTIES LABELS "scxml;fast")
elseif(BSC_TEST_W3C)
  add_test(NAME scxml.w3c COMMAND ${CMAKE_COMMAND} -E echo
    "skipped: the W3C SCXML IRP suite is not at ${BSC_W3C_IRP_DIR} (set BSC_W3C_IRP_DIR)")
  set_tests_properties(scxml.w3c PROPERTIES LABELS scxml SKIP_REGULAR_EXPRESSION "skipped:")
endif()

add_test(NAME scxml.compiler
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/scxml/compiler_test.py
    ${bsc_scxml_compiler} ${CMAKE_CXX_COMPILER} ${PROJECT_SOURCE_DIR}/include ${CMAKE_CURRENT_BINARY_DIR}/scxml_compiler)
set_tests_properties(scxml.compiler PROPERTIES LABELS scxml TIMEOUT 300)

# scxml.round_trip: every example chart exported as SCXML (bsc::to_scxml_annotated), compiled back
# by bsc-scxml --chart, and driven side by side with the original (round_trip_test.cpp). The list
# of charts is tests/scxml/round_trip_charts.txt; round_trip.py writes the exporter and the header
# that lists the pairs when CMake configures, and compiles the documents back at build time.
set(bsc_rt_dir ${CMAKE_CURRENT_BINARY_DIR}/round_trip)
set(bsc_rt_list ${CMAKE_CURRENT_SOURCE_DIR}/scxml/round_trip_charts.txt)
set(bsc_rt_script ${CMAKE_CURRENT_SOURCE_DIR}/scxml/round_trip.py)
execute_process(COMMAND ${Python3_EXECUTABLE} ${bsc_rt_script} sources ${bsc_rt_list} ${bsc_rt_dir}
  RESULT_VARIABLE bsc_rt_result)
if(NOT bsc_rt_result EQUAL 0)
  message(FATAL_ERROR "tests/scxml/round_trip.py sources failed")
endif()
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${bsc_rt_list} ${bsc_rt_script})
add_executable(export_annotated ${bsc_rt_dir}/export_annotated.cpp)
target_include_directories(export_annotated PRIVATE ${PROJECT_SOURCE_DIR}/examples)
target_link_libraries(export_annotated PRIVATE bsc::bsc)
bsc_set_warnings(export_annotated)
file(STRINGS ${bsc_rt_list} bsc_rt_lines REGEX "^[a-z]")
set(bsc_rt_headers)
foreach(line IN LISTS bsc_rt_lines)
  string(REGEX MATCH "^[a-z_]+" name "${line}")
  list(APPEND bsc_rt_headers ${bsc_rt_dir}/rt_${name}.hpp)
endforeach()
add_custom_command(OUTPUT ${bsc_rt_headers}
  COMMAND export_annotated ${bsc_rt_dir}
  COMMAND ${Python3_EXECUTABLE} ${bsc_rt_script} compile ${bsc_rt_list} ${bsc_rt_dir} ${bsc_scxml_compiler}
  DEPENDS export_annotated ${bsc_scxml_compiler} ${bsc_rt_list} ${bsc_rt_script}
  COMMENT "round trip: the example charts exported as SCXML and compiled back"
  VERBATIM)
add_executable(round_trip_test unit/main.cpp scxml/round_trip_test.cpp ${bsc_rt_headers})
target_include_directories(round_trip_test PRIVATE
  ${bsc_rt_dir} ${CMAKE_CURRENT_SOURCE_DIR}/unit ${PROJECT_SOURCE_DIR}/examples)
target_link_libraries(round_trip_test PRIVATE bsc::bsc doctest::doctest)
bsc_set_warnings(round_trip_test)
add_test(NAME scxml.round_trip COMMAND round_trip_test)
set_tests_properties(scxml.round_trip PROPERTIES LABELS scxml TIMEOUT 300)
