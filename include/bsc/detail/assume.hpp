#pragma once
// Tells the optimiser a fact the code keeps but cannot show it (a machine's status byte has no
// failure bit set between runs; its queue is empty between runs), so that it drops the tests
// the fact settles. The fact must hold: where it does not, the behaviour is undefined. GCC
// follows what it is told through later tests; Clang drops it where paths join (driver.hpp says
// what it does there instead). A build without NDEBUG tests the fact instead, and stops the
// program where it does not hold. (The compilers' spellings: detail/config.hpp.)

#include <cassert>

#include <bsc/detail/config.hpp>

namespace bsc::detail {

BSC_DETAIL_ALWAYS_INLINE constexpr void assume(bool holds) {
#if !defined(NDEBUG)
    assert(holds &&
           "bsc: a machine's invariant is broken: it was called back from inside its own run under a "
           "policy that does not refuse it, or copied, assigned to or destroyed there");
#else
    BSC_DETAIL_ASSUME(holds);
#endif
}

}  // namespace bsc::detail
