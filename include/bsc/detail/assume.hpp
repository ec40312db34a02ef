#pragma once
// Tells the optimiser a fact the code keeps but cannot show it (a machine's status byte has no
// failure bit set between runs; its queue is empty between runs), so that it drops the tests
// the fact settles. The fact must hold: where it does not, the behaviour is undefined. GCC
// follows what it is told through later tests; Clang drops it where paths join (driver.hpp says
// what it does there instead). A build without NDEBUG tests the fact instead, and stops the
// program where it does not hold.

#include <cassert>

namespace bsc::detail {

[[gnu::always_inline]] constexpr void assume(bool holds) {
#if !defined(NDEBUG)
    assert(holds && "bsc: a machine's invariant is broken: it was called back from inside its own run under a "
                    "policy that does not refuse it, or copied, assigned to or destroyed there");
#elif defined(__clang__)
    __builtin_assume(holds);
#else
    if (!holds) __builtin_unreachable();
#endif
}

}  // namespace bsc::detail
