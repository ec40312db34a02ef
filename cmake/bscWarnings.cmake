# Project code is held to a warning-free standard; consumers of bsc are not affected.
function(bsc_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Werror)
endfunction()
