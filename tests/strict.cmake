# The library's headers under the warnings users commonly turn on: every public header, and
# tests/strict/strict_use.cpp, which instantiates both back ends on the examples' charts, a
# system, the exports and the explorer, compiled with the flags below and -Werror. Part of the
# build, so a warning in a header fails it; ctest `strict_warnings` checks the target is built.
set(BSC_STRICT_WARNING_FLAGS
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion -Wold-style-cast -Werror)

file(GLOB_RECURSE bsc_strict_headers CONFIGURE_DEPENDS RELATIVE ${PROJECT_SOURCE_DIR}/include
  ${PROJECT_SOURCE_DIR}/include/bsc/*.hpp)
if(NOT TARGET bsc::mqtt)  # they include <mosquitto.h>
  list(REMOVE_ITEM bsc_strict_headers bsc/mqtt.hpp bsc/net/mosquitto_transport.hpp)
endif()
if(NOT TARGET bsc::hana)  # it includes Boost.Hana
  list(REMOVE_ITEM bsc_strict_headers bsc/adapt/hana.hpp)
endif()
list(SORT bsc_strict_headers)
set(bsc_strict_includes "")
foreach(header IN LISTS bsc_strict_headers)
  string(APPEND bsc_strict_includes "#include <${header}>\n")
endforeach()
file(CONFIGURE OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/strict/all_headers.cpp @ONLY CONTENT "${bsc_strict_includes}")
# The same headers in the reverse order: a header must not depend on what happened to be
# included before it (a name of bsc::detail hiding a public one, for instance).
list(REVERSE bsc_strict_headers)
set(bsc_strict_includes "")
foreach(header IN LISTS bsc_strict_headers)
  string(APPEND bsc_strict_includes "#include <${header}>\n")
endforeach()
file(CONFIGURE OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/strict/all_headers_reversed.cpp @ONLY CONTENT "${bsc_strict_includes}")

add_library(bsc_strict_warnings OBJECT
  ${CMAKE_CURRENT_BINARY_DIR}/strict/all_headers.cpp
  ${CMAKE_CURRENT_BINARY_DIR}/strict/all_headers_reversed.cpp
  strict/strict_use.cpp
  strict/no_exceptions.cpp)
set_source_files_properties(strict/no_exceptions.cpp PROPERTIES COMPILE_OPTIONS -fno-exceptions)
target_link_libraries(bsc_strict_warnings PRIVATE bsc::bsc)
if(TARGET bsc::mqtt)
  target_link_libraries(bsc_strict_warnings PRIVATE bsc::mqtt)
endif()
if(TARGET bsc::hana)
  target_link_libraries(bsc_strict_warnings PRIVATE bsc::hana)
endif()
target_include_directories(bsc_strict_warnings PRIVATE ${PROJECT_SOURCE_DIR}/examples)
target_compile_options(bsc_strict_warnings PRIVATE ${BSC_STRICT_WARNING_FLAGS})
# GCC 12's false -Wrestrict on inlined std::string concatenation (see cmake/bscWarnings.cmake).
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  target_compile_options(bsc_strict_warnings PRIVATE -Wno-restrict)
endif()
add_test(NAME strict_warnings
  COMMAND ${CMAKE_COMMAND} --build ${CMAKE_BINARY_DIR} --target bsc_strict_warnings --config $<CONFIG>)
