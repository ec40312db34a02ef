# Packaging tests (label packaging): bsc as its users get it (docs/packaging.md).
#   packaging.find_package        install bsc into ${CMAKE_BINARY_DIR}/pkg-prefix, then a project
#                                 finds it with find_package(bsc CONFIG REQUIRED), and with
#                                 COMPONENTS hana where this build has bsc::hana
#   packaging.add_subdirectory    a project adds bsc's source directory; bsc adds no tests of its own
#   packaging.fetch_content       a project fetches an archive of bsc with FetchContent (file:// URL)
#   packaging.single_header       programs built with only single_include/ on the path,
#                                 one for each of bsc.hpp, verify.hpp and export.hpp
#   packaging.headers_self_contained
#                                 every header under include/bsc compiles on its own
#   packaging.standard_library_only
#                                 the headers include the standard library and bsc only
#                                 (and <mosquitto.h> for bsc::mqtt, Boost.Hana for bsc::hana,
#                                 Google Benchmark and valgrind's header for <bsc/benchmark.hpp>)
# Each consumer is configured and built by a cmake subprocess with this build's compiler,
# generator and build type (tests/packaging/run_consumer.cmake).
if(TARGET bsc::hana)
  set(bsc_packaging_hana ON)  # the installed bsc has it too: the consumer requires it
else()
  set(bsc_packaging_hana OFF)
endif()
foreach(method IN ITEMS find_package add_subdirectory fetch_content single_header)
  add_test(NAME packaging.${method}
    COMMAND ${CMAKE_COMMAND}
      -DMETHOD=${method}
      -DBSC_SOURCE_DIR=${PROJECT_SOURCE_DIR}
      -DWORK_DIR=${CMAKE_BINARY_DIR}/packaging
      -DPREFIX=${CMAKE_BINARY_DIR}/pkg-prefix
      -DGENERATOR=${CMAKE_GENERATOR}
      -DCXX=${CMAKE_CXX_COMPILER}
      -DBUILD_TYPE=${CMAKE_BUILD_TYPE}
      -DCTEST=${CMAKE_CTEST_COMMAND}
      -DHANA=${bsc_packaging_hana}
      -P ${CMAKE_CURRENT_SOURCE_DIR}/packaging/run_consumer.cmake)
  set_tests_properties(packaging.${method} PROPERTIES LABELS packaging TIMEOUT 300)
endforeach()

# Every public header compiles on its own: one translation unit per header, holding only its
# #include, all in one object library that is part of the build; the test checks it is built.
file(GLOB_RECURSE bsc_public_headers CONFIGURE_DEPENDS RELATIVE ${PROJECT_SOURCE_DIR}/include
  ${PROJECT_SOURCE_DIR}/include/bsc/*.hpp)
if(NOT TARGET bsc::mqtt)  # they include <mosquitto.h>
  list(REMOVE_ITEM bsc_public_headers bsc/mqtt.hpp bsc/net/mosquitto_transport.hpp)
endif()
if(NOT TARGET bsc::hana)  # it includes Boost.Hana
  list(REMOVE_ITEM bsc_public_headers bsc/adapt/hana.hpp)
endif()
set(bsc_header_units)
foreach(header IN LISTS bsc_public_headers)
  string(REGEX REPLACE "\\.hpp$" ".cpp" unit ${header})
  set(unit ${CMAKE_CURRENT_BINARY_DIR}/header_units/${unit})
  file(CONFIGURE OUTPUT ${unit} @ONLY CONTENT "#include <${header}>\n")
  list(APPEND bsc_header_units ${unit})
endforeach()
add_library(bsc_headers_self_contained OBJECT ${bsc_header_units})
target_link_libraries(bsc_headers_self_contained PRIVATE bsc::bsc)
if(TARGET bsc::mqtt)
  target_link_libraries(bsc_headers_self_contained PRIVATE bsc::mqtt)
endif()
if(TARGET bsc::hana)
  target_link_libraries(bsc_headers_self_contained PRIVATE bsc::hana)
endif()
bsc_set_warnings(bsc_headers_self_contained)
add_test(NAME packaging.headers_self_contained
  COMMAND ${CMAKE_COMMAND} --build ${CMAKE_BINARY_DIR} --target bsc_headers_self_contained)
set_tests_properties(packaging.headers_self_contained PROPERTIES LABELS packaging)

# The library depends on the standard library alone (libmosquitto for bsc::mqtt, Boost.Hana for
# bsc::hana).
add_test(NAME packaging.standard_library_only
  COMMAND ${CMAKE_COMMAND} -DBSC_SOURCE_DIR=${PROJECT_SOURCE_DIR}
    -P ${CMAKE_CURRENT_SOURCE_DIR}/packaging/standard_library_only.cmake)
set_tests_properties(packaging.standard_library_only PROPERTIES LABELS packaging)
