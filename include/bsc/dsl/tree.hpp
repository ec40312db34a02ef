#pragma once
// The state tree: the chart's first table. Declarations are empty objects whose types
// carry the structure (BSC's S, p and delta): basic, final, composite (OR) and parallel (AND)
// states, initial children and history.

#include <cstdint>
#include <type_traits>

#include <bsc/error.hpp>
#include <bsc/detail/meta.hpp>
#include <bsc/dsl/state.hpp>

namespace bsc::detail {

enum class kind : std::uint8_t { top, basic, final_state, composite, parallel, history };
enum class history : std::uint8_t { none, shallow, deep };

struct node_base {};

// A basic or final state. Implicit: declared by `initial<S>` alone, with no declaration of its own.
template <class S, kind K, bool Implicit = false>
struct leaf_node : node_base {
    using tag = S;
    static constexpr kind node_kind = K;
    static constexpr history hist = history::none;
    static constexpr bool implicit = Implicit;
    using initials = type_list<>;
    using children = type_list<>;
};

template <class S, history H, class Initials, class Children, class MoreInitials = type_list<>>
struct composite_node : node_base {
    using tag = S;
    static constexpr kind node_kind = kind::composite;
    static constexpr history hist = H;
    static constexpr bool implicit = false;
    using initials = Initials;
    using children = Children;
    // The initial states after the first, one in each region of a parallel state below
    // (`bsc::initial<A, B>`, SCXML's initial="a b").
    using more_initials = MoreInitials;
};

template <class S, class Children>
struct parallel_node : node_base {
    using tag = S;
    static constexpr kind node_kind = kind::parallel;
    static constexpr history hist = history::none;
    static constexpr bool implicit = false;
    using initials = type_list<>;
    using children = Children;
};

// A history pseudo-state of the enclosing composite: never active; entering it restores the
// composite's remembered configuration, or enters Default when there is none.
template <class S, history H, class Default>
struct history_node : node_base {
    using tag = S;
    using default_state = Default;
    static constexpr kind node_kind = kind::history;
    static constexpr history hist = H;
    static constexpr bool implicit = false;
    using initials = type_list<>;
    using children = type_list<>;
};

template <class S, class... More>
struct initial_marker {
    using tag = S;
    using more = type_list<More...>;
};
template <history H>
struct history_marker {};

template <class A>
inline constexpr bool is_node = std::is_base_of_v<node_base, A>;
template <class A>
inline constexpr bool is_state_ref = false;
template <class S>
inline constexpr bool is_state_ref<state_ref<S>> = true;
template <class A>
inline constexpr bool is_initial_marker = false;
template <class S, class... More>
inline constexpr bool is_initial_marker<initial_marker<S, More...>> = true;
template <class A>
inline constexpr bool is_history_marker = false;
template <history H>
inline constexpr bool is_history_marker<history_marker<H>> = true;

template <class A>
struct tag_of {
    using type = typename A::tag;
};
template <class S>
struct tag_of<state_ref<S>> {
    using type = S;
};

// The tags of a node and of everything below it.
template <class Node>
constexpr auto subtree_tags();
template <class... C>
constexpr auto subtree_tags_of(type_list<C...>) {
    return concat_t<decltype(subtree_tags<C>())...>{};
}
template <class Node>
constexpr auto subtree_tags() {
    return concat_t<type_list<typename Node::tag>, decltype(subtree_tags_of(typename Node::children{}))>{};
}
// Whether argument A declares S below itself; whether one of the arguments does (S is then a
// deep initial's target). (A function of one argument, not a lambda inside declared_below,
// whose symbol would spell every argument.)
template <class S, class A>
constexpr bool declares_below() {
    if constexpr (is_node<A>)
        return position_in<S, decltype(subtree_tags<A>())>::value >= 0;
    else
        return false;
}
template <class S, class... A>
constexpr bool declared_below(type_list<A...>) {
    return any_true({declares_below<S, A>()..., false});
}

// The child declarations an argument of composite<S>(...) contributes, in document order.
// An initial<X> declares X only if no argument declares it, as a child or below one (a deep
// initial), and no earlier initial<X> did. (The tags below are searched only for an initial
// that is not a child: most charts never pay for it.)
template <class A, bool FirstOfItsKind, class Args, class... Declared>
constexpr auto children_from_initial() {
    using S = typename tag_of<A>::type;
    if constexpr (any_true({std::is_same_v<S, Declared>..., false}) || !FirstOfItsKind)
        return type_list<>{};
    else if constexpr (declared_below<S>(Args{}))
        return type_list<>{};
    else
        return type_list<leaf_node<S, kind::basic, true>>{};
}
template <class A>
constexpr auto children_from() {
    if constexpr (is_node<A>)
        return type_list<A>{};
    else if constexpr (is_state_ref<A>)
        return type_list<leaf_node<typename A::tag, kind::basic>>{};
    else
        return type_list<>{};
}

template <std::size_t I, class... A>
constexpr bool first_of_its_kind() {
    using list = type_list<A...>;
    return position_in<at<I, list>, list>::value == static_cast<int>(I);
}

template <class A>
constexpr auto initials_from() {
    if constexpr (is_initial_marker<A>)
        return type_list<typename tag_of<A>::type>{};
    else
        return type_list<>{};
}

template <class A>
constexpr auto more_initials_from() {
    if constexpr (is_initial_marker<A>)
        return typename A::more{};
    else
        return type_list<>{};
}

template <class A>
constexpr auto declared_tag() {
    if constexpr (is_node<A> || is_state_ref<A>)
        return type_list<typename tag_of<A>::type>{};
    else
        return type_list<>{};
}

template <class... A>
constexpr history history_from() {
    history h = history::none;
    // (In order, as a list: detail::max_fold.)
    [[maybe_unused]] history const seen[] = {
        (h = std::is_same_v<A, history_marker<history::deep>>      ? history::deep
             : std::is_same_v<A, history_marker<history::shallow>> ? history::shallow
                                                                   : h)...,
        h};
    return h;
}

// The children argument I (A) contributes. Only an initial<X> needs the other arguments; the
// choice is a class, which makes no symbol, so that an ordinary argument's functions do not
// spell every argument in their names (building those names was a quadratic part of a large
// chart's compile time).
template <class A, std::size_t I, class Args, class Declared, bool = is_initial_marker<A>>
struct children_of_argument {
    using type = decltype(children_from<A>());
};
template <class A, std::size_t I, class... Args, class... Declared>
struct children_of_argument<A, I, type_list<Args...>, type_list<Declared...>, true> {
    using type = decltype(children_from_initial<A, first_of_its_kind<I, Args...>(), type_list<Args...>, Declared...>());
};

template <class Tags, class Seq, class... A>
struct composite_children;
template <class... Declared, std::size_t... I, class... A>
struct composite_children<type_list<Declared...>, std::index_sequence<I...>, A...> {
    using type = concat_t<typename children_of_argument<A, I, type_list<A...>, type_list<Declared...>>::type...>;
};

}  // namespace bsc::detail

namespace bsc {

/// Names the initial (default) state of a composite state: a child, or a deeper descendant (a
/// deep initial, SCXML's `<initial>` whose transition targets a descendant: entering the
/// composite by default enters the path down to it, the other regions of parallel states on
/// the way by default). If S is declared nowhere among the composite's arguments,
/// `initial<S>` also declares S as a basic child.
///
/// `initial<A, B, ...>` names several, one in each of orthogonal regions below the composite
/// (SCXML's `initial="a b"`): entering the composite by default enters each, and the regions
/// that hold none by default. At most 4 (bsc::error::initial_states_not_orthogonal if two are not
/// in different regions of a parallel state).
template <class S, class... More>
inline constexpr detail::initial_marker<S, More...> initial{};

/// Marks a composite state as remembering its last active child (restored on re-entry).
inline constexpr detail::history_marker<detail::history::shallow> shallow_history{};

/// Marks a composite state as remembering its whole last active sub-configuration.
inline constexpr detail::history_marker<detail::history::deep> deep_history{};

/// A shallow history pseudo-state H of the composite it is declared in (SCXML's
/// `<history type="shallow">`): a transition to H enters the composite in the child it was last
/// in (that child by default), or, if the composite was never active, enters Default (a state
/// inside the composite) after running H's `state<H> + on_initial / action` rows. H is never
/// active itself and takes no other rows. A composite may have several history states.
/// Requirements: declared in a composite, Default inside it (bsc::error::invalid_history_state).
template <class H, class Default>
inline constexpr detail::history_node<H, detail::history::shallow, Default> shallow_history_state{};

/// A deep history pseudo-state H (SCXML's `<history type="deep">`): as shallow_history_state,
/// but a transition to H restores the whole sub-configuration the composite was last in.
template <class H, class Default>
inline constexpr detail::history_node<H, detail::history::deep, Default> deep_history_state{};

/// A final state: reaching it is an intended end, so it is exempt from the dead-end check.
/// A final child of the root state halts the machine.
template <class S>
inline constexpr detail::leaf_node<S, detail::kind::final_state> final_state{};

/// A composite (OR, exclusive) state: exactly one child is active while it is.
template <class S, class... A>
constexpr auto composite(A...) {
    // (Lists, not fold expressions, here and below: a composite may have more children than
    // Clang nests a fold, 256, and GCC's time grows faster than the length of a fold.)
    constexpr bool all_valid = detail::all_true({(detail::is_node<A> || detail::is_state_ref<A> ||
                                                  detail::is_initial_marker<A> || detail::is_history_marker<A>)...});
    constexpr int history_markers = detail::count_true({detail::is_history_marker<A>..., false});
    if constexpr (!all_valid) {
        constexpr int bad = detail::position_in<
            std::false_type, detail::type_list<std::bool_constant<detail::is_node<A> || detail::is_state_ref<A> ||
                                                                  detail::is_initial_marker<A> ||
                                                                  detail::is_history_marker<A>>...>>::value;
        detail::report<
            error::not_a_state_declaration<S, detail::at<static_cast<std::size_t>(bad), detail::type_list<A...>>>>();
    } else if constexpr (history_markers > 1) {
        detail::report<error::conflicting_history_markers<S>>();
    }
    using declared = detail::concat_t<decltype(detail::declared_tag<A>())...>;
    using children = typename detail::composite_children<declared, std::index_sequence_for<A...>, A...>::type;
    using initials = detail::concat_t<decltype(detail::initials_from<A>())...>;
    using more_initials = detail::concat_t<decltype(detail::more_initials_from<A>())...>;
    static_assert(more_initials::size <= 3, "bsc::initial takes at most 4 states");
    return detail::composite_node<S, detail::history_from<A...>(), initials, children, more_initials>{};
}

/// A parallel (AND) state: all of its children (its components, or regions) are active while it is.
template <class S, class... A>
constexpr auto parallel(A...) {
    constexpr bool all_valid = detail::all_true({(detail::is_node<A> || detail::is_state_ref<A>)...});
    if constexpr (!all_valid) {
        constexpr int bad = detail::position_in<
            std::false_type,
            detail::type_list<std::bool_constant<detail::is_node<A> || detail::is_state_ref<A>>...>>::value;
        detail::report<
            error::not_a_state_declaration<S, detail::at<static_cast<std::size_t>(bad), detail::type_list<A...>>>>();
    } else if constexpr (sizeof...(A) == 0) {
        detail::report<error::empty_parallel_state<S>>();
    }
    using children = detail::concat_t<decltype(detail::children_from<A>())...>;
    return detail::parallel_node<S, children>{};
}

}  // namespace bsc
