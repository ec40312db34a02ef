# inspector.*: the inspector's page in a real browser (tests/inspector/inspector_test.mjs):
# Debian's Chromium, headless, driven by playwright-core from web/node_modules. inspector.live
# runs the MCS with its view and pushes buttons on the page; inspector.system watches and drives
# the production cell, a system of ten actors, and inspector.replay_system opens a recording of it;
# inspector.replay opens a recorded
# run of the manufacturing cell from file:// and steps through it. Screenshots go to
# <build>/tests/inspector/. Without Node.js, Chromium or the npm packages (scripts/run deps
# installs them; the build copies elk.bundled.js beside the page) the tests report skipped,
# never passed. The replay also compares the page's reader with tools/bsc-trace (Python).
set(bsc_inspector_out ${CMAKE_CURRENT_BINARY_DIR}/inspector)
set(bsc_inspector_script ${CMAKE_CURRENT_SOURCE_DIR}/inspector/inspector_test.mjs)
set(bsc_node_modules ${PROJECT_SOURCE_DIR}/web/node_modules)
find_program(BSC_NODE node)
if(BSC_NODE)
  set(bsc_browser_test ${BSC_NODE} ${bsc_inspector_script})
else()
  set(bsc_browser_test ${Python3_EXECUTABLE} -c "import sys; print('Node.js not found: skipped'); sys.exit(77)")
endif()

add_test(NAME inspector.live
  COMMAND ${bsc_browser_test} live --program $<TARGET_FILE:mcs> --out ${bsc_inspector_out}
    --node-modules ${bsc_node_modules})

# inspector.system: the production cell with its view, one panel per actor and the links
# between them; the page shows another actor's chart, pauses and steps the cell, sets an input.
add_test(NAME inspector.system
  COMMAND ${bsc_browser_test} system --program $<TARGET_FILE:production_cell> --out ${bsc_inspector_out}
    --node-modules ${bsc_node_modules})

# The recorded run the replay opens: two pieces through the cell.
add_test(NAME inspector.record_cell
  COMMAND manufacturing_cell --quiet --pieces 2 --trace ${bsc_inspector_out}/cell.bsctrace)
set_tests_properties(inspector.record_cell PROPERTIES FIXTURES_SETUP bsc_cell_trace)
add_test(NAME inspector.replay
  COMMAND ${bsc_browser_test} replay --trace ${bsc_inspector_out}/cell.bsctrace --web-root ${BSC_INSPECTOR_WEB_ROOT}
    --out ${bsc_inspector_out} --node-modules ${bsc_node_modules} --python ${Python3_EXECUTABLE})
set_tests_properties(inspector.replay PROPERTIES FIXTURES_REQUIRED bsc_cell_trace)

# A system's recording (the production cell's checked run: system.json and a trace per actor),
# replayed from file:// with every actor's box following the time of the actor shown.
add_test(NAME inspector.record_system
  COMMAND sh -c "rm -rf \"$1\" && mkdir -p \"$1\" && \"$2\" --trace \"$1\" > /dev/null"
    record ${bsc_inspector_out}/production_cell $<TARGET_FILE:production_cell>)
set_tests_properties(inspector.record_system PROPERTIES FIXTURES_SETUP bsc_system_trace)
add_test(NAME inspector.replay_system
  COMMAND ${bsc_browser_test} replay-system --folder ${bsc_inspector_out}/production_cell --web-root ${BSC_INSPECTOR_WEB_ROOT}
    --out ${bsc_inspector_out} --node-modules ${bsc_node_modules})
set_tests_properties(inspector.replay_system PROPERTIES FIXTURES_REQUIRED bsc_system_trace)

file(MAKE_DIRECTORY ${bsc_inspector_out})
set_tests_properties(inspector.live inspector.system inspector.replay inspector.replay_system PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 150 LABELS browser
  RESOURCE_LOCK browser)
