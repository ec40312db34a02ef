#pragma once
// Observer hooks: entry, exit and transition notifications for traces and tests. An
// observer implements any subset of the hooks; a machine without one pays nothing.

#include <string_view>

#include <bsc/detail/type_name.hpp>
#include <bsc/duration.hpp>
#include <bsc/events.hpp>

namespace bsc {

/// Identifies a state in observer calls: `tag.name` is its unqualified name, `type` the state.
template <class S>
struct state_tag {
    using type = S;
    static constexpr std::string_view name = name_of<S>;
};

/// The target reported for an internal transition, which exits and enters nothing.
struct internal {};

/// The default observer: no hooks, no cost.
struct no_observer {};

/// An observer may define, each optional:
///   void on_entry(auto state);              // after state's entry actions
///   void on_exit(auto state);               // after state's exit actions
///   void on_transition(auto source, auto target, auto const& event);  // before the action
///   void on_row(int row);                   // the same moment: the row's position in make_chart
///   void on_guard(std::string_view guard);  // just before on_transition, for a row with a guard:
///                                           // the guard as the exports write it, e.g. "released",
///                                           // "!released && ready", "guard" when no part has a name
///   void on_defer(auto source, auto const& event);  // just before on_transition, for a row
///                                           // that defers the event (`/ bsc::defer`)
///   void on_dispatch(auto const& event);    // dispatch(event) begins (not when refused)
///   void on_cycle(bsc::duration now);       // step(now) begins, with the cycle's time
///   void on_cycle_end();                    // that cycle's outputs are committed
/// where `state`, `source` and `target` are bsc::state_tag<S> (target: state_tag<bsc::internal>
/// for an internal transition) and `event` is the event: bsc::eventless for an eventless row,
/// bsc::timeout_elapsed{delay} for a timeout row. A hook the observer lacks costs nothing.
/// The time of a dispatch is the machine's clock, now(): the time of the last cycle (a machine
/// that keeps no clock, policy keep_clock, has none: its on_cycle gets the caller's time).
namespace detail {
template <class O, class Tag>
concept observes_entry = requires(O& o) {
    o.on_entry(Tag{});
};
template <class O, class Tag>
concept observes_exit = requires(O& o) {
    o.on_exit(Tag{});
};
template <class O, class Src, class Dst, class E>
concept observes_transition = requires(O& o, E const& e) {
    o.on_transition(Src{}, Dst{}, e);
};
template <class O>
concept observes_guards = requires(O& o, std::string_view text) {
    o.on_guard(text);
};
template <class O, class Src, class E>
concept observes_deferrals = requires(O& o, E const& e) {
    o.on_defer(Src{}, e);
};
template <class O>
concept observes_rows = requires(O& o) {
    o.on_row(0);
};
template <class O, class E>
concept observes_dispatch = requires(O& o, E const& e) {
    o.on_dispatch(e);
};
template <class O>
concept observes_cycles = requires(O& o) {
    o.on_cycle(duration{});
};
template <class O>
concept observes_cycle_ends = requires(O& o) {
    o.on_cycle_end();
};
}  // namespace detail

}  // namespace bsc
