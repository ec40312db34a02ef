#pragma once
// Tells the optimiser a fact the code keeps but cannot show it (a machine's status byte has no
// failure bit set between runs), so that it drops the tests the fact settles. The fact must
// hold: where it does not, the behaviour is undefined. GCC follows what it is told through
// later tests; Clang drops it where paths join (driver.hpp says what it does there instead).

namespace bsc::detail {

[[gnu::always_inline]] constexpr void assume(bool holds) {
#if defined(__clang__)
    __builtin_assume(holds);
#else
    if (!holds) __builtin_unreachable();
#endif
}

}  // namespace bsc::detail
