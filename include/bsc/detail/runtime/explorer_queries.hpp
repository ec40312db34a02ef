#pragma once
// What only the explorer (bsc::verify, through detail::access) asks of a machine: its
// configuration with the bytes that can no longer matter reset, whether a timeout's age still
// matters, and the delays of the timeout rows. A layer of the driver (detail/runtime/driver.hpp).

#include <array>
#include <cstddef>

#include <bsc/detail/runtime/timeouts.hpp>
#include <bsc/duration.hpp>

namespace bsc::detail {

template <class Backend, class Chart, class Policy, class Observer, class Queue>
class explorer_queries : public timeouts<Backend, Chart, Policy, Observer, Queue> {
    using base = timeouts<Backend, Chart, Policy, Observer, Queue>;

protected:
    using base::base;
    using typename base::model;
    using typename base::layout;
    using typename base::configuration_type;
    using base::tree;
    using base::state_count;
    using base::config_;
    using base::active_flags;
    using base::row;

    // The configuration with every byte that can never matter again reset to its initial
    // value: the byte of an inactive composite that neither has history (a marker or a history
    // state) nor lies below a deep one. Two machines with equal canonical configurations behave
    // the same.
    constexpr configuration_type canonical_configuration() const {
        configuration_type c = config_;
        if constexpr (tree.slots > 0) {
            auto const active = active_flags();
            for (std::size_t s = 1; s < state_count; ++s) {
                if (tree.slot[s] < 0 || active[s]) continue;
                bool remembered = tree.hist[s] != history::none || layout::history_child[s] >= 0;
                for (int a = tree.parent[s]; a > 0 && !remembered; a = tree.parent[static_cast<std::size_t>(a)])
                    remembered = tree.hist[static_cast<std::size_t>(a)] == history::deep ||
                                 layout::deep_history_child[static_cast<std::size_t>(a)];
                if (!remembered)
                    c.active[static_cast<std::size_t>(tree.slot[s])] =
                        layout::initial_bytes[static_cast<std::size_t>(tree.slot[s])];
            }
        }
        return c;
    }

    // A timeout slot's age matters only while its state is active.
    constexpr bool timeout_armed(std::size_t slot) const {
        auto const active = active_flags();
        if constexpr (layout::timeout_slots > 0)
            return slot < layout::timeout_slot_state.size() &&
                   active[static_cast<std::size_t>(layout::timeout_slot_state[slot])];
        else
            return false;
    }

    // The longest delay of any timeout row: past it, a state's age no longer matters.
    constexpr duration longest_timeout() const {
        duration longest{};
        for (duration delay : row_delays())
            if (delay > longest) longest = delay;
        return longest;
    }

    // Each row's delay: a timeout row's, zero for the others.
    constexpr std::array<duration, static_cast<std::size_t>(model::R)> row_delays() const {
        std::array<duration, static_cast<std::size_t>(model::R)> delays{};
        // clang-format off
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            [[maybe_unused]] int const read[] = {(  // (a list: detail::max_fold)
                [&] {
                    if constexpr (layout::is_timeout_row(static_cast<int>(I)))
                        delays[I] = this->template row<static_cast<int>(I)>().trigger_value.delay;
                }(),
                0)...};
        }(std::make_index_sequence<static_cast<std::size_t>(model::R)>{});
        // clang-format on
        return delays;
    }

    friend struct access;
};

}  // namespace bsc::detail
