#pragma once
// std::chrono's durations, time points, clocks and literals, without the rest of <chrono>.
// Since C++20, libstdc++'s <chrono> also brings calendars, time zones and formatting (with
// <string> and <sstream>): 0.17 s of CPU in every translation unit that includes bsc, against
// 0.03 s for the part bsc uses, which libstdc++ keeps in a header of its own, named by
// BSC_DETAIL_CHRONO_HEADER (detail/config.hpp). Other standard libraries get <chrono> itself.

#include <bsc/detail/config.hpp>

#include BSC_DETAIL_CHRONO_HEADER
