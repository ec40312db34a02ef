#pragma once
// std::chrono's durations, time points, clocks and literals, without the rest of <chrono>.
// Since C++20, libstdc++'s <chrono> also brings calendars, time zones and formatting (with
// <string> and <sstream>): 0.17 s of CPU in every translation unit that includes bsc, against
// 0.03 s for the part bsc uses, which libstdc++ keeps in <bits/chrono.h>. Other standard
// libraries get <chrono> itself.

#include <version>  // defines __GLIBCXX__ where the library is libstdc++

#if defined(__GLIBCXX__) && __has_include(<bits/chrono.h>)
#include <bits/chrono.h>
#else
#include <chrono>
#endif
