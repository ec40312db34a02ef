#pragma once
// Observer hooks: entry, exit and transition notifications for traces and tests. An
// observer implements any subset of the hooks; a machine without one pays nothing.

#include <string_view>

#include <bsc/detail/type_name.hpp>

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
/// where `state`, `source` and `target` are bsc::state_tag<S> (target: state_tag<bsc::internal>
/// for an internal transition) and `event` is the event (bsc::eventless for eventless ones).
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
concept observes_rows = requires(O& o) {
    o.on_row(0);
};
}  // namespace detail

}  // namespace bsc
