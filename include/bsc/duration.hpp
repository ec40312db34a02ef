#pragma once
// bsc::duration: the machine's notion of time. The library never reads a clock: time is given
// to step(now) by the caller, so simulations and tests are deterministic. The caller's time
// may start anywhere (negative times included): a machine's clock starts at its first cycle.

#include <cstdint>
#include <limits>

#include <bsc/detail/chrono.hpp>

namespace bsc {

/// A duration since an origin the caller chooses, as given to step(now).
using duration = std::chrono::nanoseconds;

}  // namespace bsc

namespace bsc::detail {

// Whether at least `delay` (>= 0) has passed from `since` to `now` (since <= now), without
// the overflow of `now - since` when the two lie far apart: the difference is exact in
// unsigned arithmetic.
constexpr bool has_elapsed(duration since, duration now, duration delay) {
    if (now < since) return false;
    auto const passed = static_cast<std::uint64_t>(now.count()) - static_cast<std::uint64_t>(since.count());
    return passed >= static_cast<std::uint64_t>(delay.count());
}

// t + shift, saturated at duration::min() and duration::max(): a far-off time must not overflow.
constexpr duration shifted(duration t, duration shift) {
    auto const a = t.count();
    auto const b = shift.count();
    using limits = std::numeric_limits<duration::rep>;
    if (b > 0 && a > limits::max() - b) return duration::max();
    if (b < 0 && a < limits::min() - b) return duration::min();
    return duration{a + b};
}

// to - from, saturated at duration::min() and duration::max(), as shifted.
constexpr duration difference(duration to, duration from) {
    auto const a = to.count();
    auto const b = from.count();
    using limits = std::numeric_limits<duration::rep>;
    if (b < 0 && a > limits::max() + b) return duration::max();
    if (b > 0 && a < limits::min() + b) return duration::min();
    return duration{a - b};
}

// Whether t + shift lies past duration::max(): a time no clock of a machine ever reaches (a
// delayed event due then never comes due). A shift below duration::min() is not "past".
constexpr bool shifted_past_max(duration t, duration shift) {
    return shift.count() > 0 && t.count() > std::numeric_limits<duration::rep>::max() - shift.count();
}

// Whether a timeout armed at `since` with `delay` came due before one armed at `other_since`
// with `other_delay`: the earlier due time (since + delay), and at equal due times the earlier
// arming. Both are due (has_elapsed at the same time), so neither sum lies past that time: no
// overflow.
constexpr bool came_due_first(duration since, duration delay, duration other_since, duration other_delay) {
    duration const due = since + delay;
    duration const other_due = other_since + other_delay;
    return due < other_due || (due == other_due && since < other_since);
}

// `now - since` (since <= now), saturated at duration::max().
constexpr duration elapsed(duration since, duration now) {
    if (now <= since) return duration::zero();
    auto const passed = static_cast<std::uint64_t>(now.count()) - static_cast<std::uint64_t>(since.count());
    auto const max = static_cast<std::uint64_t>(duration::max().count());
    return duration{static_cast<duration::rep>(passed > max ? max : passed)};
}

}  // namespace bsc::detail
