# Project code is held to a warning-free standard; consumers of bsc are not affected.
function(bsc_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Werror)
  # GCC 12 at -O2/-O3 reports overlapping copies inside std::string concatenations it has
  # inlined (a false -Wrestrict, GCC bug 105329, fixed in GCC 13); with -Werror it would stop the
  # release preset on ordinary `a + b` string code in tests and examples.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${target} PRIVATE -Wno-restrict)
  endif()
endfunction()
