#pragma once
// The contract between the driver (detail/runtime/driver.hpp) and a back end. A back end derives
// from the driver (CRTP) and supplies what differs between back ends: how a transition is
// selected and fired, how states are entered and left, how a component takes its turn in a cycle.
// backend_hooks names each hook once, with what it does; machine_backend is the contract, which
// the driver checks when a machine is built. A back end befriends backend_hooks and the driver's
// layers that call the hooks (driver, settling, deferral, done_raising).
//
// (The layers call the hooks directly, not through backend_hooks: given the forwarding
// functions, Clang 14 laid out the MCS workload's dispatch with 19% more instructions per event,
// and GCC 12, with them forced inline, 7% more; perf.instructions holds it.)

#include <concepts>

#include <bsc/detail/model/chart_model.hpp>
#include <bsc/events.hpp>

namespace bsc::detail {

struct backend_hooks {
    // Whether a dispatch marks the machine running only once it is about to run a guard or a
    // transition (a back end that tells an ignored event without running anything).
    template <class B>
    static constexpr bool marks_running_lazily = B::marks_running_lazily;
    // Enters the root and its default completion, entry actions and all; settles nothing.
    template <class B>
    static constexpr auto enter_initial(B& b) -> decltype(b.enter_initial()) {
        b.enter_initial();
    }
    // Selects and fires the transitions that e enables (Trigger: the event's position in the
    // chart, or eventless_id), without settling; true if one fired.
    template <int Trigger, class B, class E>
    static constexpr auto fire(B& b, E const& e) -> decltype(b.template fire<Trigger>(e)) {
        return b.template fire<Trigger>(e);
    }
    // fire() for the event a dispatch takes (a back end may lay that call out differently).
    template <int Trigger, class B, class E>
    static constexpr auto fire_dispatched(B& b, E const& e) -> decltype(b.template fire_dispatched<Trigger>(e)) {
        return b.template fire_dispatched<Trigger>(e);
    }
    // Component's turn in a BSC cycle (the root, or a region of a parallel state): at most one
    // eventless or timeout transition; true if one fired.
    template <int Component, class B>
    static constexpr auto component_step(B& b) -> decltype(b.template component_step<Component>()) {
        return b.template component_step<Component>();
    }
    // Whether state S (its index in the chart's model) is active.
    template <int S, class B>
    static constexpr auto is_active(B const& b) -> decltype(b.template is_active<S>()) {
        return b.template is_active<S>();
    }
    // The machine halts: every active state's exit actions, innermost first.
    template <class B>
    static constexpr auto exit_all(B& b) -> decltype(b.exit_all()) {
        b.exit_all();
    }
};

// What a back end B supplies: each hook of backend_hooks, with its result type. Checked by the driver's
// constructor, where B is complete: a back end that misses a hook fails there, naming this
// concept and the hook.
template <class B>
concept machine_backend = requires(B& b, B const& const_b) {
    { backend_hooks::marks_running_lazily<B> } -> std::convertible_to<bool>;
    { backend_hooks::enter_initial(b) } -> std::same_as<void>;
    { backend_hooks::fire<eventless_id>(b, eventless{}) } -> std::same_as<bool>;
    { backend_hooks::fire_dispatched<eventless_id>(b, eventless{}) } -> std::same_as<bool>;
    { backend_hooks::component_step<0>(b) } -> std::same_as<bool>;
    { backend_hooks::is_active<0>(const_b) } -> std::same_as<bool>;
    { backend_hooks::exit_all(b) } -> std::same_as<void>;
};

}  // namespace bsc::detail
