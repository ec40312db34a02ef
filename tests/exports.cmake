# The diagram exports on the examples (docs/exports.md). export_diagrams writes the examples'
# diagrams; the fixture exports.generate runs it with --all on a directory of the build, and
# the tests after it check what it wrote:
#   exports.scxml_well_formed  the SCXML parses as XML (Python's xml.etree), ids and targets agree
#   exports.dot_renders        Graphviz renders the DOT without a warning (skipped without dot)
#   diagrams_up_to_date        docs/diagrams/*.mmd and *.dot, and the Diagram sections of the
#                              example pages, are what the exporter writes today
add_executable(export_diagrams ${PROJECT_SOURCE_DIR}/docs/diagrams/export_diagrams.cpp)
target_link_libraries(export_diagrams PRIVATE bsc::bsc)
bsc_set_warnings(export_diagrams)

set(bsc_exports_dir ${CMAKE_CURRENT_BINARY_DIR}/exports)
add_test(NAME exports.generate COMMAND export_diagrams --all ${bsc_exports_dir})
add_test(NAME exports.scxml_well_formed
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/export/check_exports.py scxml ${bsc_exports_dir})
add_test(NAME exports.dot_renders
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/export/check_exports.py dot ${bsc_exports_dir})
add_test(NAME diagrams_up_to_date
  COMMAND ${Python3_EXECUTABLE} scripts/diagrams.py --check ${bsc_exports_dir}
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(exports.generate PROPERTIES FIXTURES_SETUP bsc_exports LABELS exports)
set_tests_properties(exports.scxml_well_formed exports.dot_renders diagrams_up_to_date PROPERTIES
  FIXTURES_REQUIRED bsc_exports LABELS exports)
set_tests_properties(exports.dot_renders PROPERTIES SKIP_RETURN_CODE 77)
