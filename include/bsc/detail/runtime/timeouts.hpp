#pragma once
// Timeouts (`after(delay)` rows): a state's timeouts count from its entry, a timeout is due once
// its delay has elapsed at the time of the last cycle, a due timeout that leaves its state active
// counts again from then, and of a state's timeouts due at once the first to come due fires. The
// back ends say when (a state entered, a timeout row tried or fired); the rule is here, once.
// Slots are numbered as detail/model/layout.hpp numbers them. A layer of the driver
// (detail/runtime/driver.hpp).

#include <cstddef>

#include <bsc/detail/runtime/machine_data.hpp>
#include <bsc/duration.hpp>

namespace bsc::detail {

template <class Backend, class Chart, class Policy, class Observer, class Queue>
class timeouts : public machine_data<Backend, Chart, Policy, Observer, Queue> {
    using base = machine_data<Backend, Chart, Policy, Observer, Queue>;

protected:
    using base::base;
    using base::armed_;
    using base::cycle_time;

    // A state was entered: its timeouts, slots first_slot to first_slot + count - 1, count from
    // now (the time of the last cycle).
    constexpr void arm_timeouts(int first_slot, int count) {
        for (int k = 0; k < count; ++k) armed_[static_cast<std::size_t>(first_slot + k)] = cycle_time();
    }

    // Whether the timeout in `slot`, of `delay`, is due: its state has been active for the delay.
    constexpr bool timeout_due(int slot, duration delay) const {
        return has_elapsed(armed_[static_cast<std::size_t>(slot)], cycle_time(), delay);
    }

    // A timeout fired and its state stays active (layout.hpp, rearms): it counts again from now.
    constexpr void rearm_timeout(int slot) { armed_[static_cast<std::size_t>(slot)] = cycle_time(); }

    // Of two due timeouts of one state, whether the one in `slot` (of `delay`) came due before the
    // one in `other_slot` (of `other_delay`), the one declared first: then it fires instead
    // (detail::came_due_first says how a tie is broken).
    constexpr bool came_due_before(int slot, duration delay, int other_slot, duration other_delay) const {
        return came_due_first(armed_[static_cast<std::size_t>(slot)], delay,
                              armed_[static_cast<std::size_t>(other_slot)], other_delay);
    }
};

}  // namespace bsc::detail
