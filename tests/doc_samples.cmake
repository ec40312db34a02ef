# The code samples of the documentation are compiled, and run, by the test suite, so that they
# cannot drift from the library. bsc_add_doc_samples(page prefix) takes every ```cpp block of
# the page, in order (<prefix>_1, <prefix>_2, ...); tests/doc_samples/doc_samples.py cuts the
# page into translation units at configure time, and doc.samples_covered fails if a C++ block of
# README.md or docs/ is on a page that is not listed below.
#
# A block is a complete program unless an HTML comment on the line just before its fence says
# otherwise:
#
#   (no comment)                   a complete program: built as the executable <prefix>_<n> and
#                                  run by ctest doc.<prefix>_<n>, which passes on exit status 0.
#   <!-- sample: prelude -->       declarations that the blocks after it on the page assume
#                                  (includes, states, events): put before each of them, not
#                                  compiled alone.
#   <!-- sample: in NAME -->       a fragment: it is pasted into tests/doc_samples/NAME.cpp.in,
#                                  which holds what the page leaves out (includes, the
#                                  declarations the fragment uses, a main() that checks what the
#                                  page says of it). Where the wrapper has a line `@SAMPLE@`,
#                                  each block is pasted there and is a program of its own. Where
#                                  it has lines `@SAMPLE_1@`, `@SAMPLE_2@`, ..., the page's blocks
#                                  marked `in NAME` are pasted there in order and make one
#                                  program, <prefix>_<i>_<j>_...: a page's fragments that need
#                                  the same context cost one translation unit.
#   <!-- sample: fails defect=TYPE -->
#   <!-- sample: in NAME; fails defect=TYPE -->
#                                  the block shows a compile error and its fix. A line with a
#                                  comment `// Error...` belongs to the erroneous version only,
#                                  a line with a comment `// Fix...` to the fixed version only,
#                                  the other lines to both. The error is a defect of the
#                                  catalogue, tests/defects/catalogue.py: TYPE is its check's
#                                  name, or its error type as the compiler prints it without
#                                  bsc::error:: (`defect=dead_end_state<cf::Stuck>`,
#                                  `defect=at_row<3, local_target_outside_source<cf::Work, cf::Idle>`),
#                                  and the catalogue gives the regex, with the check's message,
#                                  that the compile-fail tests and error_size.* use too.
#   <!-- sample: fails REGEX -->   the same, with a regex of its own (a diagnostic that is no
#                                  check's message). Either way, the erroneous version must
#                                  fail to compile with a diagnostic matching the regex: ctest
#                                  doc.<prefix>_<n>.fails builds the object library
#                                  <prefix>_<n> (EXCLUDE_FROM_ALL) and passes if the build output
#                                  matches (PASS_REGULAR_EXPRESSION, as tests/compile_fail). The
#                                  fixed versions of a page's blocks are compiled together, each
#                                  in a namespace sample_<n> of its own, as the program
#                                  <prefix>_fixes (ctest doc.<prefix>_fixes).
#
# The generated sources carry #line directives, so diagnostics name the page and its line. The
# wrappers see the examples' headers (examples/ is on their include path).

set(bsc_doc_samples_script ${CMAKE_CURRENT_SOURCE_DIR}/doc_samples/doc_samples.py)

# A sample that includes <bsc/adapt/hana.hpp> links bsc::hana, and is left out where Boost is not.
function(bsc_doc_sample_program name source)
  file(STRINGS ${source} hana REGEX "^#include <bsc/adapt/hana\\.hpp>")
  if(hana AND NOT TARGET bsc::hana)
    return()
  endif()
  add_executable(${name} ${source})
  target_link_libraries(${name} PRIVATE bsc::bsc)
  if(hana)
    target_link_libraries(${name} PRIVATE bsc::hana)
  endif()
  # A sample that includes <bsc/benchmark.hpp> links Google Benchmark (benchmark/latency.cmake finds it).
  file(STRINGS ${source} latency REGEX "^#include <bsc/benchmark\\.hpp>")
  if(latency)
    target_link_libraries(${name} PRIVATE benchmark::benchmark)
  endif()
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR}/examples)
  bsc_set_warnings(${name})
  add_test(NAME doc.${name} COMMAND ${name})
  set_tests_properties(doc.${name} PROPERTIES LABELS doc)
endfunction()

function(bsc_doc_sample_failing name source regex)
  add_library(${name} OBJECT EXCLUDE_FROM_ALL ${source})
  target_link_libraries(${name} PRIVATE bsc::bsc)
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR}/examples)
  bsc_set_warnings(${name})
  add_test(NAME doc.${name}.fails
    COMMAND ${CMAKE_COMMAND} --build ${CMAKE_BINARY_DIR} --target ${name} --config $<CONFIG>)
  set_tests_properties(doc.${name}.fails PROPERTIES PASS_REGULAR_EXPRESSION "${regex}" LABELS "doc;compile")
endfunction()

function(bsc_add_doc_samples page prefix)
  set(out ${CMAKE_CURRENT_BINARY_DIR}/doc_samples)
  execute_process(
    COMMAND ${Python3_EXECUTABLE} ${bsc_doc_samples_script} extract ${PROJECT_SOURCE_DIR} ${page} ${prefix} ${out}
    RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "the code samples of ${page} cannot be extracted (see above)")
  endif()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
    ${PROJECT_SOURCE_DIR}/${page} ${bsc_doc_samples_script} ${bsc_defect_catalogue})
  set_property(GLOBAL APPEND PROPERTY bsc_doc_sample_pages ${page})
  include(${out}/${prefix}.cmake)
endfunction()

bsc_add_doc_samples(README.md readme)
bsc_add_doc_samples(docs/tutorial.md tutorial)
bsc_add_doc_samples(docs/api.md api)
bsc_add_doc_samples(docs/exports.md exports)
bsc_add_doc_samples(docs/checks.md checks)
bsc_add_doc_samples(docs/composition.md composition)
bsc_add_doc_samples(docs/verification.md verification)
bsc_add_doc_samples(docs/table-runtime.md table_runtime)
bsc_add_doc_samples(docs/trace.md trace)
bsc_add_doc_samples(docs/inspector.md inspector)
bsc_add_doc_samples(docs/examples/eca_cell.md eca_cell_page)

get_property(bsc_doc_sample_pages GLOBAL PROPERTY bsc_doc_sample_pages)
add_test(NAME doc.samples_covered
  COMMAND ${Python3_EXECUTABLE} ${bsc_doc_samples_script} check ${PROJECT_SOURCE_DIR} ${bsc_doc_sample_pages})
set_tests_properties(doc.samples_covered PROPERTIES LABELS "doc;fast")
