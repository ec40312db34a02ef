# bsc_add_scxml: compiles SCXML documents into bsc charts when a target is built (docs/scxml.md).
#
#   bsc_add_scxml(<target> <document.scxml>...
#                 [NAMESPACE <ns>]              C++ namespace of the chart (default: the file's name)
#                 [ALLOW <finding>...])         findings of bsc's checks the charts allow
#
# Each document becomes <name>.hpp in a directory of the build that the target's include path
# gets, regenerated when the document (or the compiler) changes:
#   #include "door.hpp"   // door::chart, door::machine, door::datamodel, door::events::...
# The compiler is tools/bsc-scxml (a Python 3 script of the standard library only).

include_guard(GLOBAL)
# Python 3.9 (str.removeprefix) is needed only by a project that calls bsc_add_scxml: one that
# does not builds without Python.
# Kept as global properties: a project that adds bsc as a subdirectory calls the function from
# its own directory, where bsc's variables are not seen.
find_package(Python3 3.9 COMPONENTS Interpreter QUIET)
if(Python3_Interpreter_FOUND)
  set_property(GLOBAL PROPERTY BSC_SCXML_PYTHON "${Python3_EXECUTABLE}")
endif()

if(NOT DEFINED BSC_SCXML_COMPILER)
  set(BSC_SCXML_COMPILER "${CMAKE_CURRENT_LIST_DIR}/../tools/bsc-scxml")
endif()
set_property(GLOBAL PROPERTY BSC_SCXML_COMPILER "${BSC_SCXML_COMPILER}")

function(bsc_add_scxml target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "NAMESPACE" "ALLOW")
  if(NOT TARGET ${target})
    message(FATAL_ERROR "bsc_add_scxml: ${target} is not a target")
  endif()
  if(NOT arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "bsc_add_scxml(${target} ...): name at least one SCXML document")
  endif()
  get_property(python GLOBAL PROPERTY BSC_SCXML_PYTHON)
  if(NOT python)
    message(FATAL_ERROR "bsc_add_scxml(${target} ...): bsc-scxml needs Python 3.9 or later, which CMake did not find")
  endif()
  get_property(compiler GLOBAL PROPERTY BSC_SCXML_COMPILER)
  set(out_dir "${CMAKE_CURRENT_BINARY_DIR}/${target}_scxml")
  file(MAKE_DIRECTORY "${out_dir}")
  set(options)
  if(arg_NAMESPACE)
    list(APPEND options --namespace ${arg_NAMESPACE})
  endif()
  if(arg_ALLOW)
    list(JOIN arg_ALLOW "," allowed)
    list(APPEND options --allow ${allowed})
  endif()
  set(headers)
  foreach(document IN LISTS arg_UNPARSED_ARGUMENTS)
    get_filename_component(document "${document}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    get_filename_component(name "${document}" NAME_WE)
    set(header "${out_dir}/${name}.hpp")
    add_custom_command(OUTPUT "${header}"
      COMMAND "${python}" "${compiler}" "${document}" -o "${header}" ${options}
      DEPENDS "${document}" "${compiler}"
      COMMENT "bsc-scxml ${name}.scxml"
      VERBATIM)
    list(APPEND headers "${header}")
  endforeach()
  target_sources(${target} PRIVATE ${headers})
  target_include_directories(${target} PRIVATE "${out_dir}")
endfunction()
