# packaging.standard_library_only: the library's headers (include/ and single_include/) include
# only the standard library, bsc's own headers and, for bsc::mqtt alone, <mosquitto.h>, and for
# bsc::hana alone (include/bsc/adapt/hana.hpp, single_include/bsc/hana.hpp) Boost.Hana's, and for
# the latency benchmark alone (include/bsc/benchmark.hpp and its detail/benchmark/callgrind_counter.hpp)
# Google Benchmark's, valgrind's <valgrind/callgrind.h> and <unistd.h>, and for the inspector's
# server alone (include/bsc/detail/inspector/http.hpp, single_include/bsc/inspector.hpp and system_inspector.hpp) POSIX's sockets. (One header of the standard
# library's own is named: libstdc++'s <bits/chrono.h>, the part of <chrono> bsc uses, included
# only where __GLIBCXX__ says it is libstdc++: BSC_DETAIL_CHRONO_HEADER in detail/config.hpp,
# which detail/chrono.hpp includes.) The single-header consumer
# cannot show it: the system's headers (Boost among them) are on every compiler's default path.
# Run with -DBSC_SOURCE_DIR=... -P standard_library_only.cmake.
file(GLOB_RECURSE headers ${BSC_SOURCE_DIR}/include/*.hpp ${BSC_SOURCE_DIR}/single_include/*.hpp)
set(offending)
foreach(header IN LISTS headers)
  file(STRINGS ${header} includes REGEX "^[ \t]*#[ \t]*include[ \t]*<")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*<([^>]+)>.*" "\\1" name "${line}")
    # Standard headers have no extension and no directory (c++ headers) or are C headers in <c...>.
    if(name MATCHES "^bsc/" OR name STREQUAL "mosquitto.h" OR name STREQUAL "bits/chrono.h"
       OR NOT name MATCHES "[./]")
      continue()
    endif()
    if(header MATCHES "/(include/bsc/adapt|single_include/bsc)/hana\\.hpp$" AND name MATCHES "^boost/hana/")
      continue()
    endif()
    # The latency benchmark (opt-in, include/ only): Google Benchmark, and valgrind's client
    # requests with the process id they need, where __has_include finds them.
    if(header MATCHES "/include/bsc/benchmark\\.hpp$" AND name STREQUAL "benchmark/benchmark.h")
      continue()
    endif()
    if(header MATCHES "/include/bsc/detail/benchmark/callgrind_counter\\.hpp$"
       AND (name STREQUAL "valgrind/callgrind.h" OR name STREQUAL "unistd.h"))
      continue()
    endif()
    # The inspector's server (opt-in, POSIX): the socket interface.
    if(header MATCHES "/(include/bsc/detail/inspector/http|single_include/bsc/(system_)?inspector)\\.hpp$"
       AND name MATCHES "^(arpa/inet|netinet/in|poll|sys/socket|unistd)\\.h$")
      continue()
    endif()
    list(APPEND offending "${header}: #include <${name}>")
  endforeach()
endforeach()
if(offending)
  list(JOIN offending "\n" text)
  message(FATAL_ERROR "headers that include more than the standard library:\n${text}")
endif()
list(LENGTH headers count)
message(STATUS "${count} headers include the standard library and bsc only")
