# perf.instructions and perf.compile_time: scripts/perf_gate.py holds the dispatch instruction
# counts (callgrind, deterministic) and the compile time of the 50-state chart (as a ratio to a
# reference translation unit compiled alternately with it) to their baselines in
# bench/baselines.json, for this build's compiler. The script compiles its own programs (-O2,
# no sanitizers). Skipped (exit 77) for a compiler without a baseline or without valgrind.
option(BSC_PERF_GATE "Check dispatch instruction counts and compile time against bench/baselines.json" ON)
if(BSC_PERF_GATE)
  foreach(gate IN ITEMS instructions compile-time)
    string(REPLACE "-" "_" name ${gate})
    add_test(NAME perf.${name}
      COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/perf_gate.py ${gate} --compiler ${CMAKE_CXX_COMPILER})
    set_tests_properties(perf.${name} PROPERTIES LABELS perf RUN_SERIAL TRUE TIMEOUT 900 SKIP_RETURN_CODE 77)
  endforeach()
endif()
