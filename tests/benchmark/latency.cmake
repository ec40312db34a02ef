# benchmark.*: bsc::measure_latency (<bsc/benchmark.hpp>). benchmark.latency runs the test with
# the sanitizers; benchmark.latency_instructions runs it under callgrind, which counts each pair's
# instructions, so that it can assert which pair is the slowest (valgrind cannot run a sanitized
# program: that build has none); benchmark.latency_mcs and benchmark.latency_cell run bench/latency's reports on the
# MCS and the manufacturing cell.
find_package(benchmark REQUIRED)
find_program(BSC_VALGRIND valgrind)
# The header the counts need (Debian's valgrind package has it; elsewhere it may be apart).
include(CheckIncludeFileCXX)
check_include_file_cxx(valgrind/callgrind.h BSC_HAVE_CALLGRIND_H)

add_executable(latency_test benchmark/latency_test.cpp)
target_link_libraries(latency_test PRIVATE bsc::bsc benchmark::benchmark)
bsc_set_warnings(latency_test)
add_test(NAME benchmark.latency COMMAND latency_test)

add_executable(latency_test_plain benchmark/latency_test.cpp)
# Without the directory's sanitizer flags (the two properties start from them).
set_target_properties(latency_test_plain PROPERTIES COMPILE_OPTIONS "" LINK_OPTIONS "")
target_compile_options(latency_test_plain PRIVATE -O2)
target_link_libraries(latency_test_plain PRIVATE bsc::bsc benchmark::benchmark)
bsc_set_warnings(latency_test_plain)
set(bsc_callgrind_out ${CMAKE_CURRENT_BINARY_DIR}/latency/callgrind.%p)
file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/latency)
if(BSC_VALGRIND AND BSC_HAVE_CALLGRIND_H)
  add_test(NAME benchmark.latency_instructions
    COMMAND ${BSC_VALGRIND} --tool=callgrind --callgrind-out-file=${bsc_callgrind_out}
            $<TARGET_FILE:latency_test_plain> --callgrind ${bsc_callgrind_out})
else()
  add_test(NAME benchmark.latency_instructions COMMAND ${CMAKE_COMMAND} -E echo "valgrind or valgrind/callgrind.h not found")
  set_tests_properties(benchmark.latency_instructions PROPERTIES SKIP_REGULAR_EXPRESSION "not found")
endif()
set_tests_properties(benchmark.latency_instructions PROPERTIES
  PASS_REGULAR_EXPRESSION "latency_test: all checks passed" TIMEOUT 300)

if(BSC_BUILD_BENCHMARKS)
  add_test(NAME benchmark.latency_mcs COMMAND bench_latency_mcs)
  add_test(NAME benchmark.latency_cell COMMAND bench_latency_cell)
endif()
