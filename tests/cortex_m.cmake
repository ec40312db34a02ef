# The Cortex-M4 target (tests/cortex_m/, scripts/cortex_m.py): the examples' controllers and the
# CD player built for a Cortex-M4 with arm-none-eabi-gcc, run under QEMU (mps2-an386) with
# semihosting, and held to what they do on the host.
#   cortex_m.build              the images, at -Os and -O2, by a CMake project of their own
#                               (tests/cortex_m/CMakeLists.txt and its toolchain file), so that this
#                               build's flags and sanitizers do not reach them
#   cortex_m.<program>.trace    each image prints the trace the same source prints built for the
#                               host (the programs below), and a bsc machine's trace is the
#                               hand-written controller's
#   cortex_m.symbols            no image holds malloc, printf, __cxa_*, an unwinder or typeinfo
#   perf.cortex_m               flash, RAM and instructions per event of bsc's programs against
#                               bench/baselines.json ("cortex_m4")
# Without arm-none-eabi-g++ or qemu-system-arm (scripts/run deps installs them) they report
# skipped.
option(BSC_TEST_CORTEX_M "Build the programs of tests/cortex_m/ for a Cortex-M4 and run them under QEMU" ON)
if(BSC_TEST_CORTEX_M)
  include(${CMAKE_CURRENT_SOURCE_DIR}/cortex_m/programs.cmake)
  set(bsc_cortex_m_dir ${CMAKE_CURRENT_BINARY_DIR}/cortex_m)
  set(bsc_cortex_m ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/cortex_m.py)

  add_test(NAME cortex_m.build COMMAND ${bsc_cortex_m} build --build-dir ${bsc_cortex_m_dir})
  set_tests_properties(cortex_m.build PROPERTIES
    FIXTURES_SETUP bsc_cortex_m LABELS cortex_m SKIP_RETURN_CODE 77 TIMEOUT 600)

  foreach(program IN LISTS BSC_CORTEX_M_PROGRAMS)
    string(REGEX REPLACE "_[a-z]+$" "" chart ${program})
    if(program MATCHES "_floor$")  # a driver without a chart: measured, not traced
      continue()
    endif()
    add_executable(cortex_m_${program} cortex_m/${program}.cpp)
    target_link_libraries(cortex_m_${program} PRIVATE bsc::bsc)
    bsc_set_warnings(cortex_m_${program})
    set(reference)
    if(NOT program MATCHES "_hand$")
      set(reference --reference $<TARGET_FILE:cortex_m_${chart}_hand>)
    endif()
    add_test(NAME cortex_m.${program}.trace
      COMMAND ${bsc_cortex_m} trace --build-dir ${bsc_cortex_m_dir} --host $<TARGET_FILE:cortex_m_${program}>
        ${reference} ${program})
    set_tests_properties(cortex_m.${program}.trace PROPERTIES
      FIXTURES_REQUIRED bsc_cortex_m LABELS cortex_m SKIP_RETURN_CODE 77 TIMEOUT 300)
  endforeach()

  add_test(NAME cortex_m.symbols COMMAND ${bsc_cortex_m} symbols --build-dir ${bsc_cortex_m_dir})
  add_test(NAME perf.cortex_m COMMAND ${bsc_cortex_m} report --check --build-dir ${bsc_cortex_m_dir})
  set_tests_properties(cortex_m.symbols PROPERTIES
    FIXTURES_REQUIRED bsc_cortex_m LABELS cortex_m SKIP_RETURN_CODE 77)
  set_tests_properties(perf.cortex_m PROPERTIES
    FIXTURES_REQUIRED bsc_cortex_m LABELS "cortex_m;perf" SKIP_RETURN_CODE 77 TIMEOUT 600)
endif()
