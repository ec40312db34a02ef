# Runs one packaging test (cmake -P): builds the consumer project tests/packaging/<METHOD>/
# against this checkout of bsc as a user of that method would, then runs the consumer's own test.
#   -DMETHOD=find_package|add_subdirectory|fetch_content|single_header
#   -DBSC_SOURCE_DIR=... -DWORK_DIR=... -DPREFIX=... (find_package's install prefix)
#   -DGENERATOR=... -DCXX=... -DBUILD_TYPE=... -DCTEST=...
#   -DHANA=ON|OFF (find_package: whether the consumer requires the component hana)
cmake_minimum_required(VERSION 3.21)

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT result EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "failed (${result}): ${command}\n${output}")
  endif()
endfunction()

set(consumer ${CMAKE_CURRENT_LIST_DIR}/${METHOD})
set(work ${WORK_DIR}/${METHOD})
if(NOT IS_DIRECTORY ${consumer})
  message(FATAL_ERROR "no consumer project ${consumer}")
endif()
file(REMOVE_RECURSE ${work})
file(MAKE_DIRECTORY ${work})
set(common -G ${GENERATOR} -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_BUILD_TYPE=${BUILD_TYPE})
set(consumer_args)

if(METHOD STREQUAL "find_package")
  # Configure, build and install bsc alone into PREFIX, as a package would be.
  file(REMOVE_RECURSE ${PREFIX})
  run(${CMAKE_COMMAND} -S ${BSC_SOURCE_DIR} -B ${work}/bsc-build ${common}
      -DBSC_BUILD_TESTS=OFF -DBSC_BUILD_EXAMPLES=OFF -DBSC_BUILD_BENCHMARKS=OFF -DBSC_INSTALL=ON
      -DCMAKE_INSTALL_PREFIX=${PREFIX})
  run(${CMAKE_COMMAND} --build ${work}/bsc-build)
  run(${CMAKE_COMMAND} --install ${work}/bsc-build)
  list(APPEND consumer_args -DCMAKE_PREFIX_PATH=${PREFIX} -DBSC_HANA=${HANA})
elseif(METHOD STREQUAL "add_subdirectory")
  list(APPEND consumer_args -DBSC_SOURCE_DIR=${BSC_SOURCE_DIR})
elseif(METHOD STREQUAL "fetch_content")
  # An archive of what a release of bsc holds; FetchContent unpacks it from a file:// URL.
  run(${CMAKE_COMMAND} -E chdir ${BSC_SOURCE_DIR}
      ${CMAKE_COMMAND} -E tar czf ${work}/bsc.tar.gz CMakeLists.txt cmake include single_include)
  list(APPEND consumer_args -DBSC_ARCHIVE=${work}/bsc.tar.gz)
elseif(METHOD STREQUAL "single_header")
  list(APPEND consumer_args -DBSC_SINGLE_INCLUDE=${BSC_SOURCE_DIR}/single_include)
else()
  message(FATAL_ERROR "unknown METHOD ${METHOD}")
endif()

run(${CMAKE_COMMAND} -S ${consumer} -B ${work}/build ${common} ${consumer_args})
run(${CMAKE_COMMAND} --build ${work}/build)
run(${CTEST} --test-dir ${work}/build --output-on-failure)
message(STATUS "${METHOD}: the consumer builds and passes its test")
