#pragma once
// bsc - Basic Statecharts, single-header distribution.
// Generated from include/bsc/bsc.hpp by `python3 scripts/amalgamate.py`.
// Do not edit: change the headers under include/ and regenerate.
// begin include/bsc/bsc.hpp
// bsc: Basic Statecharts for C++20. Include this header to get the whole library.

// begin include/bsc/allow.hpp
// bsc::allow: a chart's explicit allowance of findings of the static checks that it accepts by
// design, as a chart compiled from an SCXML document does (SCXML accepts states never entered
// and transitions that never fire).

#include <cstddef>

// begin include/bsc/detail/meta.hpp
// Small type-level toolkit: type lists, lookup by type and by position.
// Everything heavier than this is done by constexpr functions over arrays.

#include <cstddef>
#include <initializer_list>
#include <type_traits>
#include <utility>

// begin include/bsc/detail/config.hpp
// How bsc spells what compilers spell differently: the attributes that steer inlining, the
// built-ins it uses where the standard spelling costs compile time, the signature a type's name
// is read from, and the part of <chrono> it includes. Every such spelling is here and nowhere
// else. GCC and Clang get the spellings bsc's instruction counts and compile times were
// measured with (docs/performance.md); any other compiler gets the standard spelling, or
// nothing where an optimisation hint has none (the same behaviour, possibly slower code).

#include <version>  // defines __GLIBCXX__ where the standard library is libstdc++

// ---- inlining ------------------------------------------------------------------------------------
// BSC_DETAIL_ALWAYS_INLINE: the function is inlined wherever it is called.
// BSC_DETAIL_NOINLINE: the function is never inlined.
// BSC_DETAIL_FLATTEN: every call in the function's body is inlined into it, whatever the
//   inlining budget (GCC: and every call below those; Clang: only the calls written in the body).
//   Nothing where the build optimises for size (-Os, __OPTIMIZE_SIZE__): a flattened firing copies
//   every exit and entry path into each event's function (docs/performance.md, "A firing is one
//   flattened function").
// BSC_DETAIL_WALK_INLINE: on the functions and lambdas of the compiled back end's walk of the
//   configuration, which a flattened firing is made of. Under GCC, whose `flatten` reaches
//   every call below, it adds nothing; under Clang the walk's functions are always inlined
//   themselves (docs/performance.md, rule "Walk inlined under Clang"). In the GNU spelling,
//   which a lambda takes after its parameters.
// BSC_DETAIL_VISIT_INLINE: on the functions that hand a context's fields to a visitor. Clang 14
//   leaves the visit out of line unless told; GCC 12 inlines it where that pays, and forced,
//   costs more (docs/performance.md, rule "Fields visited without a tuple").
#if defined(__GNUC__) || defined(__clang__)
#define BSC_DETAIL_ALWAYS_INLINE [[gnu::always_inline]]
#define BSC_DETAIL_NOINLINE [[gnu::noinline]]
#if defined(__OPTIMIZE_SIZE__)
#define BSC_DETAIL_FLATTEN
#else
#define BSC_DETAIL_FLATTEN [[gnu::flatten]]
#endif
#else
#define BSC_DETAIL_ALWAYS_INLINE
#define BSC_DETAIL_NOINLINE
#define BSC_DETAIL_FLATTEN
#endif
#if defined(__clang__)
#define BSC_DETAIL_WALK_INLINE __attribute__((always_inline))
#define BSC_DETAIL_VISIT_INLINE [[gnu::always_inline]]
#else
#define BSC_DETAIL_WALK_INLINE
#define BSC_DETAIL_VISIT_INLINE
#endif

// ---- what the optimiser is told ------------------------------------------------------------------
// BSC_DETAIL_ASSUME(cond): the optimiser may take cond as true (a statement; cond is not
//   evaluated and must hold, or the behaviour is undefined). bsc calls it through
//   detail::assume (detail/assume.hpp), which checks cond instead in builds without NDEBUG.
// BSC_DETAIL_ASSUMPTION_SURVIVES_JOINS: 1 where the optimiser follows an assumption through
//   later tests, past the joins of paths (GCC); 0 where it drops it at the first join (Clang),
//   or is not known to keep it: there bsc stores what it would have assumed (detail/runtime/run_control.hpp).
#if defined(__clang__)
#define BSC_DETAIL_ASSUME(cond) __builtin_assume(cond)
#define BSC_DETAIL_ASSUMPTION_SURVIVES_JOINS 0
#elif defined(__GNUC__)
#define BSC_DETAIL_ASSUME(cond)               \
    do {                                      \
        if (!(cond)) __builtin_unreachable(); \
    } while (false)
#define BSC_DETAIL_ASSUMPTION_SURVIVES_JOINS 1
#elif defined(_MSC_VER)
#define BSC_DETAIL_ASSUME(cond) __assume(cond)
#define BSC_DETAIL_ASSUMPTION_SURVIVES_JOINS 0
#else
#define BSC_DETAIL_ASSUME(cond) static_cast<void>(sizeof(cond))
#define BSC_DETAIL_ASSUMPTION_SURVIVES_JOINS 0
#endif

// ---- type traits as built-ins ----------------------------------------------------------------------
// BSC_DETAIL_IS_SAME(A, B), BSC_DETAIL_IS_BASE_OF(Base, Derived), BSC_DETAIL_IS_CLASS(T): the
// values of std::is_same_v, std::is_base_of_v and std::is_class_v, as the compiler's built-ins
// where it has them: a built-in instantiates no class template, which a chart's analysis would
// otherwise do once per pair of types it compares (docs/performance.md,
// rule "No template per lookup").
#if defined(__GNUC__) || defined(__clang__)
#define BSC_DETAIL_TRAIT_BUILTINS 1
#elif defined(__has_builtin)
#if __has_builtin(__is_same) && __has_builtin(__is_base_of) && __has_builtin(__is_class)
#define BSC_DETAIL_TRAIT_BUILTINS 1
#endif
#endif
#if defined(BSC_DETAIL_TRAIT_BUILTINS)
#define BSC_DETAIL_IS_SAME(A, B) __is_same(A, B)
#define BSC_DETAIL_IS_BASE_OF(Base, Derived) __is_base_of(Base, Derived)
#define BSC_DETAIL_IS_CLASS(T) __is_class(T)
#else
#include <type_traits>
#define BSC_DETAIL_IS_SAME(A, B) (std::is_same_v<A, B>)
#define BSC_DETAIL_IS_BASE_OF(Base, Derived) (std::is_base_of_v<Base, Derived>)
#define BSC_DETAIL_IS_CLASS(T) (std::is_class_v<T>)
#endif
// BSC_DETAIL_TYPE_PACK_ELEMENT(I, Ts...): the I-th of Ts, a built-in where the compiler has one
// (Clang), for detail::at: the lookup by overload resolution among every element that it
// replaces took Clang 5 ms per row of a 200-row chart.
#if defined(__has_builtin)
#if __has_builtin(__type_pack_element)
#define BSC_DETAIL_TYPE_PACK_ELEMENT(I, ...) __type_pack_element<I, __VA_ARGS__>
#endif
#endif
// BSC_DETAIL_BASES_OF(T): GCC's __bases, every base class of class T as a pack, so that the
// event families (detail/model/event_families.hpp) ask each event of its own bases, not of every
// other event: GCC takes 1.7 s for the 250,000 pairs of a chart of 500 events. Clang has no
// __bases, and asks the pairs in a tenth of the time.
#if defined(__GNUC__) && !defined(__clang__)
#define BSC_DETAIL_BASES_OF(T) __bases(T)
#endif

// ---- names -----------------------------------------------------------------------------------------
// BSC_DETAIL_FUNCTION_SIGNATURE: the enclosing function's signature, with its template arguments
// spelled out, from which detail/type_name.hpp reads a type's name and detail/member_names.hpp a
// member's. Its parsing knows GCC's and Clang's format; under another compiler names are not
// read correctly.
#if defined(__GNUC__) || defined(__clang__)
#define BSC_DETAIL_FUNCTION_SIGNATURE __PRETTY_FUNCTION__
#elif defined(_MSC_VER)
#define BSC_DETAIL_FUNCTION_SIGNATURE __FUNCSIG__
#else
#define BSC_DETAIL_FUNCTION_SIGNATURE __func__
#endif

// ---- diagnostics -----------------------------------------------------------------------------------
// BSC_DETAIL_PRINTS_STRING_ARGUMENTS: 1 where the compiler shows a string held by a template
// argument as text in its errors (GCC), so that an error can show a row as written; 0 where it
// shows numbers (Clang) or is not known to, and the text is not computed.
// BSC_DETAIL_DECLARED_ONLY_BEGIN, BSC_DETAIL_DECLARED_ONLY_END: around code that names a
// variable template declared and never defined, in constant expressions only (the objects whose
// members' addresses name the members): Clang warns of the missing definition, which is never
// needed.
#if defined(__GNUC__) && !defined(__clang__)
#define BSC_DETAIL_PRINTS_STRING_ARGUMENTS 1
#else
#define BSC_DETAIL_PRINTS_STRING_ARGUMENTS 0
#endif
#if defined(__clang__)
#define BSC_DETAIL_DECLARED_ONLY_BEGIN                                                                \
    _Pragma("clang diagnostic push") _Pragma("clang diagnostic ignored \"-Wundefined-var-template\"") \
        _Pragma("clang diagnostic ignored \"-Wundefined-internal\"")
#define BSC_DETAIL_DECLARED_ONLY_END _Pragma("clang diagnostic pop")
#else
#define BSC_DETAIL_DECLARED_ONLY_BEGIN
#define BSC_DETAIL_DECLARED_ONLY_END
#endif

// ---- the standard library --------------------------------------------------------------------------
// BSC_DETAIL_CHRONO_HEADER: the header detail/chrono.hpp includes for durations, time points and
// clocks. libstdc++ keeps them in <bits/chrono.h>, without the calendars, time zones and
// formatting that its C++20 <chrono> brings (0.17 s of CPU in every translation unit that
// includes bsc: docs/performance.md, rule "Headers include only what bsc uses"); any other
// library gets <chrono>.
#if defined(__GLIBCXX__) && defined(__has_include)
#if __has_include(<bits/chrono.h>)
#define BSC_DETAIL_CHRONO_HEADER <bits/chrono.h>
#endif
#endif
#if !defined(BSC_DETAIL_CHRONO_HEADER)
#define BSC_DETAIL_CHRONO_HEADER <chrono>
#endif
// end include/bsc/detail/config.hpp

namespace bsc::detail {

template <class...>
inline constexpr bool dependent_false = false;

// (size is an enumerator, not a static data member: a member variable makes a symbol, which
// the compiler names by spelling the list, for every list instantiated; the folds that build
// lists instantiate one per prefix, so that for a large chart those names grew quadratically.)
template <class... Ts>
struct type_list {
    enum : std::size_t { size = sizeof...(Ts) };
};

// Concatenation of lists: concat_t<Lists...>. A class, which makes no symbol: a function of
// the lists (an operator+ folded over them, say) is a symbol per step of the fold, named by
// spelling the list so far, and for a large chart building those names took quadratic time.
template <class... Lists>
struct concat;
template <>
struct concat<> {
    using type = type_list<>;
};
template <class... As>
struct concat<type_list<As...>> {
    using type = type_list<As...>;
};
template <class... As, class... Bs, class... Rest>
struct concat<type_list<As...>, type_list<Bs...>, Rest...> {
    using type = typename concat<type_list<As..., Bs...>, Rest...>::type;
};
template <class... As, class... Bs, class... Cs, class... Ds, class... Rest>
struct concat<type_list<As...>, type_list<Bs...>, type_list<Cs...>, type_list<Ds...>, Rest...> {
    using type = typename concat<type_list<As..., Bs..., Cs..., Ds...>, Rest...>::type;
};
// (Sixteen lists a step where there are as many: each step copies the list built so far, so a
// step per four lists made the concatenation of a chart's n one-element lists cost n^2 / 8.)
template <class... T0, class... T1, class... T2, class... T3, class... T4, class... T5, class... T6, class... T7,
          class... T8, class... T9, class... T10, class... T11, class... T12, class... T13, class... T14, class... T15,
          class... Rest>
struct concat<type_list<T0...>, type_list<T1...>, type_list<T2...>, type_list<T3...>, type_list<T4...>,
              type_list<T5...>, type_list<T6...>, type_list<T7...>, type_list<T8...>, type_list<T9...>,
              type_list<T10...>, type_list<T11...>, type_list<T12...>, type_list<T13...>, type_list<T14...>,
              type_list<T15...>, Rest...> {
    using type = typename concat<type_list<T0..., T1..., T2..., T3..., T4..., T5..., T6..., T7..., T8..., T9..., T10...,
                                           T11..., T12..., T13..., T14..., T15...>,
                                 Rest...>::type;
};
template <class... Lists>
using concat_t = typename concat<Lists...>::type;

// O(1) access by position after one O(n) instantiation per list.
template <std::size_t I, class T>
struct indexed {
    using type = T;
};
template <class Seq, class... Ts>
struct indexer;
template <std::size_t... Is, class... Ts>
struct indexer<std::index_sequence<Is...>, Ts...> : indexed<Is, Ts>... {};
template <std::size_t I, class T>
indexed<I, T> select_indexed(indexed<I, T>);

// The position of T among the bases of an indexer, found by overload resolution: no
// instantiation per element, so n lookups in a list of n cost O(n), not O(n^2). Declared only:
// it is called in decltype, and answers with the type of its result.
template <class T, std::size_t I>
std::integral_constant<int, static_cast<int>(I)> position_by_type(indexed<I, T> const*);

template <class List>
struct indexer_of;
template <class... Ts>
struct indexer_of<type_list<Ts...>> {
    using type = indexer<std::index_sequence_for<Ts...>, Ts...>;
};

// How many of the flags are true. (A list and a loop where a fold expression would do: GCC
// takes time superlinear in the length of a fold, and the lists here are as long as a chart.)
constexpr int count_true(std::initializer_list<bool> flags) {
    int n = 0;
    for (bool flag : flags) n += flag ? 1 : 0;
    return n;
}

// Whether any of the flags is true; whether all are. (For packs as long as a chart, in place of
// a fold expression: see count_true.)
constexpr bool any_true(std::initializer_list<bool> flags) {
    for (bool flag : flags)
        if (flag) return true;
    return false;
}
constexpr bool all_true(std::initializer_list<bool> flags) {
    for (bool flag : flags)
        if (!flag) return false;
    return true;
}

// The position of the first true among the flags, or -1.
constexpr int first_true(std::initializer_list<bool> flags) {
    int i = 0;
    for (bool flag : flags) {
        if (flag) return i;
        ++i;
    }
    return -1;
}

// Position of the first T in List, or -1: position_in<T, List>::value. A class, not a function
// or a variable: those are symbols, which the compiler names by spelling the list, once per
// lookup, and n lookups in a list of n made names of quadratic total length.
template <class T, class List>
struct scan_for;
template <class T, class... Ts>
struct scan_for<T, type_list<Ts...>> {
    enum : int { value = first_true({BSC_DETAIL_IS_SAME(T, Ts)...}) };
};
template <class T, class List, class = void>
struct position_in : scan_for<T, List> {};  // absent, or present twice (the base is ambiguous)
template <class T, class List>
struct position_in<
    T, List,
    std::void_t<decltype(detail::position_by_type<T>(static_cast<typename indexer_of<List>::type const*>(nullptr)))>>
    : decltype(detail::position_by_type<T>(static_cast<typename indexer_of<List>::type const*>(nullptr))) {};

template <std::size_t I, class List>
struct at_impl;
template <std::size_t I, class... Ts>
struct at_impl<I, type_list<Ts...>> {
#if defined(BSC_DETAIL_TYPE_PACK_ELEMENT)
    using type = BSC_DETAIL_TYPE_PACK_ELEMENT(I, Ts...);
#else
    using type = typename decltype(detail::select_indexed<I>(indexer<std::index_sequence_for<Ts...>, Ts...>{}))::type;
#endif
};
template <std::size_t I, class List>
using at = typename at_impl<I, List>::type;

template <int I>
using int_c = std::integral_constant<int, I>;

// The longest pack the library folds with a fold expression; longer ones, which a chart's states,
// rows or events can be, are lists (an array's initializers, or count_true and the like):
// Clang nests a fold at most 256 deep, and GCC's time grows faster than the length of a fold.
inline constexpr std::size_t max_fold = 128;

// Calls f(int_c<I>) for the I in [0, N) equal to i; compilers turn the chain into a jump table.
template <int N, class F, int... Is>
constexpr void visit_index_impl(int i, F& f, std::integer_sequence<int, Is...>) {
    if constexpr (sizeof...(Is) <= max_fold)
        (void)((i == Is ? (f(int_c<Is>{}), true) : false) || ...);
    else [[maybe_unused]]
        bool const visited[] = {(i == Is ? (f(int_c<Is>{}), true) : false)...};
}
template <int N, class F>
constexpr void visit_index(int i, F&& f) {
    visit_index_impl<N>(i, f, std::make_integer_sequence<int, N>{});
}

}  // namespace bsc::detail
// end include/bsc/detail/meta.hpp
// begin include/bsc/error.hpp
// Every error bsc reports at compile time, in one place. Each is a class template whose
// arguments are the culprits (states, events, callables); the static_assert in its destructor
// says what is wrong and how to fix it, and its condition, dependent_false<the error type>,
// makes the compiler print the error's name with the culprits. The assertion sits in the
// destructor so that it fires where an error object is destroyed, not where the class is
// named: make_chart returns its findings as an object (detail::rejected_chart) whose
// destructor raises them from a function the compiler instantiates at the end of the
// translation unit, so the error's context is not make_chart<...the whole chart type...>.
// detail::report<E>() raises one anywhere else. docs/checks.md lists them all with an example
// each.

#include <cstddef>
#include <type_traits>

// begin include/bsc/detail/fixed_string.hpp
// A string as a template argument: the names of bsc::named<"released"> and the rows that
// errors reproduce (bsc::error::as_written).

#include <cstddef>
#include <string_view>

namespace bsc::detail {

/// N characters including the terminating zero, usable as a non-type template argument.
template <std::size_t N>
struct fixed_string {
    char chars[N]{};
    constexpr fixed_string() = default;
    // Implicit, so that a string literal converts to it as a template argument.
    constexpr fixed_string(char const (&text)[N]) {  // NOLINT(google-explicit-constructor)
        for (std::size_t i = 0; i < N; ++i) chars[i] = text[i];
    }
    constexpr std::string_view view() const { return {chars, N - 1}; }
};

}  // namespace bsc::detail
// end include/bsc/detail/fixed_string.hpp

namespace bsc::error {

// ---- the static checks of a chart (bsc::make_chart) ----------------------------------------

template <class State>
struct unreachable_state {
    constexpr ~unreachable_state() {
        static_assert(detail::dependent_false<unreachable_state>,
                      "bsc: unreachable state: no initial entry, history or transition can activate this state "
                      "from the initial configuration; add a transition to it (or make it an initial child), or "
                      "remove it");
    }
};

template <class State>
struct dead_end_state {
    constexpr ~dead_end_state() {
        static_assert(detail::dependent_false<dead_end_state>,
                      "bsc: dead end: no transition leaves this non-final state (neither from it, nor from an "
                      "ancestor, nor from an orthogonal region); add one, or declare it with bsc::final_state");
    }
};

template <class Source, class Trigger>
struct conflicting_transitions {
    constexpr ~conflicting_transitions() {
        static_assert(detail::dependent_false<conflicting_transitions>,
                      "bsc: conflicting transitions: two unguarded transitions leave this state on the same "
                      "trigger, so the chart is nondeterministic; guard one of them or remove one");
    }
};

template <class Source, class Trigger, class Target>
struct shadowed_transition {
    constexpr ~shadowed_transition() {
        static_assert(detail::dependent_false<shadowed_transition>,
                      "bsc: shadowed transition: an earlier unguarded transition from this state on the same "
                      "trigger (or on a family of it: a base class, or bsc::any_event) always wins, so the "
                      "transition to Target can never fire; guard the earlier one or move this one before it");
    }
};

template <class Source, class Trigger, class Target>
struct dead_transition {
    constexpr ~dead_transition() {
        static_assert(detail::dependent_false<dead_transition>,
                      "bsc: dead transition: this row can never fire: its source is a final child of the root "
                      "(the machine has halted there), or every state below its source takes the same event "
                      "first with an unguarded row of its own; remove the row, guard the rows below, or move it "
                      "(Target is bsc::detail::no_target for an internal row)");
    }
};

template <class Source, class Trigger, class Target, class Outer>
struct dead_transition_behind_outer {
    constexpr ~dead_transition_behind_outer() {
        static_assert(detail::dependent_false<dead_transition_behind_outer>,
                      "bsc: dead transition under parent-first priority: Outer, an ancestor of this row's source, "
                      "has an unguarded row on the same event (or on a family of it), which is tried first "
                      "whenever the source is active; remove the row, guard the outer row, or declare the chart "
                      "child-first (Target is bsc::detail::no_target for an internal row)");
    }
};

template <class Event>
struct event_in_two_families {
    constexpr ~event_in_two_families() {
        static_assert(detail::dependent_false<event_in_two_families>,
                      "bsc: event in two families: two triggers of the chart that do not derive from one another "
                      "are both base classes of this event, so it is unclear which rows take it; an event's "
                      "families (its base classes among the chart's triggers, and bsc::any_event) must form one "
                      "chain: derive one family from the other, or trigger no row with one of them");
    }
};

template <class HistoryState>
struct invalid_history_state {
    constexpr ~invalid_history_state() {
        static_assert(detail::dependent_false<invalid_history_state>,
                      "bsc: invalid history state: a history state (shallow_history_state<H, Default>, "
                      "deep_history_state<H, Default>) must be declared in a composite, its Default must be a "
                      "state inside that composite (not a history state), and it takes no rows but on_initial "
                      "(the action of its default transition); it is never active, so no transition leaves it");
    }
};

template <class Composite>
struct initial_states_not_orthogonal {
    constexpr ~initial_states_not_orthogonal() {
        static_assert(detail::dependent_false<initial_states_not_orthogonal>,
                      "bsc: initial states not orthogonal: the states named by bsc::initial<A, B, ...> must lie "
                      "below this composite, one in each of several regions of a parallel state (none containing "
                      "another); name one state per region");
    }
};

/// The states of a transition with several targets, as an error names them.
template <class... States>
struct target_states {};

template <class Source, class Targets>
struct targets_not_orthogonal {
    constexpr ~targets_not_orthogonal() {
        static_assert(detail::dependent_false<targets_not_orthogonal>,
                      "bsc: targets not orthogonal: a transition with several targets (bsc::targets) enters one "
                      "state in each of several regions of a parallel state, so no target may contain another, "
                      "and any two must lie in different regions of a parallel state; keep one target per "
                      "region");
    }
};

template <class Chart, class Event>
struct pending_events_not_encoded {
    constexpr ~pending_events_not_encoded() {
        static_assert(detail::dependent_false<pending_events_not_encoded>,
                      "bsc: a machine of this Chart keeps events from one call to the next (deferred by / "
                      "bsc::defer, or sent by bsc::raise_after), and the explorer (bsc::verify), bsc::save / "
                      "bsc::restore and bsc::net encode them with the rest of its state; this Event cannot be "
                      "encoded: it must be default-constructible, and each of its members (at any depth) bool, "
                      "an integer, an enum with a fixed underlying type, float, double, a std::chrono::duration, "
                      "or a std::array or struct of them (a std::string cannot); change the event, or leave the "
                      "chart's machine out of what is saved and explored");
    }
};

template <class Source, class Trigger>
struct invalid_deferral {
    constexpr ~invalid_deferral() {
        static_assert(detail::dependent_false<invalid_deferral>,
                      "bsc: invalid deferral: a row that defers (/ bsc::defer) keeps its event for later, so it "
                      "needs an event trigger (not eventless, not a timeout, not bsc::any_event, which would keep "
                      "only its tag) and no target; defer the events by name, one row each");
    }
};

template <class State>
struct initial_action_without_initial_transition {
    constexpr ~initial_action_without_initial_transition() {
        static_assert(detail::dependent_false<initial_action_without_initial_transition>,
                      "bsc: initial action of a state without an initial transition: an on_initial row runs when "
                      "a composite is entered through its initial state, and this state is not a composite, or "
                      "has a history marker (it is entered through its history instead); use on_entry, or remove "
                      "the history marker");
    }
};

template <class Source, class Target>
struct local_target_outside_source {
    constexpr ~local_target_outside_source() {
        static_assert(detail::dependent_false<local_target_outside_source>,
                      "bsc: local transition to a state outside its source: a local transition "
                      "(= bsc::local(state<Target>)) keeps its source active, so its target must lie below the "
                      "source; target a descendant, or make it an ordinary transition (= state<Target>)");
    }
};

template <class Source, class Target>
struct transition_between_orthogonal_regions {
    constexpr ~transition_between_orthogonal_regions() {
        static_assert(detail::dependent_false<transition_between_orthogonal_regions>,
                      "bsc: transition between orthogonal regions: the source and the target lie in different "
                      "regions of the same parallel state, which are always active together; target a state "
                      "outside the parallel state instead");
    }
};

template <class State>
struct state_not_in_chart {
    constexpr ~state_not_in_chart() {
        static_assert(detail::dependent_false<state_not_in_chart>,
                      "bsc: a row names a state that the state tree does not declare; declare it in the tree "
                      "(bsc::state, bsc::composite, bsc::parallel or bsc::final_state) or fix the row");
    }
};

// bsc::in<S> in a row's guard: S must be a state the tree declares, and one that can be active.
template <class State>
struct in_of_state_not_in_chart {
    constexpr ~in_of_state_not_in_chart() {
        static_assert(detail::dependent_false<in_of_state_not_in_chart>,
                      "bsc: a row's guard tests bsc::in<State>, but State is not a state of this chart (a misspelt "
                      "name, or a state of another chart), so whether it is active means nothing; name a state "
                      "that the tree declares");
    }
};

template <class State>
struct in_of_history_state {
    constexpr ~in_of_history_state() {
        static_assert(detail::dependent_false<in_of_history_state>,
                      "bsc: a row's guard tests bsc::in<State>, but State is a history pseudo-state "
                      "(shallow_history_state, deep_history_state), which is never active, so the test would "
                      "always be false; test the composite the history state belongs to, or one of its children");
    }
};

// machine.is<S>() of a state the tree does not declare (the row errors above are about rows).
template <class State>
struct queried_state_not_in_chart {
    constexpr ~queried_state_not_in_chart() {
        static_assert(detail::dependent_false<queried_state_not_in_chart>,
                      "bsc: is<State>() asks about a state that the chart's tree does not declare (a misspelt "
                      "name, or a state of another chart); name one of this chart's states");
    }
};

// ---- completion events (bsc::done<S>) --------------------------------------------------------

template <class State>
struct done_of_state_not_in_chart {
    constexpr ~done_of_state_not_in_chart() {
        static_assert(detail::dependent_false<done_of_state_not_in_chart>,
                      "bsc: a row takes bsc::done<State>, but State is not a state of this chart (a misspelt "
                      "name?), so the event is never raised and the row never fires; name a composite or "
                      "parallel state of the chart that has a final child");
    }
};

template <class State>
struct done_never_raised {
    constexpr ~done_never_raised() {
        static_assert(detail::dependent_false<done_never_raised>,
                      "bsc: a row takes bsc::done<State>, but State never completes, so the row never fires: "
                      "bsc::done<S> is raised when a composite S enters a final child (bsc::final_state), or "
                      "when every region of a parallel S is in a final state; never for a basic or final "
                      "state, a composite without a final child, a parallel state with a region that has "
                      "none, or the root (the machine halts); give State a final child, or take another event");
    }
};

template <class Source, class State>
struct done_source_inactive {
    constexpr ~done_source_inactive() {
        static_assert(detail::dependent_false<done_source_inactive>,
                      "bsc: a row on bsc::done<State> leaves Source, a state inside State that is no longer "
                      "active when State completes (then only State's final child is, and for a parallel "
                      "State its regions and their final children), so the row never fires; move the row to "
                      "State, to an ancestor of State, or to a state orthogonal to it");
    }
};

template <class State>
struct duplicate_state {
    constexpr ~duplicate_state() {
        static_assert(detail::dependent_false<duplicate_state>,
                      "bsc: this state is declared twice in the state tree; every state type may appear once");
    }
};

template <class Composite>
struct missing_initial_state {
    constexpr ~missing_initial_state() {
        static_assert(detail::dependent_false<missing_initial_state>,
                      "bsc: this composite state has no initial child; add bsc::initial<Child> to its declaration");
    }
};

template <class Composite>
struct multiple_initial_states {
    constexpr ~multiple_initial_states() {
        static_assert(detail::dependent_false<multiple_initial_states>,
                      "bsc: this composite state has more than one bsc::initial marker; keep exactly one");
    }
};

template <class Composite, class Initial>
struct initial_not_a_child {
    constexpr ~initial_not_a_child() {
        static_assert(detail::dependent_false<initial_not_a_child>,
                      "bsc: the initial state named by this composite is declared elsewhere in the tree, not inside "
                      "it; name one of its own children, or a state below it, in bsc::initial<...>");
    }
};

template <class State>
struct eventless_livelock {
    constexpr ~eventless_livelock() {
        static_assert(detail::dependent_false<eventless_livelock>,
                      "bsc: eventless livelock: unguarded eventless transitions from this state lead back to it "
                      "(or it has an unguarded eventless internal transition), so a dispatch would never settle; "
                      "guard one of the transitions on the cycle or give it an event");
    }
};

template <class Event>
struct unhandled_event {
    constexpr ~unhandled_event() {
        static_assert(detail::dependent_false<unhandled_event>,
                      "bsc: no transition of this chart is triggered by the dispatched event type; add one, fix "
                      "the event type, or dispatch with bsc::allow_unhandled to ignore it on purpose");
    }
};

template <class Policy>
struct last_outcome_not_kept {
    constexpr ~last_outcome_not_kept() {
        static_assert(detail::dependent_false<last_outcome_not_kept>,
                      "bsc: this machine's policy has keep_last_outcome = false, so it keeps no outcome: read the "
                      "outcome dispatch or step returns, or use a policy that keeps it (bsc::default_policy)");
    }
};

template <class Policy>
struct clock_not_kept {
    constexpr ~clock_not_kept() {
        static_assert(detail::dependent_false<clock_not_kept>,
                      "bsc: this machine keeps no clock: its policy has keep_clock = false and its chart has no "
                      "timeout, timer or delayed event, so nothing it does depends on time; keep the time of the "
                      "last step() yourself, or use a policy with keep_clock = true (bsc::default_policy)");
    }
};

template <class First, class Second>
struct duplicate_event_name {
    constexpr ~duplicate_event_name() {
        static_assert(detail::dependent_false<duplicate_event_name>,
                      "bsc: two events of this chart have the same name, so bsc::event_set cannot tell them apart by "
                      "name; give one of them a static member `name` of its own (static constexpr std::string_view "
                      "name = \"...\";)");
    }
};

template <class Event>
struct not_an_event_of_the_chart {
    constexpr ~not_an_event_of_the_chart() {
        static_assert(detail::dependent_false<not_an_event_of_the_chart>,
                      "bsc: bsc::event_set<Chart>::number_of<Event>: Event is none of the chart's events (the "
                      "trigger events of its rows, without bsc::done<S>, bsc::action_failed and bsc::any_event, "
                      "which the environment cannot send); see bsc::event_set<Chart>::events");
    }
};

template <class Event>
struct event_not_constructible {
    constexpr ~event_not_constructible() {
        static_assert(detail::dependent_false<event_not_constructible>,
                      "bsc: dispatch_by_name and dispatch_by_number build the event they dispatch: this event has no "
                      "default constructor, so pass a decoder that builds it, callable as "
                      "decode(std::type_identity<Event>{}) and returning the event");
    }
};

template <class Type>
struct not_an_event {
    constexpr ~not_an_event() {
        static_assert(detail::dependent_false<not_an_event>,
                      "bsc: bsc::event<E> needs E to be a complete, copyable class or enumeration type without "
                      "const or volatile (events are copied into the queue and handed to guards and actions); "
                      "void, references, arrays, functions and pointers are not events. For a transition without "
                      "an event, leave the trigger out: state<S> [guard] = state<T>");
    }
};

template <class Event>
struct raised_event_not_in_chart {
    constexpr ~raised_event_not_in_chart() {
        static_assert(detail::dependent_false<raised_event_not_in_chart>,
                      "bsc: an action raises an event type that no transition of this chart handles");
    }
};

// ---- events the environment cannot send ----------------------------------------------------

// machine.dispatch(e) of an event only the machine raises, or of the tag of a row on any event
// (detail::reserved_event in event_set.hpp).
template <class Event>
struct event_not_dispatchable {
    constexpr ~event_not_dispatchable() {
        static_assert(detail::dependent_false<event_not_dispatchable>,
                      "bsc: dispatch(e) of an event the environment cannot send: the machine raises "
                      "bsc::done<S> itself when S completes, and bsc::action_failed when one of its guards or "
                      "actions throws; bsc::any_event is the tag a row on every event receives, not an event. "
                      "Dispatch one of the chart's other events (bsc::event_set<Chart>::events), or reach the "
                      "state the done event would lead to with an event of your own");
    }
};

// ---- the arguments of bsc::make_chart ----------------------------------------------------

template <class Allowance>
struct finding_not_allowable {
    constexpr ~finding_not_allowable() {
        static_assert(detail::dependent_false<finding_not_allowable>,
                      "bsc: make_chart's third argument must be bsc::allow<...> of findings a chart may allow: "
                      "unreachable_state, dead_end_state, shadowed_transition, dead_transition, "
                      "dead_transition_behind_outer, conflicting_transitions, done_never_raised, "
                      "eventless_livelock (bsc::error::...); a malformed tree or an error in a row is never "
                      "allowed");
    }
};

template <class Argument>
struct not_a_row {
    constexpr ~not_a_row() {
        static_assert(detail::dependent_false<not_a_row>,
                      "bsc: after the state tree, every argument of make_chart must be a row: "
                      "state<S> + event<E> [guard] / action = state<T>, state<S> [guard] = state<T>, "
                      "state<S> + on_entry / action, or state<S> + on_exit / action");
    }
};

template <class Root>
struct root_must_be_composite {
    constexpr ~root_must_be_composite() {
        static_assert(detail::dependent_false<root_must_be_composite>,
                      "bsc: the first argument of make_chart is the root of the state tree and must be a "
                      "bsc::composite<...>(...) or bsc::parallel<...>(...)");
    }
};

// ---- the state tree -------------------------------------------------------------------------

template <class State, class Argument>
struct not_a_state_declaration {
    constexpr ~not_a_state_declaration() {
        static_assert(detail::dependent_false<not_a_state_declaration>,
                      "bsc: an argument of this state's declaration is not a state or marker; a composite takes "
                      "bsc::state, bsc::final_state, bsc::composite, bsc::parallel, bsc::initial, "
                      "bsc::shallow_history and bsc::deep_history; a parallel state takes states only");
    }
};

template <class State>
struct empty_parallel_state {
    constexpr ~empty_parallel_state() {
        static_assert(detail::dependent_false<empty_parallel_state>,
                      "bsc: this parallel state has no regions; give it at least one child state (a parallel "
                      "state's children are its regions), or declare it with bsc::state");
    }
};

template <class State>
struct conflicting_history_markers {
    constexpr ~conflicting_history_markers() {
        static_assert(detail::dependent_false<conflicting_history_markers>,
                      "bsc: this composite state has more than one history marker; keep one of "
                      "bsc::shallow_history or bsc::deep_history");
    }
};

// ---- the row of an error ---------------------------------------------------------------------

/// The row an error belongs to: `state<Source> + Trigger = state<Target>` (Trigger is the event,
/// bsc::detail::eventless_trigger, bsc::detail::timeout_trigger, or the entry_keyword /
/// exit_keyword of an `on_entry` / `on_exit` row; Target is bsc::detail::no_target for a row
/// without one). make_chart reports a guard or an action that cannot be called wrapped in it,
/// so that the error names its row.
template <class Source, class Trigger, class Target, class Error>
struct in_row {
    Error error;  // destroying it raises Error
};

/// The row as written, e.g. `as_written<"Idle + go [ready] = Busy">`: states and events by
/// their unqualified names, guards and actions by their bsc::named names ("guard" and "action"
/// when unnamed), a timeout as "after(...)".
template <detail::fixed_string Text>
struct as_written {};

/// Where a row's error is: the row's Position among make_chart's rows, counted from 1 with
/// bsc::rows groups expanded in place and entry/exit rows counted, and the row as_written. Every
/// error that concerns one row (a dead, shadowed or conflicting transition, a transition between
/// orthogonal regions, a state not in the chart, a guard or action that cannot be called) is
/// reported wrapped in it. Clang prints a string template argument as character codes, so with
/// Clang AsWritten is void and the row is identified by its position and the error's culprits.
template <std::size_t Position, class Error, class AsWritten = void>
struct at_row {
    Error error;  // destroying it raises Error
};

// ---- the context -----------------------------------------------------------------------------

template <class Type>
struct context_not_an_aggregate {
    constexpr ~context_not_an_aggregate() {
        static_assert(detail::dependent_false<context_not_an_aggregate>,
                      "bsc: the members of this type of the context cannot be found: it is not an aggregate (it has "
                      "private members, constructors or virtual functions); adapt it with Boost.Hana "
                      "(<bsc/adapt/hana.hpp>, BOOST_HANA_DEFINE_STRUCT) or specialise bsc::fields<Type>");
    }
};

template <class Type>
struct too_many_fields {
    constexpr ~too_many_fields() {
        static_assert(detail::dependent_false<too_many_fields>,
                      "bsc: this struct of the context has more than 128 fields; group some of them into nested "
                      "structs or std::arrays (channels and timers are found at any depth), or adapt it with "
                      "Boost.Hana (<bsc/adapt/hana.hpp>) or bsc::fields<Type>");
    }
};

template <class Type>
struct context_type_has_base_class {
    constexpr ~context_type_has_base_class() {
        static_assert(detail::dependent_false<context_type_has_base_class>,
                      "bsc: this struct of the context has a base class, whose members bsc cannot find by "
                      "itself; adapt it with Boost.Hana (<bsc/adapt/hana.hpp>) or specialise bsc::fields<Type> "
                      "to list every member, the base's included, or hold the base as a member");
    }
};

template <class Type>
struct context_type_has_c_array {
    constexpr ~context_type_has_c_array() {
        static_assert(detail::dependent_false<context_type_has_c_array>,
                      "bsc: this struct of the context has a C array member (T name[N]), which bsc cannot walk; "
                      "make it a std::array<T, N>, or adapt the struct with Boost.Hana (<bsc/adapt/hana.hpp>) or "
                      "bsc::fields<Type>");
    }
};

template <class Type>
struct hana_adapter_not_included {
    constexpr ~hana_adapter_not_included() {
        static_assert(detail::dependent_false<hana_adapter_not_included>,
                      "bsc: this Type of the context is adapted with BOOST_HANA_DEFINE_STRUCT, but bsc does not "
                      "see its members: #include <bsc/adapt/hana.hpp> before the machine is declared");
    }
};

/// The position of a member among its owner's, in declaration order from 0.
template <std::size_t Index>
struct member_number {};

template <class Owner, class Member, class Type>
struct state_out_of_reach {
    constexpr ~state_out_of_reach() {
        static_assert(detail::dependent_false<state_out_of_reach>,
                      "bsc: member Member of Owner (the context, or a struct in it) has a Type that may hold a "
                      "channel, a timer or a machine where bsc cannot reach it (inside std::optional, "
                      "std::variant, a container, a union, behind a pointer), so the machine would neither drive "
                      "it nor save, explore or record it; hold it directly, in a std::array or in a struct, or "
                      "say that it is not part of the machine's state: declare the member "
                      "bsc::transient_member<Type>, or specialise bsc::transient<Type> as true");
    }
};

template <class Type>
struct member_not_explorable {
    constexpr ~member_not_explorable() {
        static_assert(detail::dependent_false<member_not_explorable>,
                      "bsc: the explorer (bsc::verify) encodes scalars, enums, channels, timers, machines and "
                      "std::arrays and structs of them, and copies other members byte for byte when they are "
                      "trivially copyable; this Type is neither: make it one, or leave it out of the explored "
                      "state by specialising bsc::transient<Type> as true or declaring the member "
                      "bsc::transient_member<Type>");
    }
};

// ---- retentive state (bsc/retain.hpp) --------------------------------------------------------

template <class Type>
struct member_not_retainable {
    constexpr ~member_not_retainable() {
        static_assert(detail::dependent_false<member_not_retainable>,
                      "bsc: bsc::save and bsc::restore store bool, integers of up to 64 bits, enums with a fixed "
                      "underlying type, float, double, std::chrono::duration, channels, timers, machines, and "
                      "std::arrays and structs of them, none of whose members is const or a reference; the Type "
                      "in this error is none of those: make it one, or leave it out of the machine's state by "
                      "specialising bsc::transient<Type> as true or declaring the member "
                      "bsc::transient_member<Type> (a restored machine then keeps its own value of it)");
    }
};

// ---- guards and actions ----------------------------------------------------------------------

template <class Callable>
struct guard_signature_not_supported {
    constexpr ~guard_signature_not_supported() {
        static_assert(detail::dependent_false<guard_signature_not_supported>,
                      "bsc: a guard must be callable as g(context const&, event const&), g(context const&) or g(), "
                      "and return something convertible to bool; the Callable type in this error is the guard, "
                      "bsc::error::in_row<Source, Trigger, Target, ...> the row it belongs to, and "
                      "bsc::error::at_row<Position, ...> where that row is among make_chart's rows");
    }
};

// A guard that is a bool value: `!`, `&&` or `||` applied to plain lambdas converts them to
// function pointers and those to true, so the row gets the constant, not a condition.
template <class Value>
struct guard_is_a_bool_value {
    constexpr ~guard_is_a_bool_value() {
        static_assert(detail::dependent_false<guard_is_a_bool_value>,
                      "bsc: this row's guard is a bool value, not a condition: `!`, `&&` or `||` applied to a "
                      "plain lambda converts the lambda to a function pointer and that to true; wrap the lambda "
                      "in bsc::guard(...) so that the operators combine guards (bsc::guard(f) && g, "
                      "!bsc::guard(f)), or write the whole condition in one lambda");
    }
};

template <class Callable>
struct action_signature_not_supported {
    constexpr ~action_signature_not_supported() {
        static_assert(
            detail::dependent_false<action_signature_not_supported>,
            "bsc: an action must be callable as a(context&, event const&, raise&), a(context&, event const&), "
            "a(context&) or a(); an entry/exit action as a(context&, raise&), a(context&) or a(); see the "
            "Callable type in this error, in bsc::error::in_row<Source, Trigger, Target, ...> its row, and in "
            "bsc::error::at_row<Position, ...> where that row is among make_chart's rows");
    }
};

// ---- channels and systems (bsc/data/channel.hpp, bsc/system.hpp) ----------------------------
// Inputs are the environment's, outputs the chart's ([BSC]); a system's wiring is checked where
// the system type is instantiated. Actors and channels are named by their pointers to members.

template <class T>
struct input_written_by_the_chart {
    constexpr ~input_written_by_the_chart() {
        static_assert(detail::dependent_false<input_written_by_the_chart>,
                      "bsc: an action writes an input channel (bsc::input<T>::set on the context it receives as "
                      "Context&): inputs are the environment's, set between cycles through the machine's const "
                      "context() or by a system's links; publish the value through a bsc::output<T>, or make "
                      "the channel a bsc::inout<T> if both sides write it. A context built outside a machine "
                      "is not the environment's view either: give a channel its initial value in its "
                      "constructor (bsc::input<bool> start{true})");
    }
};

template <class T>
struct output_written_from_outside {
    constexpr ~output_written_from_outside() {
        static_assert(detail::dependent_false<output_written_from_outside>,
                      "bsc: an output channel is written from outside its chart (bsc::output<T>::set on the "
                      "const context a machine's context() returns, the environment's view): outputs are the "
                      "chart's, written by its actions; set one of the chart's inputs instead (bsc::input<T>, "
                      "or bsc::inout<T> if both sides write it), or give the output its initial value in its "
                      "constructor (bsc::output<bool> lamp{true})");
    }
};

template <class Entry>
struct not_a_link {
    constexpr ~not_a_link() {
        static_assert(detail::dependent_false<not_a_link>,
                      "bsc: after the actors and the order, every argument of bsc::system must be a "
                      "bsc::link<&Actors::from, &FromContext::output, &Actors::to, &ToContext::input, options...> "
                      "or a bsc::from_outside<&Actors::actor, &Context::input>; remove or fix this Entry");
    }
};

template <class Option>
struct invalid_link_option {
    constexpr ~invalid_link_option() {
        static_assert(detail::dependent_false<invalid_link_option>,
                      "bsc: this Option of a bsc::link is none of bsc::hold_last, bsc::fail_safe<V>, "
                      "bsc::lossless and bsc::convert<F>, or it is a second one of a kind: a link takes at "
                      "most one staleness policy (hold_last, fail_safe<V> or lossless) and at most one "
                      "bsc::convert; remove it, or fix it");
    }
};

template <auto Actor>
struct actor_twice_in_order {
    constexpr ~actor_twice_in_order() {
        static_assert(detail::dependent_false<actor_twice_in_order>,
                      "bsc: this Actor is named twice in the system's bsc::order, so every system step would "
                      "step it twice; name it once");
    }
};

template <auto Actor>
struct actor_not_in_order {
    constexpr ~actor_not_in_order() {
        static_assert(detail::dependent_false<actor_not_in_order>,
                      "bsc: a bsc::link or bsc::from_outside of the system names this Actor, but the system's "
                      "bsc::order does not, so it would never step and its links would never carry anything; "
                      "add it to the order (or remove the entries that name it)");
    }
};

template <auto Actor, auto Channel>
struct link_source_not_an_output {
    constexpr ~link_source_not_an_output() {
        static_assert(detail::dependent_false<link_source_not_an_output>,
                      "bsc: the source of a bsc::link must be an output of its actor: Channel must name a "
                      "bsc::output<T> or bsc::inout<T> member of the context of Actor's machine (a link carries "
                      "what its source publishes; an input is what the source reads, a plain member its "
                      "internal variable); link from an output, or make the member one");
    }
};

template <auto Actor, auto Channel>
struct link_target_not_an_input {
    constexpr ~link_target_not_an_input() {
        static_assert(detail::dependent_false<link_target_not_an_input>,
                      "bsc: the target of a bsc::link must be an input of its actor: Channel must name a "
                      "bsc::input<T> or bsc::inout<T> member of the context of Actor's machine (a link writes "
                      "what its target reads from outside; an output is the target's own to write, a plain "
                      "member its internal variable); link to an input, or make the member one");
    }
};

template <auto FromChannel, auto ToChannel, class From, class To>
struct link_value_types_differ {
    constexpr ~link_value_types_differ() {
        static_assert(detail::dependent_false<link_value_types_differ>,
                      "bsc: this bsc::link carries a From into a channel of To, a conversion that would "
                      "happen in silence (300 to true, 2.7 to 2); give both channels the same value type, or "
                      "make the conversion explicit with the option bsc::convert<F> (the target then reads "
                      "F(value))");
    }
};

template <class Convert, class From, class To>
struct link_conversion_not_applicable {
    constexpr ~link_conversion_not_applicable() {
        static_assert(detail::dependent_false<link_conversion_not_applicable>,
                      "bsc: the bsc::convert<F> of a link cannot convert its value: F must be callable with "
                      "the source's value (a From const&) and return something that converts to the target's "
                      "value type (To); fix F, or link channels of the types it converts");
    }
};

template <auto Actor, auto Channel>
struct input_driven_twice {
    constexpr ~input_driven_twice() {
        static_assert(detail::dependent_false<input_driven_twice>,
                      "bsc: two links of the system drive this input (Channel of Actor), and in every step the "
                      "later would overwrite the earlier in silence; keep one link into it (give the actor an "
                      "input for each signal, and combine them in its guards)");
    }
};

template <auto Actor, class Member, detail::fixed_string Name>
struct input_not_driven {
    constexpr ~input_not_driven() {
        static_assert(detail::dependent_false<input_not_driven>,
                      "bsc: no link of the system drives this input of Actor (member Member of its context, "
                      "named Name), so it would keep whatever it was given; link an output to it, or, if the "
                      "environment sets it between steps (a switch, a sensor outside the system), declare it "
                      "among the system's links with bsc::from_outside<&Actors::actor, &Context::channel>");
    }
};

template <auto Actor, auto Channel>
struct from_outside_not_an_input {
    constexpr ~from_outside_not_an_input() {
        static_assert(detail::dependent_false<from_outside_not_an_input>,
                      "bsc: bsc::from_outside must name an input of its actor: Channel must name a "
                      "bsc::input<T> or bsc::inout<T> member of the context of Actor's machine (the "
                      "environment sets inputs; an output is the chart's to write, a plain member its internal "
                      "variable); name an input, or remove the entry");
    }
};

template <auto Actor, auto Channel>
struct input_linked_and_from_outside {
    constexpr ~input_linked_and_from_outside() {
        static_assert(detail::dependent_false<input_linked_and_from_outside>,
                      "bsc: this input (Channel of Actor) is declared bsc::from_outside, but a link of the "
                      "system drives it too, and would overwrite in every step what the environment set; "
                      "remove the bsc::from_outside entry, or the link");
    }
};

}  // namespace bsc::error

namespace bsc::detail {

/// Raises the error E: the temporary's destruction instantiates E's destructor, whose
/// static_assert is the error. Returns false, for the checks that go on after reporting.
template <class Error>
constexpr bool report() {
    [[maybe_unused]] Error const error{};
    return false;
}

// Raises Error from a function that is not constexpr: compilers instantiate such a function
// at the end of the translation unit, outside the instantiation of make_chart, so the error's
// context is this function alone and not the chain of templates that spell the whole chart.
template <class Error>
void raise_deferred() {
    [[maybe_unused]] Error const error{};
}

/// What make_chart returns for a chart that fails its checks: the errors found, raised when
/// the object is destroyed outside constant evaluation (the destructor is instantiated
/// whenever a chart variable is declared, so every error is reported once), and the context
/// type, so that a machine declared on it (detail/runtime/rejected.hpp) stays silent instead of
/// adding errors of its own.
template <class Context, class... Errors>
struct rejected_chart {
    using context_type = Context;
    constexpr ~rejected_chart() {
        if (!std::is_constant_evaluated()) (raise_deferred<Errors>(), ...);
    }
};

template <class T>
inline constexpr bool is_rejected_chart = false;
template <class Context, class... Errors>
inline constexpr bool is_rejected_chart<rejected_chart<Context, Errors...>> = true;

}  // namespace bsc::detail
// end include/bsc/error.hpp

namespace bsc {

/// The findings a chart allows: `bsc::make_chart<Context, bsc::child_first,
/// bsc::allow<bsc::error::unreachable_state, bsc::error::dead_end_state>>(tree, rows...)`
/// compiles although a state is never entered or has no way out; every other check still
/// holds. Only findings after which the machine still runs as the chart says can be allowed:
/// unreachable_state, dead_end_state, shadowed_transition, dead_transition,
/// dead_transition_behind_outer, conflicting_transitions, done_never_raised and
/// eventless_livelock (bsc::error::finding_not_allowable names any other).
template <template <class...> class... Findings>
struct allow {};

}  // namespace bsc

namespace bsc::detail {

template <template <class...> class A, template <class...> class B>
inline constexpr bool same_template = false;
template <template <class...> class A>
inline constexpr bool same_template<A, A> = true;

template <template <class...> class F>
inline constexpr bool allowable_finding = same_template<F, error::unreachable_state> ||
                                          same_template<F, error::dead_end_state> ||
                                          same_template<F, error::shadowed_transition> ||
                                          same_template<F, error::dead_transition> ||
                                          same_template<F, error::dead_transition_behind_outer> ||
                                          same_template<F, error::conflicting_transitions> ||
                                          same_template<F, error::done_never_raised> ||
                                          same_template<F, error::eventless_livelock>;

// The finding inside the wrappers that say which row it concerns.
template <class E>
struct finding_of {
    using type = E;
};
template <std::size_t Position, class E, class AsWritten>
struct finding_of<error::at_row<Position, E, AsWritten>> : finding_of<E> {};
template <class S, class T, class G, class E>
struct finding_of<error::in_row<S, T, G, E>> : finding_of<E> {};

template <class E, template <class...> class F>
inline constexpr bool is_finding = false;
template <template <class...> class F, class... Args>
inline constexpr bool is_finding<F<Args...>, F> = true;

template <class Allowed, class E>
inline constexpr bool allowed_finding = false;
template <template <class...> class... Fs, class E>
inline constexpr bool allowed_finding<allow<Fs...>, E> = (is_finding<typename finding_of<E>::type, Fs> || ...);

// The errors that remain once the allowed findings are taken out.
template <class Allowed, class Errors>
struct without_allowed;
template <class Allowed, class... Errors>
struct without_allowed<Allowed, type_list<Errors...>> {
    using type = concat_t<std::conditional_t<allowed_finding<Allowed, Errors>, type_list<>, type_list<Errors>>...>;
};
// A chart that allows nothing, nearly every chart, keeps its errors without a look at each.
template <class... Errors>
struct without_allowed<allow<>, type_list<Errors...>> {
    using type = type_list<Errors...>;
};

template <class Allowed>
inline constexpr bool all_allowable = false;
template <template <class...> class... Fs>
inline constexpr bool all_allowable<allow<Fs...>> = (allowable_finding<Fs> && ...);

template <class T>
inline constexpr bool is_allow = false;
template <template <class...> class... Fs>
inline constexpr bool is_allow<allow<Fs...>> = true;

}  // namespace bsc::detail
// end include/bsc/allow.hpp
// begin include/bsc/chart.hpp
// bsc::make_chart: a chart is its state tree and its rows, checked when it is declared.

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

// begin include/bsc/detail/checks/checks.hpp
// Runs every static check of a chart and turns each finding into the error type that names
// it. A check returns its findings as a type_list of bsc::error types (empty: nothing found);
// nothing is reported here: make_chart returns the findings (detail::rejected_chart), and
// their destruction reports them. Structural checks come first: the others assume a
// well-formed tree.

// begin include/bsc/detail/checks/dead_transitions.hpp
// Transitions that can never fire (seed 000's "unreachable transitions"), found from the
// structure alone, guards ignored:
//   - a row leaving a final child of a composite root: the machine halts there, and dispatch
//     only ever answers outcome::halted;
//   - child first (the default priority): a row on an event leaving a composite or parallel
//     state S when every basic or final state below S takes that event first with an unguarded
//     row of its own or of an ancestor below S (on the event or on a family of it): the event
//     is consumed below S in every configuration, so it never reaches S's row;
//   - parent first: a row on an event leaving S when a proper ancestor of S has an unguarded
//     row on that event or on a family of it: that row is tried first whenever S is active;
//     likewise an eventless row, below an unguarded eventless row of the same component.
// Reachability and dead ends (reachability.hpp) then follow only the rows that can fire.
// A timeout row behind a shorter unguarded timeout of the same state is found where the
// delays are known, in make_chart's constant evaluation (chart.hpp).

#include <array>
#include <cstddef>

// begin include/bsc/detail/checks/rows_by_source.hpp
// The rows a check looks at, grouped by source state in declaration order (a counting sort),
// so that a check compares only the rows of one state: linear in the chart for the usual few
// rows per state. Rows of state s are order[begin[s]] .. order[begin[s + 1] - 1].

#include <array>
#include <cstddef>

// begin include/bsc/detail/model/chart_model.hpp
// The model of a chart: its state tree and its rows flattened into constexpr arrays, from
// which everything else is computed. The static checks, both back ends, the exports and the
// explorer read these arrays; only lookups by type use templates.

#include <array>
#include <cstdint>
#include <string_view>
#include <type_traits>

// begin include/bsc/detail/type_name.hpp
// Compile-time type names without RTTI, read from the compiler's function signature.

#include <string_view>


namespace bsc::detail {

template <class T>
constexpr std::string_view signature() {
    return BSC_DETAIL_FUNCTION_SIGNATURE;
}

// GCC: "... [with T = ns::Name; std::string_view = ...]", Clang: "... [T = ns::Name]".
constexpr std::string_view type_from_signature(std::string_view sig) {
    constexpr std::string_view key = "T = ";
    const auto start = sig.find(key) + key.size();
    auto end = start;
    int depth = 0;
    for (; end < sig.size(); ++end) {
        const char c = sig[end];
        if (c == '<' || c == '(' || c == '[') ++depth;
        if (c == '>' || c == ')') --depth;
        if (depth < 0 || (depth == 0 && (c == ';' || c == ']'))) break;
        if (c == ']') --depth;
    }
    return sig.substr(start, end - start);
}

// "ns::outer::Name<ns::X>" -> "Name<ns::X>": the last scope at bracket depth zero.
constexpr std::string_view unqualified(std::string_view name) {
    std::size_t cut = 0;
    int depth = 0;
    for (std::size_t i = 0; i + 1 < name.size(); ++i) {
        if (name[i] == '<') ++depth;
        if (name[i] == '>') --depth;
        if (depth == 0 && name[i] == ':' && name[i + 1] == ':') cut = i + 2;
    }
    return name.substr(cut);
}

}  // namespace bsc::detail

namespace bsc {

/// The fully qualified name of a type, e.g. "mcs::Tape", computed at compile time.
template <class T>
inline constexpr std::string_view qualified_name = detail::type_from_signature(detail::signature<T>());

/// The name of a type without its namespaces, e.g. "Tape"; used for states in traces.
template <class T>
inline constexpr std::string_view name_of = detail::unqualified(qualified_name<T>);

}  // namespace bsc
// end include/bsc/detail/type_name.hpp
// begin include/bsc/dsl/row.hpp
// The chart's second table: transition rows `source + trigger [guard] / action = target`,
// and entry/exit rows `state<S> + on_entry / action`.

#include <charconv>
#include <cstddef>
#include <cstdlib>
#include <stdexcept>
#include <type_traits>
#include <utility>

// begin include/bsc/duration.hpp
// bsc::duration: the machine's notion of time. The library never reads a clock: time is given
// to step(now) by the caller, so simulations and tests are deterministic. The caller's time
// may start anywhere (negative times included): a machine's clock starts at its first cycle.

#include <cstdint>
#include <limits>

// begin include/bsc/detail/chrono.hpp
// std::chrono's durations, time points, clocks and literals, without the rest of <chrono>.
// Since C++20, libstdc++'s <chrono> also brings calendars, time zones and formatting (with
// <string> and <sstream>): 0.17 s of CPU in every translation unit that includes bsc, against
// 0.03 s for the part bsc uses, which libstdc++ keeps in a header of its own, named by
// BSC_DETAIL_CHRONO_HEADER (detail/config.hpp). Other standard libraries get <chrono> itself.


#include BSC_DETAIL_CHRONO_HEADER
// end include/bsc/detail/chrono.hpp

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
// end include/bsc/duration.hpp
// begin include/bsc/dsl/action.hpp
// Actions: what a transition, an entry or an exit does to the context.
// Wrap a callable with bsc::action to sequence it with the comma operator: / (a, b, c).

#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

// begin include/bsc/detail/invoke.hpp
// Guards, actions and entry/exit actions are plain callables that take as many of
// (context, event, raise) as they need. These helpers call them with the longest
// argument list they accept, so users never write parameters they do not use.

#include <type_traits>
#include <utility>


namespace bsc::detail {

// Whether f(args...) is a call, and one that cannot throw: what the helpers below make, asked
// as requires-expressions. (std::is_invocable answers the same for the callables bsc calls,
// through INVOKE's machinery: a dozen class templates instantiated per question, and the
// compile of a chart asks several per guard and action; docs/performance.md, rule "A question
// about a call is a requires-expression".)
template <class F, class... Args>
concept callable_with = requires(F const& f, Args&&... args) {
    f(static_cast<Args&&>(args)...);
};
template <class F, class... Args>
concept nothrow_callable_with = requires(F const& f, Args&&... args) {
    { f(static_cast<Args&&>(args)...) }
    noexcept;
};
// The implicit conversion of a guard's result (std::is_invocable_r<bool, ...> asks the same).
constexpr bool as_test(bool holds) noexcept { return holds; }
template <class F, class... Args>
concept test_with = requires(F const& f, Args&&... args) {
    detail::as_test(f(static_cast<Args&&>(args)...));
};
template <class F, class... Args>
concept nothrow_test_with = requires(F const& f, Args&&... args) {
    { detail::as_test(f(static_cast<Args&&>(args)...)) }
    noexcept;
};

// Whether a callable has one of the signatures below: what make_chart checks
// (detail/checks/signatures.hpp) and what these helpers call.
template <class G, class Ctx, class E>
inline constexpr bool guard_callable = test_with<G, Ctx const&, E const&> || test_with<G, Ctx const&> || test_with<G>;
template <class A, class Ctx, class E, class Raise>
inline constexpr bool action_callable = callable_with<A, Ctx&, E const&, Raise&> || callable_with<A, Ctx&, E const&> ||
                                        callable_with<A, Ctx&> || callable_with<A>;
template <class A, class Ctx, class Raise>
inline constexpr bool state_action_callable = callable_with<A, Ctx&, Raise&> || callable_with<A, Ctx&> ||
                                              callable_with<A>;

// Whether the call these helpers make cannot throw: the form they pick is noexcept. A chart
// none of whose guards and actions can throw needs no record of failures (detail/runtime/machine_data.hpp, may_throw).
template <class G, class Ctx, class E>
constexpr bool guard_nothrow() {
    if constexpr (test_with<G, Ctx const&, E const&>)
        return nothrow_test_with<G, Ctx const&, E const&>;
    else if constexpr (test_with<G, Ctx const&>)
        return nothrow_test_with<G, Ctx const&>;
    else
        return nothrow_test_with<G>;
}
template <class A, class Ctx, class E, class Raise>
constexpr bool action_nothrow() {
    if constexpr (callable_with<A, Ctx&, E const&, Raise&>)
        return nothrow_callable_with<A, Ctx&, E const&, Raise&>;
    else if constexpr (callable_with<A, Ctx&, E const&>)
        return nothrow_callable_with<A, Ctx&, E const&>;
    else if constexpr (callable_with<A, Ctx&>)
        return nothrow_callable_with<A, Ctx&>;
    else
        return nothrow_callable_with<A>;
}
template <class A, class Ctx, class Raise>
constexpr bool state_action_nothrow() {
    if constexpr (callable_with<A, Ctx&, Raise&>)
        return nothrow_callable_with<A, Ctx&, Raise&>;
    else if constexpr (callable_with<A, Ctx&>)
        return nothrow_callable_with<A, Ctx&>;
    else
        return nothrow_callable_with<A>;
}

template <class G, class Ctx, class E>
constexpr bool call_guard(G const& g, Ctx const& ctx, E const& e) noexcept(guard_nothrow<G, Ctx, E>()) {
    if constexpr (test_with<G, Ctx const&, E const&>)
        return static_cast<bool>(g(ctx, e));
    else if constexpr (test_with<G, Ctx const&>)
        return static_cast<bool>(g(ctx));
    else if constexpr (test_with<G>)
        return static_cast<bool>(g());
    else
        return report<error::guard_signature_not_supported<G>>();
}

template <class A, class Ctx, class E, class Raise>
constexpr void call_action(A const& a, Ctx& ctx, E const& e,
                           Raise& raise) noexcept(action_nothrow<A, Ctx, E, Raise>()) {
    if constexpr (callable_with<A, Ctx&, E const&, Raise&>)
        a(ctx, e, raise);
    else if constexpr (callable_with<A, Ctx&, E const&>)
        a(ctx, e);
    else if constexpr (callable_with<A, Ctx&>)
        a(ctx);
    else if constexpr (callable_with<A>)
        a();
    else
        detail::report<error::action_signature_not_supported<A>>();
}

template <class A, class Ctx, class Raise>
constexpr void call_state_action(A const& a, Ctx& ctx, Raise& raise) noexcept(state_action_nothrow<A, Ctx, Raise>()) {
    if constexpr (callable_with<A, Ctx&, Raise&>)
        a(ctx, raise);
    else if constexpr (callable_with<A, Ctx&>)
        a(ctx);
    else if constexpr (callable_with<A>)
        a();
    else
        detail::report<error::action_signature_not_supported<A>>();
}

}  // namespace bsc::detail
// end include/bsc/detail/invoke.hpp
// begin include/bsc/outcome.hpp
// What a run reports: the outcome of a dispatch, the report of a cycle; and the tag that lets
// a dispatch ignore an event no transition handles.

#include <cstddef>
#include <cstdint>

// begin include/bsc/policies.hpp
// The limits a machine runs under: bsc::default_policy, bsc::scan_policy, bsc::lean_policy, and
// the requirements a policy of one's own meets (bsc::machine_policy).

#include <concepts>
#include <cstddef>

namespace bsc {

/// The limits of a machine. Derive from it and override a member to change one:
/// `struct my_limits : bsc::default_policy { static constexpr std::size_t queue_capacity = 32; };`
struct default_policy {
    /// Events an action may raise before the queue is drained; one more is an overflow.
    static constexpr std::size_t queue_capacity = 8;
    /// Events a machine keeps deferred (`/ bsc::defer`) at once; one more is an overflow. Read
    /// only for a chart with a deferring row.
    static constexpr std::size_t deferred_capacity = 8;
    /// Events sent with bsc::raise_after pending at once; one more is an overflow. Read only for
    /// a chart whose actions send delayed events.
    static constexpr std::size_t delayed_capacity = 8;
    /// Eventless transitions taken in a row before dispatch reports a livelock.
    static constexpr std::size_t max_eventless_steps = 64;
    /// Internal events processed within one dispatch before it reports a livelock.
    static constexpr std::size_t max_internal_events = 256;
    /// true (SCXML): construction and dispatch take eventless transitions until none is
    /// enabled. false (BSC scan): eventless transitions are taken only by step(), at most one
    /// per component per cycle.
    static constexpr bool settle_eventless = true;
    /// What happens to an exception from a guard or action that no transition takes as a
    /// bsc::action_failed event: true, dispatch() or step() rethrows it once the machine is
    /// consistent (and the constructor, for an entry action); false, they return
    /// outcome::failed and last_failure() holds it.
    static constexpr bool rethrow_failures = true;
    /// true: a dispatch or step called from inside the machine's own guards, actions or
    /// observer hooks is refused (outcome::reentrant). false: the caller promises that none
    /// is; the machine does not test for it, and one that is called is undefined behaviour (a
    /// run starts from an empty queue, which the optimiser is told; builds without NDEBUG
    /// check it with an assertion).
    static constexpr bool refuse_reentry = true;
    /// true: the machine keeps each run's outcome for last_outcome(). false: it keeps nothing
    /// (dispatch and step still return it); last_outcome() and last_failure() do not compile.
    static constexpr bool keep_last_outcome = true;
    /// true: every machine keeps the time of its last cycle, for now() and for
    /// step_report::clock_went_backwards. false: only a machine whose chart needs time keeps it
    /// (a timeout row, a bsc::timer in the context, a delayed event); in the others now() does
    /// not compile, clock_went_backwards stays false, and the machine is smaller by the clock
    /// and its flag (8 bytes and 1, with their padding). bsc::vcd_recorder reads now().
    static constexpr bool keep_clock = true;
};

/// The limits of a machine driven by BSC execution cycles (the Basic Statechart paper [BSC],
/// docs/references.md): eventless transitions are condition-driven and run only in step(), so a
/// chart whose components keep reacting to each other (a PLC scan loop) neither livelocks at
/// construction nor in dispatch.
struct scan_policy : default_policy {
    static constexpr bool settle_eventless = false;
};

/// The policy of a machine with nothing but the chart's own work: no test for a reentrant
/// call, no record of the last outcome, and no clock unless the chart needs time
/// (docs/performance.md, rule "A lean machine is the chart's own work": on a flat chart with
/// noexcept actions, a dispatch is then as short as a hand-written switch, and the machine is
/// its configuration and its context). For code whose guards, actions and observer never call the machine back, that
/// reads each outcome from dispatch's return value, and that keeps its own time.
struct lean_policy : default_policy {
    static constexpr bool refuse_reentry = false;
    static constexpr bool keep_last_outcome = false;
    static constexpr bool keep_clock = false;
};

/// What a machine reads of its policy: every member of bsc::default_policy, of its type. A
/// policy of one's own derives from bsc::default_policy and overrides members, and so meets it;
/// `bsc::machine<decltype(chart), Context, Observer, Policy>` with a Policy that does not names
/// this concept in its error, at the declaration.
template <class Policy>
concept machine_policy = requires {
    { Policy::queue_capacity } -> std::convertible_to<std::size_t>;
    { Policy::max_eventless_steps } -> std::convertible_to<std::size_t>;
    { Policy::max_internal_events } -> std::convertible_to<std::size_t>;
    { Policy::settle_eventless } -> std::convertible_to<bool>;
    { Policy::rethrow_failures } -> std::convertible_to<bool>;
    { Policy::refuse_reentry } -> std::convertible_to<bool>;
    { Policy::keep_last_outcome } -> std::convertible_to<bool>;
    { Policy::keep_clock } -> std::convertible_to<bool>;
};

}  // namespace bsc
// end include/bsc/policies.hpp

namespace bsc {

/// The result of dispatching one event (run to completion, internal events included).
enum class outcome : std::uint8_t {
    consumed,        ///< at least one transition fired for the dispatched event
    ignored,         ///< no transition was enabled; the event was discarded (SCXML semantics)
    queue_overflow,  ///< an action raised an event while the internal queue was full; that event was dropped
    livelock,        ///< the eventless-step or internal-event limit was reached; the rest was abandoned
    halted,          ///< the machine had reached a final child of its root; nothing was processed
    reentrant,       ///< called from inside one of the machine's own guards or actions: refused, nothing changed
    failed,          ///< a guard or action threw and no transition took the bsc::action_failed event (the
                     ///< policy's rethrow_failures is false; last_failure() holds the exception)
    unknown_event,   ///< dispatch_by_name or dispatch_by_number named no event of the chart: nothing was
                     ///< processed (bsc::event_set<Chart>::unknown(name) says why)
};

/// What one BSC execution cycle (`step(now)`) did, on either back end.
struct step_report {
    outcome status = outcome::ignored;  ///< consumed if any transition fired in the cycle
    int transitions = 0;                ///< condition-driven transitions fired by the components
    bool clock_went_backwards = false;  ///< `now` was earlier than the previous cycle's time
};

/// Tag for dispatch(e, bsc::allow_unhandled): dispatching an event type that no transition
/// handles is then allowed (and ignored) instead of failing to compile.
struct allow_unhandled_t {
    explicit allow_unhandled_t() = default;
};
inline constexpr allow_unhandled_t allow_unhandled{};

}  // namespace bsc
// end include/bsc/outcome.hpp

namespace bsc::detail {

struct action_base {};  // marks bsc action wrappers, so operator, applies to them only

template <class A>
concept bsc_action = std::is_base_of_v<action_base, A>;

// What bsc::defer is: the "action" of a row that defers its event. The machines recognise it
// by its type and keep the event instead of calling it; it runs nothing itself.
struct defer_action {
    template <class Ctx, class E, class Raise>
    constexpr void operator()(Ctx&, E const&, Raise&) const noexcept {}
};

template <class F>
struct action_fn : action_base {
    [[no_unique_address]] F fn;
    template <class Ctx, class E, class Raise>
    constexpr void operator()(Ctx& ctx, E const& e, Raise& raise) const
        noexcept(noexcept(call_action(fn, ctx, e, raise))) {
        call_action(fn, ctx, e, raise);
    }
};

template <class... As>
struct action_seq : action_base {
    [[no_unique_address]] std::tuple<As...> actions;
    template <class Ctx, class E, class Raise>
    constexpr void operator()(Ctx& ctx, E const& e, Raise& raise) const
        noexcept((nothrow_callable_with<As, Ctx&, E const&, Raise&> && ...)) {
        std::apply([&](auto const&... a) { (a(ctx, e, raise), ...); }, actions);
    }
};

template <class A>
constexpr auto as_action(A a) {
    if constexpr (bsc_action<A> || std::is_same_v<A, defer_action>)
        return a;
    else
        return action_fn<A>{{}, std::move(a)};
}

template <class A>
constexpr auto as_tuple(A a) {
    static_assert(!std::is_same_v<A, defer_action>,
                  "bsc::defer is a row's whole action: `state<S> + event<E> / bsc::defer`; it does not sequence with "
                  "other actions");
    if constexpr (requires { a.actions; })
        return a.actions;
    else
        return std::tuple{as_action(std::move(a))};
}

template <class... As>
constexpr auto make_seq(std::tuple<As...> t) {
    return action_seq<As...>{{}, std::move(t)};
}

template <class L, class R>
    requires(bsc_action<L> || bsc_action<R>)
constexpr auto operator,(L l, R r) { return make_seq(std::tuple_cat(as_tuple(std::move(l)), as_tuple(std::move(r)))); }

struct no_action {
    template <class Ctx, class E, class Raise>
    constexpr void operator()(Ctx&, E const&, Raise&) const noexcept {}
};


// The event a bsc action sees when it runs as an entry or exit action.
struct state_change {};

// Entry and exit actions see the context (and the raise queue), never an event.
template <class A>
struct state_action {
    [[no_unique_address]] A fn;
    template <class Ctx, class Raise>
    static constexpr bool nothrow() {
        if constexpr (bsc_action<A>)
            return nothrow_callable_with<A, Ctx&, state_change const&, Raise&>;
        else
            return state_action_nothrow<A, Ctx, Raise>();
    }
    template <class Ctx, class Raise>
    constexpr void operator()(Ctx& ctx, Raise& raise) const noexcept(nothrow<Ctx, Raise>()) {
        if constexpr (bsc_action<A>)
            fn(ctx, state_change{}, raise);
        else
            call_state_action(fn, ctx, raise);
    }
};

// What the chart's analysis hands an action as its raise argument, to learn whether it takes one
// (may_raise below) and whether it can be called at all (detail/checks/signatures.hpp): callable with
// any event, as a machine's queue is with the chart's events (an event the chart does not take
// is reported where the machine calls the action: bsc::error::raised_event_not_in_chart). Not a
// machine's queue, whose type spells every event of the chart and holds a std::variant of
// them: each question would instantiate it and make a symbol named after it.
// (It answers what a machine's queue answers besides the call, as an empty queue of the
// default capacity would, so that an action that asks is judged as before.)
struct raise_stand_in {
    template <class E>
    constexpr bool operator()(E const&) noexcept {
        return true;
    }
    constexpr bool empty() const noexcept { return true; }
    constexpr std::size_t size() const noexcept { return 0; }
    static constexpr std::size_t capacity() noexcept { return default_policy::queue_capacity; }
    constexpr bool overflowed() const noexcept { return false; }
    constexpr void clear_overflow() noexcept {}
    constexpr void clear() noexcept {}
};

// Whether an action can raise an event, i.e. whether it is ever handed the raise argument
// (an action that does not accept it is called without it). A chart none of whose actions
// can raise needs no event queue. Unknown action types are assumed to raise.
template <class Ctx, class E, class Raise>
constexpr bool may_raise(void const*) {
    return true;
}
template <class Ctx, class E, class Raise>
constexpr bool may_raise(no_action const*) {
    return false;
}
template <class Ctx, class E, class Raise>
constexpr bool may_raise(defer_action const*) {
    return false;
}
template <class Ctx, class E, class Raise, class F>
constexpr bool may_raise(action_fn<F> const*) {
    return callable_with<F, Ctx&, E const&, Raise&>;
}
template <class Ctx, class E, class Raise, class A>
constexpr bool may_raise(state_action<A> const*) {  // a plain callable of an entry or exit row
    return callable_with<A, Ctx&, Raise&>;
}

// The callable of bsc::raise(e): a type of its own, so that the machine knows which event such an
// action raises (detail::raised_by) and its queue holds only the events that can be raised.
template <class E>
struct raise_fn {
    E event;
    template <class Ctx, class Ev, class Queue>
    constexpr void operator()(Ctx&, Ev const&, Queue& queue) const noexcept(noexcept(queue(event))) {
        queue(event);
    }
};

// What an action can raise: a type_list of the event types, or raises_anything for an action
// that is handed the raise argument and may raise whatever it likes. Joined by join_raised,
// raises_anything absorbing the rest.
struct raises_anything {};
template <bool Anything, class... Lists>
struct join_raised_of {
    using type = raises_anything;
};
template <class... Lists>
struct join_raised_of<false, Lists...> {
    using type = concat_t<Lists...>;
};
template <class... Lists>
using join_raised =
    typename join_raised_of<any_true({std::is_same_v<Lists, raises_anything>..., false}), Lists...>::type;

// (A sequence, and an entry or exit action wrapping one of bsc's, are looked into; any other
// action raises anything if may_raise says it can raise at all.)
template <class Ctx, class E, class Raise, class A>
auto raised_by(A const*)
    -> std::conditional_t<may_raise<Ctx, E, Raise>(static_cast<A const*>(nullptr)), raises_anything, type_list<>>;
template <class Ctx, class E, class Raise, class Ev>
auto raised_by(action_fn<raise_fn<Ev>> const*) -> type_list<Ev>;
template <class Ctx, class E, class Raise, class... As>
auto raised_by(action_seq<As...> const*)
    -> join_raised<decltype(raised_by<Ctx, E, Raise>(static_cast<As const*>(nullptr)))...>;
template <class Ctx, class E, class Raise, class A>
    requires bsc_action<A>
auto raised_by(state_action<A> const*) -> decltype(raised_by<Ctx, state_change, Raise>(static_cast<A const*>(nullptr)));

}  // namespace bsc::detail

namespace bsc {

/// Wraps a callable as an action that sequences with others: `/ (bsc::action(a), b)`.
template <class F>
constexpr auto action(F f) {
    return detail::action_fn<F>{{}, std::move(f)};
}

/// Runs the given actions in order.
template <class... Fs>
constexpr auto seq(Fs... fs) {
    return detail::make_seq(std::tuple_cat(detail::as_tuple(std::move(fs))...));
}

/// The action of a row that defers its event (UML's deferred events, Boost.SML's `defer`):
/// `state<S> + event<E> / bsc::defer`. Selected like any row (the deepest source first, then
/// declaration order), it keeps the event, unless another region takes it with a transition in
/// the same microstep; kept events are dispatched again, in the order they came, after the next
/// transition that changes the configuration (docs/semantics.md, "Deferred events").
/// Requirements: the row has an event trigger other than bsc::any_event and no target
/// (bsc::error::invalid_deferral).
inline constexpr detail::defer_action defer{};

/// An action that raises `e` into the machine's internal queue; it is processed after
/// the current step, before dispatch returns.
template <class E>
constexpr auto raise(E e) {
    return action(detail::raise_fn<E>{std::move(e)});
}

}  // namespace bsc
// end include/bsc/dsl/action.hpp
// begin include/bsc/dsl/guard.hpp
// Guards: conditions on the context (and the event) that enable a transition.
// Wrap a callable with bsc::guard to compose it with !, && and ||. bsc::in<S>, SCXML's In(S),
// is a guard on the machine's configuration: whether state S is active.

#include <type_traits>
#include <utility>


namespace bsc::detail {

struct guard_base {};  // marks bsc guard wrappers, so the operators below apply to them only

template <class G>
concept bsc_guard = std::is_base_of_v<guard_base, G>;

// Whether a guard tests the configuration: it is, or has a part that is, a bsc::in<S>. Such a
// guard is called as g(ctx, e, active), where `active` answers active.is_active<S>() (a
// configuration view of the back end, detail/model/configuration_view.hpp); every other guard
// as before, g(ctx, e), so that a chart without bsc::in compiles and runs as it did. (A member
// of the guard types, reads_configuration, so that a named guard inherits it from its guard.)
template <class G>
inline constexpr bool tests_configuration = false;
template <class G>
    requires(G::reads_configuration)
inline constexpr bool tests_configuration<G> = true;

// What the checks hand a guard that tests the configuration: a view whose every state is active.
struct any_configuration {
    template <class S>
    constexpr bool is_active() const noexcept {
        return true;
    }
};

template <class F>
struct guard_fn : guard_base {
    [[no_unique_address]] F fn;
    template <class Ctx, class E>
    constexpr bool operator()(Ctx const& ctx, E const& e) const noexcept(noexcept(call_guard(fn, ctx, e))) {
        return call_guard(fn, ctx, e);
    }
    // Called so when another part of the guard tests the configuration, which this one ignores.
    template <class Ctx, class E, class Active>
    constexpr bool operator()(Ctx const& ctx, E const& e, Active const&) const
        noexcept(noexcept(call_guard(fn, ctx, e))) {
        return call_guard(fn, ctx, e);
    }
};

/// bsc::in<S>: whether state S is active (SCXML's In). Only callable with a configuration view.
template <class S>
struct in_guard : guard_base {
    using state = S;
    static constexpr bool reads_configuration = true;
    template <class Ctx, class E, class Active>
    constexpr bool operator()(Ctx const&, E const&, Active const& active) const
        noexcept(noexcept(active.template is_active<S>())) {
        return active.template is_active<S>();
    }
};

template <class G>
struct not_guard : guard_base {
    [[no_unique_address]] G g;
    static constexpr bool reads_configuration = tests_configuration<G>;
    template <class Ctx, class E>
    constexpr bool operator()(Ctx const& ctx, E const& e) const noexcept(noexcept(!g(ctx, e))) {
        return !g(ctx, e);
    }
    template <class Ctx, class E, class Active>
    constexpr bool operator()(Ctx const& ctx, E const& e, Active const& active) const
        noexcept(noexcept(!g(ctx, e, active))) {
        return !g(ctx, e, active);
    }
};

template <class L, class R>
struct and_guard : guard_base {
    [[no_unique_address]] L l;
    [[no_unique_address]] R r;
    static constexpr bool reads_configuration = tests_configuration<L> || tests_configuration<R>;
    template <class Ctx, class E>
    constexpr bool operator()(Ctx const& ctx, E const& e) const noexcept(noexcept(l(ctx, e) && r(ctx, e))) {
        return l(ctx, e) && r(ctx, e);
    }
    template <class Ctx, class E, class Active>
    constexpr bool operator()(Ctx const& ctx, E const& e, Active const& active) const
        noexcept(noexcept(l(ctx, e, active) && r(ctx, e, active))) {
        return l(ctx, e, active) && r(ctx, e, active);
    }
};

template <class L, class R>
struct or_guard : guard_base {
    [[no_unique_address]] L l;
    [[no_unique_address]] R r;
    static constexpr bool reads_configuration = tests_configuration<L> || tests_configuration<R>;
    template <class Ctx, class E>
    constexpr bool operator()(Ctx const& ctx, E const& e) const noexcept(noexcept(l(ctx, e) || r(ctx, e))) {
        return l(ctx, e) || r(ctx, e);
    }
    template <class Ctx, class E, class Active>
    constexpr bool operator()(Ctx const& ctx, E const& e, Active const& active) const
        noexcept(noexcept(l(ctx, e, active) || r(ctx, e, active))) {
        return l(ctx, e, active) || r(ctx, e, active);
    }
};

// The guard stored in a transition: always callable as g(ctx, event).
template <class G>
constexpr auto as_guard(G g) {
    if constexpr (bsc_guard<G>)
        return g;
    else
        return guard_fn<G>{{}, std::move(g)};
}

struct no_guard {
    template <class Ctx, class E>
    constexpr bool operator()(Ctx const&, E const&) const noexcept {
        return true;
    }
};

template <bsc_guard G>
constexpr auto operator!(G g) {
    return not_guard<G>{{}, std::move(g)};
}
template <bsc_guard L, class R>
constexpr auto operator&&(L l, R r) {
    using RG = decltype(as_guard(std::move(r)));
    return and_guard<L, RG>{{}, std::move(l), as_guard(std::move(r))};
}
template <class L, bsc_guard R>
    requires(!bsc_guard<L>)
constexpr auto operator&&(L l, R r) {
    using LG = decltype(as_guard(std::move(l)));
    return and_guard<LG, R>{{}, as_guard(std::move(l)), std::move(r)};
}
template <bsc_guard L, class R>
constexpr auto operator||(L l, R r) {
    using RG = decltype(as_guard(std::move(r)));
    return or_guard<L, RG>{{}, std::move(l), as_guard(std::move(r))};
}
template <class L, bsc_guard R>
    requires(!bsc_guard<L>)
constexpr auto operator||(L l, R r) {
    using LG = decltype(as_guard(std::move(l)));
    return or_guard<LG, R>{{}, as_guard(std::move(l)), std::move(r)};
}

}  // namespace bsc::detail

namespace bsc {

/// Wraps a callable as a guard that composes with `!`, `&&` and `||`.
/// The callable is `g(context const&, event const&)`, `g(context const&)` or `g()`, returning bool.
template <class F>
constexpr auto guard(F f) {
    return detail::guard_fn<F>{{}, std::move(f)};
}

/// SCXML's In(S): a guard that holds while state S is active, as the configuration is when the
/// guard is evaluated (before the exits of the microstep it selects for). Composes with `!`,
/// `&&`, `||` like any bsc guard: `state<B1> + event<go> [bsc::in<A2>] = state<B2>`,
/// `[!bsc::in<A2> && ready]`.
/// Requirements: S is a state of the chart's tree (bsc::error::in_of_state_not_in_chart), not a
/// history pseudo-state (bsc::error::in_of_history_state), which is never active.
template <class S>
inline constexpr detail::in_guard<S> in{};

}  // namespace bsc
// end include/bsc/dsl/guard.hpp
// begin include/bsc/events.hpp
// The events bsc itself defines: the tag of an eventless transition, the trigger every event
// matches, a state's completion event, the event of a failed guard or action, and what an
// observer receives for a timeout.

#include <exception>


namespace bsc {

namespace detail {
// The trigger of a transition taken without an event, when its guard holds.
struct eventless_trigger {};
}  // namespace detail

/// The tag used in diagnostics and observers for a transition without an event.
using eventless = detail::eventless_trigger;

/// The trigger every event matches: `state<S> + event<bsc::any_event> = state<T>` takes any
/// event that no deeper state and no earlier row of S takes first (SCXML's event="*",
/// Boost.SML's event<_>). Its guard and action receive this tag, not the event.
struct any_event {};

/// The completion event of state S (SCXML's done.state.S): raised when a final child of the
/// composite S is entered, or, for a parallel S, when every region of S has entered a final
/// state. A row takes it like any event: `state<Work> + event<bsc::done<Work>> = state<Next>`.
/// (A final child of the root raises nothing: the machine halts.)
template <class S>
struct done {
    using state = S;
};

/// What a machine puts on its internal queue when a guard, an action, an entry or an exit
/// action throws (W3C SCXML's error.execution): the rest of that callable is skipped, the
/// microstep completes, and this event carries the exception. A chart handles it with
/// ordinary rows, e.g. `state<Running> + event<bsc::action_failed> = state<Fault>`. A failure
/// that no transition takes is the caller's: dispatch() or step() rethrows it once the machine
/// is consistent (or reports outcome::failed, as the policy says).
struct action_failed {
    std::exception_ptr error;
};

/// What on_transition receives as the event of a timeout row (`after(delay)`): its delay. An
/// eventless row's transition receives bsc::eventless, an event's transition the event.
struct timeout_elapsed {
    duration delay;
};

}  // namespace bsc
// end include/bsc/events.hpp

namespace bsc::detail {

template <class S>
struct state_ref;
template <class S>
struct local_ref;
template <class... S>
struct targets_ref;

template <class E>
struct event_trigger {
    using event = E;
};
// Deliberately not constexpr (as bsc_after_negative_delay below): in a constexpr chart, reaching
// it is the compile error, and its name says what is wrong; a chart built at run time throws.
// (The message is written into a buffer, not built as a std::string: the body of an inline
// function is compiled in every translation unit that includes it, and std::string's
// operators would be instantiated there.)
[[noreturn]] inline void bsc_dead_transition_timeout_behind_a_shorter_unguarded_timeout(std::size_t row,
                                                                                        std::size_t fires_first) {
#if defined(__cpp_exceptions)
    constexpr char head[] = "bsc::make_chart: the timeout row at position ";
    constexpr char middle[] = " can never fire: the unguarded timeout row at position ";
    constexpr char tail[] =
        " leaves its state first, every time, with a shorter (or equal) delay, from the same state or "
        "from a state below it that is active whenever it is";
    char message[sizeof head + sizeof middle + sizeof tail + 40];  // each number in 20 digits at most
    char* end = message;
    auto const append = [&](char const* text) {
        while (*text != '\0') *end++ = *text++;
    };
    append(head);
    end = std::to_chars(end, message + sizeof message, row).ptr;
    append(middle);
    end = std::to_chars(end, message + sizeof message, fires_first).ptr;
    append(tail);
    *end = '\0';
    throw std::invalid_argument(message);
#else
    (void)row;
    (void)fires_first;
    std::abort();
#endif
}
// The frame the compiler shows with its arguments (Clang prints their values): the positions of
// the dead row and of the row that always fires first, counted from 1 among make_chart's rows
// (as bsc::error::at_row counts them).
// (The test keeps GCC from rejecting a constexpr function that can never be constant.)
constexpr void timeout_row_never_fires(std::size_t row, std::size_t fires_first) {
    if (row != fires_first) bsc_dead_transition_timeout_behind_a_shorter_unguarded_timeout(row, fires_first);
}

/// The trigger of a state-scoped timeout: the source has been active for `delay`.
struct timeout_trigger {
    duration delay;

    // How make_chart reports a timeout row that can never fire (chart.hpp): a delay is never
    // negative (bsc::after refuses one), so make_chart writes the positions of the dead row and
    // of the row that fires first, as a negative delay, into its own copy of the dead row, the
    // parameter, once the chart is built. The parameter is destroyed after make_chart returns,
    // in the declaration of the chart, and this is the compile error: its context is the row's
    // type, where a failure inside make_chart would print make_chart's, which spells the chart.
    static constexpr long long dead_mark_base = 1LL << 24;
    static constexpr duration dead_mark(std::size_t row, std::size_t fires_first) {
        return duration{-1 - static_cast<long long>(row) * dead_mark_base - static_cast<long long>(fires_first)};
    }
    constexpr ~timeout_trigger() {
        if (std::is_constant_evaluated() && delay < duration::zero()) {
            long long const mark = -1 - static_cast<long long>(delay.count());
            timeout_row_never_fires(static_cast<std::size_t>(mark / dead_mark_base),
                                    static_cast<std::size_t>(mark % dead_mark_base));
        }
    }
};
/// The target of an internal transition: no exit, no entry.
struct no_target {};
/// The target T of a local transition (bsc::local): in a row's type, so that the row says so.
template <class T>
struct local_target {};
// A row's target state, and whether the row is local.
/// The targets of a transition with several, one in each of orthogonal regions (bsc::targets).
template <class T, class... More>
struct several_targets {};
// A row's target state (its first, where it has several), whether the row is local, and all
// its targets.
template <class T>
struct target_parts {
    using state = T;
    static constexpr bool local = false;
    using all = type_list<T>;
};
template <>
struct target_parts<no_target> {
    using state = no_target;
    static constexpr bool local = false;
    using all = type_list<>;
};
template <class T>
struct target_parts<local_target<T>> {
    using state = T;
    static constexpr bool local = true;
    using all = type_list<T>;
};
template <class T, class... More>
struct target_parts<several_targets<T, More...>> {
    using state = T;
    static constexpr bool local = false;
    using all = type_list<T, More...>;
};

// What marks a row. A base of its own for each row type: rows whose guard, action and trigger
// are empty are empty themselves, and the tuple of a chart's rows can then take no space at
// all, which it could not if every row had the same (empty) base at a distinct address.
template <class Row>
struct row_base {
    using bsc_row_type = Row;
};

template <class Trigger, class G, class A>
struct trigger_spec {
    [[no_unique_address]] Trigger trigger;
    [[no_unique_address]] G guard;
    [[no_unique_address]] A action;
    template <class A2>
        requires std::is_same_v<A, no_action>
    constexpr auto operator/(A2 a) const {
        using action_t = decltype(as_action(std::move(a)));
        return trigger_spec<Trigger, G, action_t>{trigger, guard, as_action(std::move(a))};
    }
};

template <class E>
struct event_ref {
    using event = E;
    template <class G>
    constexpr auto operator[](G g) const {
        using guard_t = decltype(as_guard(std::move(g)));
        return trigger_spec<event_trigger<E>, guard_t, no_action>{{}, as_guard(std::move(g)), {}};
    }
    template <class A>
    constexpr auto operator/(A a) const {
        using action_t = decltype(as_action(std::move(a)));
        return trigger_spec<event_trigger<E>, no_guard, action_t>{{}, {}, as_action(std::move(a))};
    }
};

struct timeout_ref {
    duration delay;
    template <class G>
    constexpr auto operator[](G g) const {
        using guard_t = decltype(as_guard(std::move(g)));
        return trigger_spec<timeout_trigger, guard_t, no_action>{{delay}, as_guard(std::move(g)), {}};
    }
    template <class A>
    constexpr auto operator/(A a) const {
        using action_t = decltype(as_action(std::move(a)));
        return trigger_spec<timeout_trigger, no_guard, action_t>{{delay}, {}, as_action(std::move(a))};
    }
};

template <class S, class Trigger, class G, class A, class T>
struct transition_row : row_base<transition_row<S, Trigger, G, A, T>> {
    using source = S;
    using trigger = Trigger;
    using target = typename target_parts<T>::state;
    /// A local transition (`= bsc::local(state<T>)`): its source stays active.
    static constexpr bool local = target_parts<T>::local;
    /// Every target: none, the one, or several (`= bsc::targets(state<A>, state<B>)`).
    using targets = typename target_parts<T>::all;
    static constexpr bool guarded = !std::is_same_v<G, no_guard>;
    /// A row that defers its event (`/ bsc::defer`).
    static constexpr bool defers = std::is_same_v<A, defer_action>;
    [[no_unique_address]] Trigger trigger_value;
    [[no_unique_address]] G guard;
    [[no_unique_address]] A action;

    template <class T2>
        requires std::is_same_v<T, no_target>
    constexpr auto operator=(state_ref<T2>) const {
        return transition_row<S, Trigger, G, A, T2>{{}, trigger_value, guard, action};
    }
    template <class T2>
        requires std::is_same_v<T, no_target>
    constexpr auto operator=(local_ref<T2>) const {
        return transition_row<S, Trigger, G, A, local_target<T2>>{{}, trigger_value, guard, action};
    }
    template <class... T2>
        requires std::is_same_v<T, no_target>
    constexpr auto operator=(targets_ref<T2...>) const {
        return transition_row<S, Trigger, G, A, several_targets<T2...>>{{}, trigger_value, guard, action};
    }
    template <class A2>
        requires(std::is_same_v<A, no_action>&& std::is_same_v<T, no_target>)
    constexpr auto operator/(A2 a) const {
        using action_t = decltype(as_action(std::move(a)));
        return transition_row<S, Trigger, G, action_t, T>{{}, trigger_value, guard, as_action(std::move(a))};
    }
};

template <class A>
struct entry_spec {
    [[no_unique_address]] A action;
};
template <class A>
struct exit_spec {
    [[no_unique_address]] A action;
};
struct entry_keyword {
    template <class A>
    constexpr auto operator/(A a) const {
        return entry_spec<state_action<A>>{{std::move(a)}};
    }
};
struct exit_keyword {
    template <class A>
    constexpr auto operator/(A a) const {
        return exit_spec<state_action<A>>{{std::move(a)}};
    }
};
template <class A>
struct initial_spec {
    [[no_unique_address]] A action;
};
struct initial_keyword {
    template <class A>
    constexpr auto operator/(A a) const {
        return initial_spec<state_action<A>>{{std::move(a)}};
    }
};

template <class S, class A>
struct entry_row : row_base<entry_row<S, A>> {
    using source = S;
    [[no_unique_address]] A action;
};
template <class S, class A>
struct exit_row : row_base<exit_row<S, A>> {
    using source = S;
    [[no_unique_address]] A action;
};
// The action of a composite's initial transition (SCXML's <initial><transition>).
template <class S, class A>
struct initial_row : row_base<initial_row<S, A>> {
    using source = S;
    [[no_unique_address]] A action;
};

template <class R>
inline constexpr bool is_row = requires {
    typename R::bsc_row_type;
    requires std::is_same_v<typename R::bsc_row_type, R>;
};
template <class R>
inline constexpr bool is_transition_row = false;
template <class S, class Tr, class G, class A, class T>
inline constexpr bool is_transition_row<transition_row<S, Tr, G, A, T>> = true;
template <class R>
inline constexpr bool is_timeout_row = false;
template <class S, class G, class A, class T>
inline constexpr bool is_timeout_row<transition_row<S, timeout_trigger, G, A, T>> = true;
template <class R>
inline constexpr bool is_entry_row = false;
template <class S, class A>
inline constexpr bool is_entry_row<entry_row<S, A>> = true;
template <class R>
inline constexpr bool is_exit_row = false;
template <class S, class A>
inline constexpr bool is_exit_row<exit_row<S, A>> = true;
template <class R>
inline constexpr bool is_initial_row = false;
template <class S, class A>
inline constexpr bool is_initial_row<initial_row<S, A>> = true;

// Whether a row's guard tests the configuration (bsc::in<S>), and whether any of a list of rows'
// does: a back end calls such guards with a view of the configuration (dsl/guard.hpp).
template <class R>
inline constexpr bool row_tests_configuration = false;
template <class S, class Tr, class G, class A, class T>
inline constexpr bool row_tests_configuration<transition_row<S, Tr, G, A, T>> = tests_configuration<G>;
template <class Rows>
inline constexpr bool any_row_tests_configuration = false;
template <class... Rows>
inline constexpr bool any_row_tests_configuration<type_list<Rows...>> = any_true({row_tests_configuration<Rows>...,
                                                                                  false});

}  // namespace bsc::detail

namespace bsc::detail {

// What can be an event: a complete class or enumeration type, copyable, not cv-qualified.
template <class E>
constexpr bool is_event_type() {
    if constexpr (!(std::is_class_v<E> || std::is_enum_v<E>) || !std::is_same_v<E, std::remove_cv_t<E>>)
        return false;
    else if constexpr (!requires { sizeof(E); })
        return false;
    else
        return std::is_copy_constructible_v<E> && std::is_destructible_v<E>;
}

template <class E>
constexpr event_ref<E> checked_event_ref() {
    if constexpr (!is_event_type<E>()) detail::report<error::not_an_event<E>>();
    return {};
}

}  // namespace bsc::detail

namespace bsc {

/// Names an event type as a trigger: `state<A> + event<E> = state<B>`.
/// Requirements: E is a complete, copyable class or enumeration type, not cv-qualified.
template <class E>
inline constexpr detail::event_ref<E> event = detail::checked_event_ref<E>();

/// Entry action row: `state<S> + on_entry / action`; runs each time S is entered.
inline constexpr detail::entry_keyword on_entry{};

/// Exit action row: `state<S> + on_exit / action`; runs each time S is exited.
inline constexpr detail::exit_keyword on_exit{};

/// The action of composite S's initial transition: `state<S> + on_initial / action` runs when
/// S is entered through its initial state (not through history, not by a transition to a state
/// inside S), after S's entry actions and before the initial state's (SCXML's
/// `<initial><transition>` content).
/// Requirements: S is a composite without a history marker
/// (bsc::error::initial_action_without_initial_transition).
inline constexpr detail::initial_keyword on_initial{};

namespace detail {
// Deliberately not constexpr: in a constexpr chart, reaching one of these is the compile error
// (its name says what is wrong); in a chart built at run time, it throws (or aborts without
// exceptions), so no machine ever runs with such a delay.
[[noreturn]] inline void bsc_after_negative_delay() {
#if defined(__cpp_exceptions)
    throw std::invalid_argument("bsc::after: the delay is negative");
#else
    std::abort();
#endif
}
[[noreturn]] inline void bsc_after_delay_beyond_bsc_duration() {
#if defined(__cpp_exceptions)
    throw std::out_of_range("bsc::after: the delay does not fit bsc::duration (nanoseconds: about 292 years)");
#else
    std::abort();
#endif
}

// A delay of bsc::after or bsc::raise_after as a bsc::duration, refused (the functions above)
// when it is negative or does not fit.
template <class Rep, class Period>
constexpr duration checked_delay(std::chrono::duration<Rep, Period> delay) {
    if (delay < std::chrono::duration<Rep, Period>::zero()) bsc_after_negative_delay();
    if (std::chrono::duration<long double, std::nano>(delay) >
        std::chrono::duration<long double, std::nano>(duration::max()))
        bsc_after_delay_beyond_bsc_duration();
    return std::chrono::duration_cast<duration>(delay);
}
}  // namespace detail

/// A state-scoped timeout trigger: `state<S> + after(3s) = state<T>` fires in the first cycle
/// (step) at which S has been active for at least 3 s. Armed when S is entered. Without a
/// target (`state<S> + after(500ms) / a`, an internal timeout) it fires every 500 ms while S is
/// active: each time it fires, its delay counts again from that cycle. Of several timeouts of S
/// due in one cycle whose guards hold, the one that came due first fires (then the one armed
/// first, then the first declared), so that none starves another.
/// Requirements: 0 <= delay <= bsc::duration::max(); a chart with another delay does not
/// compile (constexpr chart) or throws std::invalid_argument / std::out_of_range.
template <class Rep, class Period>
constexpr detail::timeout_ref after(std::chrono::duration<Rep, Period> delay) {
    return {detail::checked_delay(delay)};
}

}  // namespace bsc
// end include/bsc/dsl/row.hpp
// begin include/bsc/dsl/tree.hpp
// The state tree: the chart's first table. Declarations are empty objects whose types
// carry the structure (BSC's S, p and delta): basic, final, composite (OR) and parallel (AND)
// states, initial children and history.

#include <cstdint>
#include <type_traits>

// begin include/bsc/dsl/state.hpp
// bsc::state<S>: names state S, in the tree (as a basic state) and in the transition rows,
// where it is the left-hand side of `state<S> + event<E> [guard] / action = state<T>`.

#include <utility>


namespace bsc::detail {

template <class S>
struct state_ref {
    using tag = S;

    template <class E>
    constexpr auto operator+(event_ref<E>) const {
        return transition_row<S, event_trigger<E>, no_guard, no_action, no_target>{};
    }
    template <class Tr, class G, class A>
    constexpr auto operator+(trigger_spec<Tr, G, A> spec) const {
        return transition_row<S, Tr, G, A, no_target>{{}, spec.trigger, std::move(spec.guard), std::move(spec.action)};
    }
    constexpr auto operator+(timeout_ref t) const {
        return transition_row<S, timeout_trigger, no_guard, no_action, no_target>{{}, {t.delay}, {}, {}};
    }
    template <class A>
    constexpr auto operator+(entry_spec<A> spec) const {
        return entry_row<S, A>{{}, std::move(spec.action)};
    }
    template <class A>
    constexpr auto operator+(exit_spec<A> spec) const {
        return exit_row<S, A>{{}, std::move(spec.action)};
    }
    template <class A>
    constexpr auto operator+(initial_spec<A> spec) const {
        return initial_row<S, A>{{}, std::move(spec.action)};
    }
    // Eventless transitions: state<S> [guard] / action = state<T>.
    template <class G>
    constexpr auto operator[](G g) const {
        using guard_t = decltype(as_guard(std::move(g)));
        return transition_row<S, eventless_trigger, guard_t, no_action, no_target>{{}, {}, as_guard(std::move(g)), {}};
    }
    template <class A>
    constexpr auto operator/(A a) const {
        using action_t = decltype(as_action(std::move(a)));
        return transition_row<S, eventless_trigger, no_guard, action_t, no_target>{{}, {}, {}, as_action(std::move(a))};
    }
    template <class T>
    constexpr auto operator=(state_ref<T>) const {
        return transition_row<S, eventless_trigger, no_guard, no_action, T>{};
    }
    template <class T>
    constexpr auto operator=(local_ref<T>) const {
        return transition_row<S, eventless_trigger, no_guard, no_action, local_target<T>>{};
    }
    template <class... T>
    constexpr auto operator=(targets_ref<T...>) const {
        return transition_row<S, eventless_trigger, no_guard, no_action, several_targets<T...>>{};
    }
};

// What bsc::targets returns: the targets of a transition with several.
template <class... S>
struct targets_ref {};

// What bsc::local returns: the target of a local transition.
template <class S>
struct local_ref {
    using tag = S;
};

}  // namespace bsc::detail

namespace bsc {

/// Names the state S: a basic state in the tree, a source or target in a transition row.
template <class S>
inline constexpr detail::state_ref<S> state{};

/// The target of a local transition (UML's kind = local, SCXML's type="internal"):
/// `state<Work> + event<restart> = local(state<Step1>)` goes from composite Work to its
/// descendant Step1 without leaving Work: only the active states below Work are exited, Work's
/// own exit and entry actions do not run, and its timeouts keep counting.
/// Requirements: the target is a proper descendant of the row's source (else the chart is
/// rejected: bsc::error::local_target_outside_source). From a parallel source the transition
/// is an ordinary one, as in SCXML, where only a compound state can keep itself active.
template <class S>
constexpr detail::local_ref<S> local(detail::state_ref<S>) {
    return {};
}

/// The targets of a transition that enters a chosen state in each of several orthogonal
/// regions (SCXML's `target="a b"`): `state<Idle> + event<go> = targets(state<A2>, state<B3>)`.
/// The transition's domain is the nearest composite above its source and all its targets; the
/// regions of a parallel state on the way that hold no target are entered by default.
/// Requirements: 2 to 4 targets, each pair in different regions of a parallel state
/// (bsc::error::targets_not_orthogonal).
template <class... S>
constexpr detail::targets_ref<S...> targets(detail::state_ref<S>...) {
    static_assert(sizeof...(S) >= 2 && sizeof...(S) <= 4,
                  "bsc::targets takes 2 to 4 states (one transition's targets in orthogonal regions)");
    return {};
}

}  // namespace bsc
// end include/bsc/dsl/state.hpp

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
// end include/bsc/dsl/tree.hpp
// begin include/bsc/priority.hpp
// bsc::priority: which of two enabled transitions a state takes when one leaves an ancestor of
// the other's source (docs/semantics.md, "Selecting transitions", "Priority").

#include <cstdint>

namespace bsc {

/// The order in which a basic state's candidate transitions are tried, chosen once per chart:
/// `bsc::make_chart<Context, bsc::parent_first>(tree, rows...)`.
/// - `child_first` (the default; SCXML, UML): the rows of the state itself first, then its
///   parent's, up to the root. An inner row overrides an outer one.
/// - `parent_first` (Stateflow, STATEMATE, IEC 61131-3 interlocks): the root's rows first, down
///   to the state's own. An outer row, an emergency stop for example, wins over every row
///   below it on the same event.
/// Among the rows of one state, declaration order either way. The choice is made at compile
/// time: dispatch tries the candidates in a fixed order, and neither order costs an instruction.
enum class priority : std::uint8_t { child_first, parent_first };

/// `bsc::make_chart<Context, bsc::child_first>`: the default, written out.
inline constexpr priority child_first = priority::child_first;
/// `bsc::make_chart<Context, bsc::parent_first>`: outer transitions first.
inline constexpr priority parent_first = priority::parent_first;

}  // namespace bsc
// end include/bsc/priority.hpp
// begin include/bsc/detail/model/event_families.hpp
// Event families: a row on event U also takes every event E derived from U, and a row on
// bsc::any_event takes every event (SCXML's event descriptors, which match by prefix, written
// as C++ inheritance). U is then a family of E. Computed from the chart's events by the model,
// the queue (which stores an event the chart does not name as its nearest family) and the
// back ends (which hand a row the event as its own type).

#include <array>
#include <cstddef>
#include <type_traits>


namespace bsc::detail {

// A row on event U also takes every event E derived from U (publicly or not: the conversion is
// checked where the row is called), and a row on bsc::any_event takes every event: U is then
// E's family. The families of an event must form one chain (each family below the next), so
// that an event's rows are those of its own type and of its chain, and an event the chart does
// not name behaves as the most derived chart event of its chain.
// The chart events (Us) that are E's families. (Built-in traits, not std::is_base_of_v: a
// chart of K events asks K * K times, and no template is instantiated per pair.)
template <class E, class... Us>
constexpr std::array<bool, sizeof...(Us)> families_of() {
    return {(!BSC_DETAIL_IS_SAME(Us, E) && (BSC_DETAIL_IS_SAME(Us, any_event) || BSC_DETAIL_IS_BASE_OF(Us, E)))...};
}

// Of the families `of` (a row of the matrix below), the nearest to the event: the one with
// the most families of its own (`counts`). -1 if there is none; -2 if the families do not
// form a chain.
template <std::size_t K>
constexpr int nearest_family(std::array<bool, K> const& of, std::array<std::array<bool, K>, K> const& family,
                             std::array<int, K> const& counts) {
    int nearest = -1;
    for (std::size_t u = 0; u < K; ++u)
        if (of[u] && (nearest < 0 || counts[u] > counts[static_cast<std::size_t>(nearest)]))
            nearest = static_cast<int>(u);
    if (nearest < 0) return -1;
    // A chain: the nearest family's own families are all the others.
    for (std::size_t u = 0; u < K; ++u)
        if (of[u] && static_cast<int>(u) != nearest && !family[static_cast<std::size_t>(nearest)][u]) return -2;
    return nearest;
}

template <class Events>
struct event_families;
template <class... Us>
struct event_families<type_list<Us...>> {
    static constexpr std::size_t K = sizeof...(Us);
    // Whether the chart names bsc::any_event, every other event's family.
    static constexpr bool names_any_event = position_in<any_event, type_list<Us...>>::value >= 0;
#if defined(BSC_DETAIL_BASES_OF)
    // How many of class E's proper bases are chart events (a base reached by two paths counts
    // twice: the callers ask only whether there are none). Classes, not functions or variables,
    // which would be symbols named by spelling every event of the chart, one per event.
    template <class... B>
    struct base_list {
        enum : int{in_chart = count_true({(position_in<B, type_list<Us...>>::value >= 0)..., false})};
    };
    template <class E, bool = BSC_DETAIL_IS_CLASS(E)>
    struct bases_below {
        enum : int{value = base_list<BSC_DETAIL_BASES_OF(E)...>::in_chart};
    };
    template <class E>
    struct bases_below<E, false> {
        enum : int{value = 0};
    };
#endif
    // How many chart events E derives from, E itself included if it is one (a class is its own
    // base): one built-in per chart event, or, where the compiler lists a class's bases, E's
    // bases looked up among the chart's events. (A list, not a fold: detail::max_fold.)
    template <class E>
    static constexpr int chart_bases = [] {
#if defined(BSC_DETAIL_BASES_OF)
        if constexpr (!BSC_DETAIL_IS_CLASS(E))
            return 0;
        else
            return static_cast<int>(position_in<E, type_list<Us...>>::value >= 0) + bases_below<E>::value;
#else
        return count_true({BSC_DETAIL_IS_BASE_OF(Us, E)...});
#endif
    }();
    // Whether event E, which the chart does not name (trigger_of asks only then), has a family
    // among the chart's events; any: whether a chart event has.
    template <class E>
    static constexpr bool has_family = (names_any_event && !BSC_DETAIL_IS_SAME(E, any_event)) || chart_bases<E> > 0;
#if defined(BSC_DETAIL_BASES_OF)
    static constexpr bool any = (names_any_event && K > 1) || any_true({(bases_below<Us>::value > 0)..., false});
#else
    static constexpr bool any = (names_any_event && K > 1) ||
                                any_true({(chart_bases<Us> > static_cast<int>(BSC_DETAIL_IS_CLASS(Us)))..., false});
#endif
    // family[t][u]: chart event u is a family of chart event t. (Built only where some event
    // has a family: a chart of K events would otherwise hold K * K flags for nothing.)
    static constexpr auto family = [] {
        if constexpr (any)
            return std::array<std::array<bool, K>, K>{families_of<Us, Us...>()...};
        else
            return std::array<std::array<bool, K>, 0>{};
    }();
    // counts[u]: how many families chart event u has.
    static constexpr std::array<int, K> counts = [] {
        std::array<int, K> out{};
        if constexpr (any)
            for (std::size_t u = 0; u < K; ++u)
                for (bool b : family[u]) out[u] += b ? 1 : 0;
        return out;
    }();
    // nearest[t]: the nearest family of chart event t, -1 if none, -2 if not a chain.
    static constexpr std::array<int, K> nearest = [] {
        std::array<int, K> out{};
        for (std::size_t t = 0; t < K; ++t) {
            if constexpr (any)
                out[t] = nearest_family(family[t], family, counts);
            else
                out[t] = -1;
        }
        return out;
    }();
    // Where no chart event has a family, an event's families form a chain only if it has one.
    static constexpr int single_family(std::array<bool, K> const& of) {
        int found = -1;
        for (std::size_t u = 0; u < K; ++u)
            if (of[u]) found = found == -1 ? static_cast<int>(u) : -2;
        return found;
    }
    // The trigger of event E: its own position if the chart names it, else its nearest family's
    // (-1: none; -2: its families are not a chain).
    template <class E>
    static constexpr int trigger_of() {
        constexpr int own = position_in<E, type_list<Us...>>::value;
        if constexpr (own >= 0)
            return own;
        else if constexpr (!has_family<E>)
            return -1;
        else if constexpr (any)
            return nearest_family(families_of<E, Us...>(), family, counts);
        else
            return single_family(families_of<E, Us...>());
    }
};

// The trigger of event E among a chart's events: its own position if the chart names it, else
// its nearest family's (-1: none; -2: its families are not a chain). A class, which makes no
// symbol, for the events the chart names; event_families::trigger_of only for the others.
template <class E, class Events>
struct unnamed_trigger : std::integral_constant<int, event_families<Events>::template trigger_of<E>()> {};
template <class E, class Events>
struct trigger_in;
template <class E, class... Us>
struct trigger_in<E, type_list<Us...>> {
    enum : int { own = position_in<E, type_list<Us...>>::value };
    enum : int {
        value = std::conditional_t<(own >= 0), std::integral_constant<int, own>,
                                   unnamed_trigger<E, type_list<Us...>>>::value
    };
};

// The event as row Row's guard and action see it, whatever event E took the row: as the row's
// own event type (a row on a family sees the family), or bsc::any_event.
template <class Seen, class E>
constexpr decltype(auto) event_as(E const& e) {
    if constexpr (BSC_DETAIL_IS_SAME(Seen, E))
        return (e);
    else if constexpr (BSC_DETAIL_IS_SAME(Seen, any_event))
        return any_event{};
    else
        return static_cast<Seen const&>(e);
}

}  // namespace bsc::detail
// end include/bsc/detail/model/event_families.hpp

namespace bsc {
template <auto const& Chart>
struct chart_ref;
}  // namespace bsc

namespace bsc::detail {

// The implicit top of every chart: the compound state above the user's root, so that a
// transition may leave and re-enter the root (SCXML's <scxml> element plays this part).
struct top_tag {};
template <class Root>
struct top_node : node_base {
    using tag = top_tag;
    static constexpr kind node_kind = kind::top;
    static constexpr history hist = history::none;
    static constexpr bool implicit = false;
    using initials = type_list<typename Root::tag>;
    using children = type_list<Root>;
};

template <class Node>
constexpr auto flatten();
template <class... C>
constexpr auto flatten_all(type_list<C...>) {
    return concat_t<decltype(flatten<C>())...>{};
}
template <class Node>
constexpr auto flatten() {
    return concat_t<type_list<Node>, decltype(flatten_all(typename Node::children{}))>{};
}

template <class List>
struct tags_of;
template <class... Nodes>
struct tags_of<type_list<Nodes...>> {
    using type = type_list<typename Nodes::tag...>;
};

enum class row_kind : std::uint8_t { transition, entry, exit, initial };

inline constexpr int eventless_id = -1;
// Every timeout row has a trigger of its own, so two timeouts on one state never "conflict".
constexpr int timeout_trigger_id(int row) { return -2 - row; }
// Eventless and timeout transitions are condition-driven: the ones a BSC cycle considers.
inline constexpr int any_condition = -1'000'000;
inline constexpr int no_state = -1;
inline constexpr int unknown_state = -2;

template <std::size_t N>
struct topology {
    std::array<kind, N> kinds{};
    std::array<history, N> hist{};
    std::array<int, N> parent{};
    std::array<int, N> first_child{};
    std::array<int, N> next_sibling{};
    std::array<int, N> child_count{};
    std::array<int, N> ordinal{};                      // position among siblings
    std::array<int, N> initial{};                      // state index of the initial child, or -1
    std::array<int, N> initial_target{};               // the initial state: the initial child, or a deeper descendant
    std::array<std::array<int, 3>, N> more_initial{};  // initial states after the first (initial<A, B>), else -1

    // State s's initial states: its initial state, then the others (initial<A, B>), -1 after.
    constexpr std::array<int, 4> initial_states(std::size_t s) const {
        return {initial_target[s], more_initial[s][0], more_initial[s][1], more_initial[s][2]};
    }
    std::array<int, N> initial_count{};  // number of initial markers
    std::array<int, N> depth{};
    std::array<int, N> end{};   // one past the last descendant: d is below s iff s < d < end[s]
    std::array<int, N> slot{};  // byte of the active configuration, composites only, else -1
    std::array<bool, N> implicit{};
    int slots = 0;

    // The most children any composite has: the configuration keeps each composite's active
    // child in a byte up to 255 of them, in two bytes above (chart_model::ordinal_type).
    constexpr int most_children() const {
        int most = 0;
        for (std::size_t s = 0; s < N; ++s)
            if (slot[s] >= 0 && child_count[s] > most) most = child_count[s];
        return most;
    }

    // States are numbered by int (negative numbers mean "none"); the arrays by size_t.
    static constexpr std::size_t at(int s) { return static_cast<std::size_t>(s); }

    constexpr bool is_leaf(int s) const { return kinds[at(s)] == kind::basic || kinds[at(s)] == kind::final_state; }
    constexpr bool is_compound(int s) const { return kinds[at(s)] == kind::composite || kinds[at(s)] == kind::top; }
    // a is an ancestor of d, or d itself
    constexpr bool contains(int a, int d) const { return a <= d && d < end[at(a)]; }
    constexpr bool is_proper_ancestor(int a, int d) const { return a < d && d < end[at(a)]; }
    constexpr int lca(int a, int b) const {
        while (!contains(a, b)) a = parent[at(a)];
        return a;
    }
    // The child of `a` on the way down to its descendant d.
    constexpr int child_toward(int a, int d) const {
        int c = d;
        while (parent[at(c)] != a) c = parent[at(c)];
        return c;
    }
    constexpr bool under_parallel(int s) const {
        for (int a = parent[at(s)]; a >= 0; a = parent[at(a)])
            if (kinds[at(a)] == kind::parallel) return true;
        return false;
    }
};

// Whether one of a node's children is a history state.
template <class... C>
constexpr bool has_history_child(type_list<C...>) {
    return any_true({(C::node_kind == kind::history)...});
}

// Links the next child of node i into the sibling chain.
template <std::size_t N>
constexpr void link_child(topology<N>& t, std::size_t i, int& previous, int child) {
    if (previous < 0)
        t.first_child[i] = child;
    else
        t.next_sibling[static_cast<std::size_t>(previous)] = child;
    previous = child;
}

// (The walk over a node's children is a fold over plain calls, with no lambda per child: a
// lambda's symbol spells its enclosing function's arguments, here the node with all its
// children, and building those names for every child of a large composite was a quadratic part
// of a chart's compile time.)
template <class Node, std::size_t N>
constexpr int fill_topology(topology<N>& t, int index, int parent, int ordinal, int depth) {
    t.kinds[static_cast<std::size_t>(index)] = Node::node_kind;
    auto const i = static_cast<std::size_t>(index);
    t.hist[i] = Node::hist;
    t.parent[i] = parent;
    t.ordinal[i] = ordinal;
    t.depth[i] = depth;
    t.implicit[i] = Node::implicit;
    t.first_child[i] = -1;
    t.next_sibling[i] = -1;
    t.initial[i] = -1;
    t.initial_target[i] = -1;
    for (int& m : t.more_initial[i]) m = -1;
    t.initial_count[i] = static_cast<int>(Node::initials::size);
    t.slot[i] = -1;
    if (Node::node_kind == kind::composite) t.slot[i] = t.slots++;
    int next = index + 1;
    int count = 0;
    int previous = -1;
    // clang-format off
    [&]<class... C>(type_list<C...>) {
        // (An array's initializers, evaluated in order, and not a fold expression: see count_true.)
        [[maybe_unused]] int const linked[] = {
            (link_child(t, i, previous, next), next = fill_topology<C>(t, next, index, count++, depth + 1))..., 0};
        if constexpr (Node::initials::size == 1) {
            using initial_tag = at<0, typename Node::initials>;
            constexpr int pos = position_in<initial_tag, type_list<typename C::tag...>>::value;
            if constexpr (pos >= 0) {
                int c = t.first_child[i];
                for (int k = 0; k < pos; ++k) c = t.next_sibling[static_cast<std::size_t>(c)];
                t.initial[i] = c;
                t.initial_target[i] = c;
            } else {
                // A deep initial: a descendant further down, numbered in document order below Node.
                constexpr int offset = position_in<initial_tag, typename tags_of<decltype(flatten<Node>())>::type>::value;
                if (offset > 0) {
                    t.initial_target[i] = index + offset;
                    t.initial[i] = t.child_toward(index, index + offset);
                }
            }
        }
    }(typename Node::children{});
    // clang-format on
    t.child_count[i] = count;
    t.end[i] = next;
    // Its initial states after the first, below it (unknown_state if not declared there).
    if constexpr (requires {
                      requires Node::more_initials::size >
                      0;
                  })
        // clang-format off
        [&]<class... More>(type_list<More...>) {
            using tags = typename tags_of<decltype(flatten<Node>())>::type;
            std::size_t k = 0;
            ((t.more_initial[i][k++] = position_in<More, tags>::value > 0 ? index + position_in<More, tags>::value : unknown_state), ...);
        }(typename Node::more_initials{});
    // clang-format on
    // The defaults of its history states, which lie anywhere below Node (-1 if not found).
    if constexpr (Node::node_kind == kind::composite && has_history_child(typename Node::children{}))
        // clang-format off
        [&]<class... C>(type_list<C...>) {
            [[maybe_unused]] int const placed[] = {(  // (a list: max_fold)
                [&] {
                    if constexpr (C::node_kind == kind::history) {
                        using tags = typename tags_of<decltype(flatten<Node>())>::type;
                        constexpr int h = position_in<typename C::tag, tags>::value;
                        constexpr int offset = position_in<typename C::default_state, tags>::value;
                        if (offset > 0 && index + offset != index + h) {
                            t.initial_target[static_cast<std::size_t>(index + h)] = index + offset;
                            t.initial[static_cast<std::size_t>(index + h)] = t.child_toward(index, index + offset);
                        }
                    }
                }(),
                0)...};
        }(typename Node::children{});
    // clang-format on
    return next;
}

template <std::size_t R>
struct row_table {
    std::array<row_kind, R> kinds{};
    std::array<int, R> source{};
    std::array<int, R> target{};   // no_state for internal transitions and entry/exit rows
    std::array<int, R> trigger{};  // eventless_id, or the event's position in the chart's event list
    std::array<bool, R> guarded{};
    std::array<int, R> domain{};   // the transition domain (SCXML), no_state if internal
    std::array<bool, R> local{};   // declared local (bsc::local): its domain is its source
    std::array<bool, R> defers{};  // defers its event (/ bsc::defer)
    // A transition with several targets (bsc::targets): `target` is the first, these the others
    // (no_state where there are fewer).
    static constexpr std::size_t max_more_targets = 3;
    std::array<std::array<int, max_more_targets>, R> more_targets{};
    // Whether row r has several targets.
    constexpr bool several(std::size_t r) const { return more_targets[r][0] >= 0; }
    // Row r's targets: its target, then the others (bsc::targets), no_state after.
    constexpr std::array<int, 1 + max_more_targets> targets_of(std::size_t r) const {
        return {target[r], more_targets[r][0], more_targets[r][1], more_targets[r][2]};
    }
    // By event position (there are no more events than rows): the event's nearest family among
    // the chart's events (-1: none, -2: not a chain). All -1 in a chart without families.
    std::array<int, R> event_family{};

    // Whether a row on trigger `row_trigger` takes trigger `taken`: the same trigger, or an
    // event position whose chain of families holds row_trigger.
    constexpr bool takes(int row_trigger, int taken) const {
        if (row_trigger == taken) return true;
        if (row_trigger < 0) return false;
        for (int t = taken; t >= 0; t = event_family[static_cast<std::size_t>(t)])
            if (t == row_trigger) return true;
        return false;
    }
};

template <class Row>
constexpr row_kind kind_of_row() {
    if constexpr (is_entry_row<Row>)
        return row_kind::entry;
    else if constexpr (is_exit_row<Row>)
        return row_kind::exit;
    else if constexpr (is_initial_row<Row>)
        return row_kind::initial;
    else
        return row_kind::transition;
}

template <class Row>
struct trigger_event {
    using type = void;
};
template <class S, class E, class G, class A, class T>
struct trigger_event<transition_row<S, event_trigger<E>, G, A, T>> {
    using type = E;
};

// The event a row's guard and action are called with: its trigger event, or bsc::eventless for
// a condition-driven row (entry and exit actions see no event).
template <class Row>
using row_event_t = std::conditional_t<std::is_void_v<typename trigger_event<Row>::type>, eventless_trigger,
                                       typename trigger_event<Row>::type>;

// The events of the rows, each once, in order of first appearance.
template <class List>
struct event_list;
template <class... Rows>
struct event_list<type_list<Rows...>> {
    using with_repeats = type_list<typename trigger_event<Rows>::type...>;
    template <std::size_t... I>
    static auto first_occurrences(std::index_sequence<I...>) -> concat_t<
        std::conditional_t<position_in<typename trigger_event<Rows>::type, with_repeats>::value == static_cast<int>(I),
                           type_list<typename trigger_event<Rows>::type>, type_list<>>...>;
    using all = decltype(first_occurrences(std::index_sequence_for<Rows...>{}));
};
template <class List>
struct drop_void;
template <class... Es>
struct drop_void<type_list<Es...>> {
    using type = concat_t<std::conditional_t<std::is_void_v<Es>, type_list<>, type_list<Es>>...>;
};

// The index of state Tag among Tags: no_state for no target, unknown_state if not there. A
// class, not a function: a function's symbol would spell the chart's states, once per row.
template <class Tag, class Tags>
struct state_index {
    enum : int { value = position_in<Tag, Tags>::value < 0 ? unknown_state : position_in<Tag, Tags>::value };
};
template <class Tags>
struct state_index<no_target, Tags> {
    enum : int { value = no_state };
};

// What the row table holds of a row, found from its type alone: classes whose enumerators are
// the values, which make no symbol. (A function or variable per row, named with the chart's
// states and events, would be one, and a large chart's names then took quadratic time.)
template <class Row, int K, class Tags, bool = (K < static_cast<int>(Row::targets::size))>
struct nth_target {
    enum : int { value = no_state };
};
template <class Row, int K, class Tags>
struct nth_target<Row, K, Tags, true> {
    enum : int { value = state_index<at<static_cast<std::size_t>(K), typename Row::targets>, Tags>::value };
};
template <class E, class Events>
struct trigger_position {
    enum : int { value = position_in<E, Events>::value };
};
template <class Events>
struct trigger_position<void, Events> {
    enum : int { value = eventless_id };
};
template <class Row, class Tags, class Events, bool = is_transition_row<Row>>
struct row_facts {  // an entry, exit or initial row
    enum : int {
        source = state_index<typename Row::source, Tags>::value,
        target = no_state,
        trigger = eventless_id,
        timeout = 0,
        guarded = 0,
        local = 0,
        defers = 0,
        more0 = no_state,
        more1 = no_state,
        more2 = no_state
    };
};
template <class Row, class Tags, class Events>
struct row_facts<Row, Tags, Events, true> {
    enum : int {
        source = state_index<typename Row::source, Tags>::value,
        target = state_index<typename Row::target, Tags>::value,
        trigger = trigger_position<typename trigger_event<Row>::type, Events>::value,
        timeout = is_timeout_row<Row> ? 1 : 0,
        guarded = Row::guarded ? 1 : 0,
        local = Row::local ? 1 : 0,
        defers = Row::defers ? 1 : 0,
        more0 = nth_target<Row, 1, Tags>::value,
        more1 = nth_target<Row, 2, Tags>::value,
        more2 = nth_target<Row, 3, Tags>::value
    };
};

template <std::size_t N, std::size_t M = 0>
constexpr int transition_domain(topology<N> const& t, int source, int target, bool local = false,
                                std::array<int, M> const& more = {}) {
    if (target < 0) return no_state;
    // SCXML's type="internal": a compound source that contains the target stays active.
    if (local && t.kinds[static_cast<std::size_t>(source)] == kind::composite && t.is_proper_ancestor(source, target))
        return source;
    // SCXML: the nearest compound proper ancestor of the source that is a proper ancestor of
    // every target.
    for (int a = t.parent[static_cast<std::size_t>(source)]; a >= 0; a = t.parent[static_cast<std::size_t>(a)]) {
        bool above_all = t.is_compound(a) && t.is_proper_ancestor(a, target);
        for (int m : more)
            if (m >= 0) above_all = above_all && t.is_proper_ancestor(a, m);
        if (above_all) return a;
    }
    return 0;
}

template <class Chart>
struct chart_model {
    using root = typename Chart::root_type;
    using nodes = decltype(flatten<top_node<root>>());
    using tags = typename tags_of<nodes>::type;
    using row_types = typename Chart::row_types;
    using chart_context = typename Chart::context_type;
    using events = typename drop_void<typename event_list<row_types>::all>::type;

    static constexpr int N = static_cast<int>(nodes::size);
    static constexpr int R = static_cast<int>(row_types::size);
    // Which of a state's candidate rows are tried first: its own or its ancestors'.
    static constexpr priority order = Chart::order;

    static constexpr topology<nodes::size> tree = [] {
        topology<nodes::size> t{};
        fill_topology<top_node<root>>(t, 0, -1, 0, 0);
        return t;
    }();
    // The type of a composite's entry in the configuration (bsc::configuration::active).
    using ordinal_type = std::conditional_t<(tree.most_children() > 255), std::uint16_t, std::uint8_t>;

    // clang-format off
    static constexpr row_table<row_types::size> rows = []<class... Rs>(type_list<Rs...>) {
        row_table<row_types::size> r{};
        for (int& f : r.event_family) f = -1;
        std::size_t e = 0;
        for (int f : event_families<events>::nearest) r.event_family[e++] = f;
        if constexpr (sizeof...(Rs) > 0) {
            // One list per column, each entry read from the row's facts (row_facts).
            row_kind const kinds[] = {kind_of_row<Rs>()...};
            int const facts[][10] = {{row_facts<Rs, tags, events>::source, row_facts<Rs, tags, events>::target,
                                      row_facts<Rs, tags, events>::trigger, row_facts<Rs, tags, events>::timeout,
                                      row_facts<Rs, tags, events>::guarded, row_facts<Rs, tags, events>::local,
                                      row_facts<Rs, tags, events>::defers, row_facts<Rs, tags, events>::more0,
                                      row_facts<Rs, tags, events>::more1, row_facts<Rs, tags, events>::more2}...};
            for (std::size_t i = 0; i < sizeof...(Rs); ++i) {
                auto const& f = facts[i];
                r.kinds[i] = kinds[i];
                r.source[i] = f[0];
                r.target[i] = f[1];
                r.trigger[i] = f[3] != 0 ? timeout_trigger_id(static_cast<int>(i)) : f[2];
                r.guarded[i] = f[4] != 0;
                r.local[i] = f[5] != 0;
                r.defers[i] = f[6] != 0;
                r.more_targets[i] = {f[7], f[8], f[9]};
                r.domain[i] = no_state;
                if (r.source[i] >= 0 && r.target[i] >= 0)
                    r.domain[i] = transition_domain(tree, r.source[i], r.target[i], r.local[i], r.more_targets[i]);
            }
        }
        return r;
    }(row_types{});
    // clang-format on

    template <int I>
    using tag_at = at<static_cast<std::size_t>(I), tags>;
    template <int I>
    using row_at = at<static_cast<std::size_t>(I), row_types>;
    // (The lookups by type are classes, which make no symbol: a variable or function per state
    // or event would be one, named by spelling the whole chart, and a large chart's symbols
    // then took time quadratic in its size.)
    template <class S>
    using index_of_state = std::integral_constant<int, position_in<S, tags>::value>;
    // Whether some event of the chart has a family (a base class among the chart's events, or
    // bsc::any_event): only then can an event take rows of another type.
    static constexpr bool has_families = event_families<events>::any;
    // Whether a row defers its event: only then does a machine keep deferred events.
    static constexpr bool has_deferral = [] {
        for (bool d : rows.defers)
            if (d) return true;
        return false;
    }();
    // The trigger of event E: its position among the chart's events, or, for an event the chart
    // does not name, its nearest family's (-1: none; -2: its families are not a chain).
    template <class E>
    using trigger_of = std::integral_constant<int, trigger_in<E, events>::value>;
};

// The model of bsc::chart_ref<chart> is the model of the chart itself: the same tables,
// computed once for the chart's checks (make_chart) and its machine, under a type whose name is
// short, so that what a machine instantiates per event or state from its model (the compiled
// plan's lists) has a short name too.
template <auto const& Chart>
struct chart_model<chart_ref<Chart>> : chart_model<std::remove_cvref_t<decltype(Chart)>> {};

// The unqualified names of a model's states, by index (0: the implicit top). A variable of
// its own, so that only what shows names (active_states, the tables, reports) instantiates it.
template <class Model>
// clang-format off
inline constexpr auto state_names_of = []<class... Tags>(type_list<Tags...>) {
    return std::array<std::string_view, sizeof...(Tags)>{name_of<Tags>...};
}(typename Model::tags{});
// clang-format on

}  // namespace bsc::detail
// end include/bsc/detail/model/chart_model.hpp

namespace bsc::detail {

template <std::size_t N, std::size_t R>
struct row_buckets {
    std::array<int, N + 1> begin{};
    std::array<int, R + 1> order{};
};

// Groups the transition rows for which keep(i) holds.
template <std::size_t N, std::size_t R, class Keep>
constexpr row_buckets<N, R> rows_by_source(row_table<R> const& r, Keep keep) {
    row_buckets<N, R> b;
    auto const kept = [&](std::size_t i) { return r.kinds[i] == row_kind::transition && keep(i); };
    for (std::size_t i = 0; i < R; ++i)
        if (kept(i)) ++b.begin[static_cast<std::size_t>(r.source[i]) + 1];
    for (std::size_t s = 0; s < N; ++s) b.begin[s + 1] += b.begin[s];
    std::array<int, N + 1> fill = b.begin;
    for (std::size_t i = 0; i < R; ++i)
        if (kept(i))
            b.order[static_cast<std::size_t>(fill[static_cast<std::size_t>(r.source[i])]++)] = static_cast<int>(i);
    return b;
}

}  // namespace bsc::detail
// end include/bsc/detail/checks/rows_by_source.hpp

namespace bsc::detail {

template <std::size_t R>
struct row_liveness {
    std::array<bool, R> dead{};
    int first_dead = -1;  // the first dead row in declaration order, or -1
    int outer = -1;       // parent first: the ancestor whose row always beats first_dead; else -1
};

template <std::size_t N, std::size_t R>
constexpr row_liveness<R> find_dead_transitions(topology<N> const& t, row_table<R> const& r, priority order) {
    row_liveness<R> found;
    constexpr int root = 1;
    bool const root_halts = N > 1 && t.kinds[root] == kind::composite;
    // Whether state b has an unguarded transition row on `trigger` or on a family of it.
    auto const unguarded = rows_by_source<N>(r, [&](std::size_t j) { return !r.guarded[j]; });
    auto takes_unguarded = [&](int b, int trigger) {
        auto const bi = static_cast<std::size_t>(b);
        for (int k = unguarded.begin[bi]; k < unguarded.begin[bi + 1]; ++k)
            if (r.takes(r.trigger[static_cast<std::size_t>(unguarded.order[static_cast<std::size_t>(k)])], trigger))
                return true;
        return false;
    };
    for (std::size_t i = 0; i < R; ++i) {
        if (r.kinds[i] != row_kind::transition) continue;
        int const s = r.source[i];
        auto const si = static_cast<std::size_t>(s);
        bool dead = false;
        int outer = -1;
        if (root_halts && t.kinds[si] == kind::final_state && t.parent[si] == root) {
            dead = true;
        } else if (order == priority::parent_first) {
            // An eventless row is tried within its [BSC] component only, under a scan policy:
            // the ancestors above the nearest parallel state take their turn in another one.
            bool const eventless = r.trigger[i] == eventless_id;
            if (r.trigger[i] >= 0 || eventless)
                for (int a = t.parent[si]; a >= 0 && outer < 0; a = t.parent[static_cast<std::size_t>(a)]) {
                    if (eventless && t.kinds[static_cast<std::size_t>(a)] == kind::parallel) break;
                    if (takes_unguarded(a, r.trigger[i])) outer = a;
                }
            dead = outer >= 0;
        } else if (r.trigger[i] >= 0 && !t.is_leaf(s) && t.end[si] > s + 1) {
            dead = true;
            for (int a = s + 1; a < t.end[si] && dead; ++a) {
                if (!t.is_leaf(a)) continue;
                bool taken = false;
                for (int b = a; b != s && !taken; b = t.parent[static_cast<std::size_t>(b)])
                    taken = takes_unguarded(b, r.trigger[i]);
                dead = taken;
            }
        }
        found.dead[i] = dead;
        if (dead && found.first_dead < 0) {
            found.first_dead = static_cast<int>(i);
            found.outer = outer;
        }
    }
    return found;
}

}  // namespace bsc::detail
// end include/bsc/detail/checks/dead_transitions.hpp
// begin include/bsc/detail/checks/determinism.hpp
// Determinism: two unguarded transitions on the same source and trigger conflict; a
// transition after an unguarded one on the same source and trigger, or on a family of its
// trigger (detail/model/event_families.hpp), is shadowed.


namespace bsc::detail {

struct row_pair {
    int first = -1;
    int second = -1;
    constexpr bool found() const { return first >= 0; }
};

struct determinism_findings {
    row_pair conflict;  // the first pair of unguarded rows on one source and trigger
    row_pair shadowed;  // the first unguarded row followed by a guarded one
};

// Only rows of the same source are compared (rows_by_source.hpp).
template <std::size_t N, std::size_t R>
constexpr determinism_findings find_nondeterminism(topology<N> const&, row_table<R> const& r) {
    determinism_findings found;
    auto const rows = rows_by_source<N>(r, [](std::size_t) { return true; });
    auto const& begin = rows.begin;
    auto const& order = rows.order;
    // Report the pair a reader meets first: by the earlier row, then by the later one.
    auto earlier = [](row_pair const& a, int i, int j) {
        return !a.found() || i < a.first || (i == a.first && j < a.second);
    };
    for (std::size_t s = 0; s < N; ++s)
        for (int a = begin[s]; a < begin[s + 1]; ++a) {
            auto const i = static_cast<std::size_t>(order[static_cast<std::size_t>(a)]);
            if (r.guarded[i]) continue;
            for (int b = a + 1; b < begin[s + 1]; ++b) {
                auto const j = static_cast<std::size_t>(order[static_cast<std::size_t>(b)]);
                // Row i takes every event row j takes: the same trigger, or a family of j's.
                if (!r.takes(r.trigger[i], r.trigger[j])) continue;
                bool const same = r.trigger[j] == r.trigger[i];
                row_pair& slot = r.guarded[j] || !same ? found.shadowed : found.conflict;
                if (earlier(slot, static_cast<int>(i), static_cast<int>(j)))
                    slot = {static_cast<int>(i), static_cast<int>(j)};
            }
        }
    return found;
}

}  // namespace bsc::detail
// end include/bsc/detail/checks/determinism.hpp
// begin include/bsc/detail/checks/done_events.hpp
// Rows on completion events (bsc::done<S>, SCXML's done.state.S) that can never fire:
//   - S is not a state of the chart (a misspelt name): nothing raises the event;
//   - S never completes: it is basic, final or the root (a final child of the root halts the
//     machine), a composite without a final child, or a parallel state one of whose regions
//     never reaches a final state;
//   - the row's source lies inside S and is not active when S completes: then S's final
//     child is, and for a parallel S its regions and, in each, what completed it.

#include <array>
#include <cstddef>
#include <type_traits>


namespace bsc::detail {

// The state whose completion an event is (done<S>: S), or void.
template <class E>
struct completed_state {
    using type = void;
};
template <class S>
struct completed_state<done<S>> {
    using type = S;
};

// Whether state s can complete: it raises bsc::done<s> in some configuration.
template <std::size_t N>
constexpr bool can_complete(topology<N> const& t, int s) {
    auto const i = static_cast<std::size_t>(s);
    if (t.kinds[i] == kind::composite) {
        for (int c = t.first_child[i]; c >= 0; c = t.next_sibling[static_cast<std::size_t>(c)])
            if (t.kinds[static_cast<std::size_t>(c)] == kind::final_state) return true;
        return false;
    }
    if (t.kinds[i] == kind::parallel) {
        for (int c = t.first_child[i]; c >= 0; c = t.next_sibling[static_cast<std::size_t>(c)])
            if (t.kinds[static_cast<std::size_t>(c)] != kind::final_state && !can_complete(t, c)) return false;
        return t.first_child[i] >= 0;
    }
    return false;
}

// Whether `source`, a state below s, is active when s completes.
template <std::size_t N>
constexpr bool active_when_complete(topology<N> const& t, int s, int source) {
    int const c = t.child_toward(s, source);
    if (t.kinds[static_cast<std::size_t>(s)] == kind::parallel)
        return c == source || active_when_complete(t, c, source);
    return c == source && t.kinds[static_cast<std::size_t>(c)] == kind::final_state;
}

enum class done_fault { none, not_in_chart, never_raised, source_inactive };

struct done_finding {
    int row = -1;
    done_fault fault = done_fault::none;
};

// The first row on a done event that can never fire. `completes[e]` is, for event e of the
// chart, the index of the state it completes (-1: not a done event; detail::unknown_state:
// done<S> of a state not in the chart).
template <std::size_t N, std::size_t R, std::size_t E>
constexpr done_finding find_dead_done_row(topology<N> const& t, row_table<R> const& r,
                                          std::array<int, E> const& completes) {
    constexpr int root = 1;
    for (std::size_t i = 0; i < R; ++i) {
        if (r.kinds[i] != row_kind::transition || r.trigger[i] < 0) continue;
        int const s = completes[static_cast<std::size_t>(r.trigger[i])];
        if (s == -1) continue;
        if (s == unknown_state) return {static_cast<int>(i), done_fault::not_in_chart};
        if (s <= root || !can_complete(t, s)) return {static_cast<int>(i), done_fault::never_raised};
        if (t.is_proper_ancestor(s, r.source[i]) && !active_when_complete(t, s, r.source[i]))
            return {static_cast<int>(i), done_fault::source_inactive};
    }
    return {};
}

// Whether a chart's events include a completion event: only then is there a row to check.
template <class... Events>
constexpr bool takes_done_event(type_list<Events...>) {
    return any_true({!std::is_void_v<typename completed_state<Events>::type>..., false});
}

// completes[e] for the events of a chart (see find_dead_done_row).
template <class Tags, class... Events>
constexpr std::array<int, sizeof...(Events)> completed_states(type_list<Events...>) {
    return {[] {
        using S = typename completed_state<Events>::type;
        if constexpr (std::is_void_v<S>)
            return -1;
        else
            return position_in<S, Tags>::value >= 0 ? position_in<S, Tags>::value : detail::unknown_state;
    }()...};
}

}  // namespace bsc::detail
// end include/bsc/detail/checks/done_events.hpp
// begin include/bsc/detail/checks/livelock.hpp
// Eventless livelock: a cycle of unguarded eventless transitions, which dispatch would
// follow forever. Nodes are basic states; u -> v when an unguarded eventless transition
// enabled in u (its source is u or an ancestor) enters v, and no other unguarded eventless
// transition enabled in u is tried before it (bsc/priority.hpp): with child-first priority,
// one whose source lies between u and the row's; with parent-first, one of an ancestor of the
// row's source.

// begin include/bsc/detail/checks/reachability.hpp
// Reachability (structure only, guards ignored) and dead ends. Both follow only the rows
// that can fire: `dead` marks the ones that never do (dead_transitions.hpp).


namespace bsc::detail {

// The states marked: flags, or flags and the list of the states in the order they were first
// marked (reachable_states works through that list).
template <std::size_t N>
constexpr void set_mark(std::array<bool, N>& m, int s) {
    m[static_cast<std::size_t>(s)] = true;
}
template <std::size_t N>
struct marked_states {
    std::array<bool, N> flag{};
    std::array<int, N> in_order{};
    std::size_t count = 0;
};
template <std::size_t N>
constexpr void set_mark(marked_states<N>& m, int s) {
    auto const i = static_cast<std::size_t>(s);
    if (m.flag[i]) return;
    m.flag[i] = true;
    m.in_order[m.count++] = s;
}

template <std::size_t N, class Marks>
constexpr void mark_entry(topology<N> const& t, Marks& m, int domain, int target);

// Marks s and the states its default entry activates (initial states, all regions, a
// history state's default).
template <std::size_t N, class Marks>
constexpr void mark_default_entry(topology<N> const& t, Marks& m, int s) {
    set_mark(m, s);
    auto const i = static_cast<std::size_t>(s);
    if (t.is_compound(s)) {
        if (t.initial_target[i] >= 0 && t.initial_target[i] != t.initial[i])
            mark_entry(t, m, s, t.initial_target[i]);  // a deep initial
        else if (t.initial[i] >= 0)
            mark_default_entry(t, m, t.initial[i]);
        for (int more : t.more_initial[i]) {  // initial<A, B>: each of the others
            if (more >= 0) mark_entry(t, m, s, more);
        }
    } else if (t.kinds[i] == kind::parallel) {
        for (int c = t.first_child[i]; c >= 0; c = t.next_sibling[static_cast<std::size_t>(c)])
            mark_default_entry(t, m, c);
    } else if (t.kinds[i] == kind::history && t.initial_target[i] >= 0) {
        // A history state enters its default (what it restores has been active before).
        mark_entry(t, m, t.parent[i], t.initial_target[i]);
    }
}

// Marks the states a transition into `target` enters below `domain`: the path, the default
// entries of parallel siblings on the path, and the default entry of the target. A transition
// with several targets (bsc::targets) is marked target by target: each marks the default
// entry of the regions the others enter otherwise, which keeps reachability an
// over-approximation (a state it calls unreachable is, whatever the targets).
template <std::size_t N, class Marks>
constexpr void mark_entry(topology<N> const& t, Marks& m, int domain, int target) {
    for (int a = target; a != domain && a >= 0; a = t.parent[static_cast<std::size_t>(a)]) {
        set_mark(m, a);
        int const p = t.parent[static_cast<std::size_t>(a)];
        if (p >= 0 && p != domain && t.kinds[static_cast<std::size_t>(p)] == kind::parallel)
            for (int c = t.first_child[static_cast<std::size_t>(p)]; c >= 0;
                 c = t.next_sibling[static_cast<std::size_t>(c)])
                if (c != a) mark_default_entry(t, m, c);
    }
    mark_default_entry(t, m, target);
}

// Whether entering state s can restore a child of `of` by shallow history, which enters that
// child by its default entry: s is a shallow history state, or a composite with a shallow
// history marker (which it is then the `of` of).
template <std::size_t N>
constexpr int restored_by_shallow_history(topology<N> const& t, int s) {
    auto const i = static_cast<std::size_t>(s);
    if (t.hist[i] != history::shallow) return -1;
    if (t.kinds[i] == kind::history) return t.parent[i];
    return t.kinds[i] == kind::composite ? s : -1;
}

// The states some sequence of firing rows reaches. Each state is visited once, when first
// reached, and then follows its own rows (grouped by source, rows_by_source.hpp): linear in
// the chart, whatever the order of its rows.
template <std::size_t N, std::size_t R>
constexpr std::array<bool, N> reachable_states(topology<N> const& t, row_table<R> const& r,
                                               std::array<bool, R> const& dead) {
    auto const rows = rows_by_source<N>(r, [&](std::size_t i) { return !dead[i] && r.target[i] >= 0; });
    marked_states<N> reach;
    std::array<bool, N> restoring{};  // composites a reached shallow history restores a child of
    std::array<bool, N> restored{};   // children a shallow history has re-entered by default
    // A shallow history restores a child that has been active, and enters it by default: its
    // initial states become active even if they never were (SCXML IRP test 388).
    auto const restore = [&](int c) {
        auto const ci = static_cast<std::size_t>(c);
        if (restored[ci] || t.kinds[ci] == kind::history) return;
        restored[ci] = true;
        mark_default_entry(t, reach, c);
    };
    mark_default_entry(t, reach, 0);
    for (std::size_t next = 0; next < reach.count; ++next) {
        int const s = reach.in_order[next];
        auto const si = static_cast<std::size_t>(s);
        for (int k = rows.begin[si]; k < rows.begin[si + 1]; ++k)
            for (int target : r.targets_of(static_cast<std::size_t>(rows.order[static_cast<std::size_t>(k)])))
                if (target >= 0) mark_entry(t, reach, -1, target);
        int const parent = t.parent[si];
        if (parent >= 0 && restoring[static_cast<std::size_t>(parent)]) restore(s);
        int const of = restored_by_shallow_history(t, s);
        if (of >= 0 && !restoring[static_cast<std::size_t>(of)]) {
            restoring[static_cast<std::size_t>(of)] = true;
            for (int c = t.first_child[static_cast<std::size_t>(of)]; c >= 0;
                 c = t.next_sibling[static_cast<std::size_t>(c)])
                if (reach.flag[static_cast<std::size_t>(c)]) restore(c);
        }
    }
    return reach.flag;
}

template <std::size_t N>
constexpr int find_unreachable(topology<N> const&, std::array<bool, N> const& reach) {
    for (std::size_t s = 1; s < N; ++s)
        if (!reach[s]) return static_cast<int>(s);
    return -1;
}

// Whether entering `target` necessarily enters basic state x again: x itself, or an ancestor
// whose initial children (or history, which remembers x) lead back down to x.
template <std::size_t N>
constexpr bool reenters(topology<N> const& t, int target, int x) {
    if (target == x) return true;
    if (!t.is_proper_ancestor(target, x)) return false;
    for (int c = target; c != x;) {
        auto const ci = static_cast<std::size_t>(c);
        int const toward = t.child_toward(c, x);
        if (t.kinds[ci] == kind::composite) {
            if (t.hist[ci] == history::deep) return true;
            if (t.hist[ci] == history::none && t.initial[ci] != toward) return false;
        }
        c = toward;
    }
    return true;
}

// A basic state x has a way out if some transition with a target can fire while x is active,
// exits x (its domain is above x) and does not necessarily enter x again. Such a transition
// leaves x itself or an ancestor of x, or a state in another region of a parallel ancestor of x
// (then its domain must be above that parallel state). Rows are grouped by source
// (rows_by_source.hpp), so both kinds are found without scanning every row for every state.
template <std::size_t N, std::size_t R>
constexpr int find_dead_end(topology<N> const& t, row_table<R> const& r, std::array<bool, R> const& dead,
                            std::array<bool, N> const& reach) {
    auto const rows = rows_by_source<N>(r, [&](std::size_t i) { return r.target[i] >= 0 && !dead[i]; });
    auto const& begin = rows.begin;
    auto const& order = rows.order;
    // Rows whose source lies in the states [lo, hi) of document order.
    auto way_out_among = [&](int lo, int hi, int x, int above) {
        for (int k = begin[static_cast<std::size_t>(lo)]; k < begin[static_cast<std::size_t>(hi)]; ++k) {
            auto const i = static_cast<std::size_t>(order[static_cast<std::size_t>(k)]);
            if (t.is_proper_ancestor(r.domain[i], above) && !reenters(t, r.target[i], x)) return true;
        }
        return false;
    };
    for (std::size_t xi = 1; xi < N; ++xi) {
        if (t.kinds[xi] != kind::basic || !reach[xi]) continue;
        int const x = static_cast<int>(xi);
        bool leaves = false;
        for (int a = x; a > 0 && !leaves; a = t.parent[static_cast<std::size_t>(a)]) {
            leaves = way_out_among(a, a + 1, x, x);
            int const p = t.parent[static_cast<std::size_t>(a)];
            if (!leaves && t.kinds[static_cast<std::size_t>(p)] == kind::parallel)
                leaves = way_out_among(p + 1, a, x, p) ||
                         way_out_among(t.end[static_cast<std::size_t>(a)], t.end[static_cast<std::size_t>(p)], x, p);
        }
        if (!leaves) return x;
    }
    return -1;
}

}  // namespace bsc::detail
// end include/bsc/detail/checks/reachability.hpp

namespace bsc::detail {

template <std::size_t R>
constexpr bool has_unguarded_eventless(row_table<R> const& r) {
    for (std::size_t i = 0; i < R; ++i)
        if (r.kinds[i] == row_kind::transition && !r.guarded[i] && r.trigger[i] == eventless_id) return true;
    return false;
}

// Calls f(u, v, source) for each edge u -> v between basic states that an unguarded eventless
// transition (from `source`, enabled in u) makes.
template <std::size_t N, std::size_t R, class F>
constexpr void for_each_eventless_edge(topology<N> const& t, row_table<R> const& r, priority order, F&& f) {
    std::array<bool, N> has_unguarded{};  // the states with an unguarded eventless row
    for (std::size_t i = 0; i < R; ++i)
        if (r.kinds[i] == row_kind::transition && !r.guarded[i] && r.trigger[i] == eventless_id)
            has_unguarded[static_cast<std::size_t>(r.source[i])] = true;
    // Whether a state from `below` up to `above` (exclusive) has one.
    auto const taken_between = [&](int below, int above) {
        for (int a = below; a != above && a >= 0; a = t.parent[static_cast<std::size_t>(a)])
            if (has_unguarded[static_cast<std::size_t>(a)]) return true;
        return false;
    };
    for (std::size_t i = 0; i < R; ++i) {
        if (r.kinds[i] != row_kind::transition || r.guarded[i] || r.trigger[i] != eventless_id) continue;
        int const s = r.source[i];
        if (order == priority::parent_first && taken_between(t.parent[static_cast<std::size_t>(s)], -1)) continue;
        std::array<bool, N> entered{};
        if (r.target[i] >= 0) mark_entry(t, entered, r.domain[i], r.target[i]);
        for (int u = s; u < t.end[static_cast<std::size_t>(s)]; ++u) {
            if (!t.is_leaf(u)) continue;
            if (order == priority::child_first && taken_between(u, s)) continue;
            if (r.target[i] < 0) {
                f(u, u, s);  // internal: it stays in the same states and fires again
                continue;
            }
            for (int v = 0; v < static_cast<int>(N); ++v)
                if (entered[static_cast<std::size_t>(v)] && t.is_leaf(v)) f(u, v, s);
        }
    }
}

template <std::size_t N, std::size_t R>
constexpr std::size_t count_eventless_edges(topology<N> const& t, row_table<R> const& r, priority order) {
    std::size_t n = 0;
    if (has_unguarded_eventless(r)) for_each_eventless_edge(t, r, order, [&](int, int, int) { ++n; });
    return n;
}

// Returns the source of an unguarded eventless transition on a cycle, or -1. E is the number
// of edges (count_eventless_edges); zero in the common case, which then costs nothing more.
template <std::size_t E, std::size_t N, std::size_t R>
constexpr int find_eventless_cycle(topology<N> const& t, row_table<R> const& r, priority order) {
    if constexpr (E == 0) {
        return -1;
    } else {
        struct edge {
            int from, to, source;
        };
        std::array<edge, E> edges{};
        std::size_t count = 0;
        for_each_eventless_edge(t, r, order, [&](int u, int v, int s) { edges[count++] = {u, v, s}; });
        // Peel off states without incoming or without outgoing edges among the rest: what remains
        // is the union of the cycles.
        std::array<bool, N> removed{};
        for (bool changed = true; changed;) {
            changed = false;
            std::array<int, N> in{}, out{};
            for (std::size_t e = 0; e < count; ++e)
                if (!removed[static_cast<std::size_t>(edges[e].from)] &&
                    !removed[static_cast<std::size_t>(edges[e].to)]) {
                    ++out[static_cast<std::size_t>(edges[e].from)];
                    ++in[static_cast<std::size_t>(edges[e].to)];
                }
            for (std::size_t v = 0; v < N; ++v)
                if (!removed[v] && (in[v] == 0 || out[v] == 0)) removed[v] = changed = true;
        }
        for (std::size_t e = 0; e < count; ++e)
            if (!removed[static_cast<std::size_t>(edges[e].from)] && !removed[static_cast<std::size_t>(edges[e].to)])
                return edges[e].source;
        return -1;
    }
}

}  // namespace bsc::detail
// end include/bsc/detail/checks/livelock.hpp
// begin include/bsc/detail/checks/row_text.hpp
// A row as the user wrote it, as text computed from its type: "Idle + go [ready] / start = Busy".
// Errors about a row carry it (bsc::error::as_written), so that the row at fault can be found
// by reading it. What the type does not hold is written generically: an unnamed guard is
// "[guard]", an unnamed action "/ action", a timeout "after(...)" (its delay is a value).
// Only rejected charts compute it.

#include <cstddef>
#include <string_view>

// begin include/bsc/dsl/named.hpp
// Names for guards and actions, shown by the diagram exports (<bsc/export.hpp>):
//
//   inline constexpr auto released = bsc::named<"released">(bsc::guard([](io const& c) { return !c.button; }));
//   inline constexpr auto start = bsc::named<"start">(bsc::action([](io& c) { c.motor.set(true); }));
//
// A named guard is still a guard and a named action still an action: wrapping changes neither
// what they do nor how they compose. A named bsc::guard composes with !, && and ||, a named
// bsc::action sequences with `,` and bsc::seq, and a named plain callable is used where the
// callable itself would be (as plain callables, it composes once an operand is a bsc::guard or
// bsc::action). The exports print composed guards and action sequences from the names of their
// parts ("!released && at_home", "start, light_on").
//
// bsc::named<"text">(f) keeps the name in the type and adds nothing to the chart's size;
// bsc::named(text, f) keeps a std::string_view in the wrapper, for names computed at compile
// time (e.g. from bsc::name_of); the chart, and each machine that copies it, grows by one
// std::string_view for each such name.

#include <cstddef>
#include <string_view>
#include <type_traits>
#include <utility>


namespace bsc::detail {

template <fixed_string Text>
struct static_name {
    static constexpr std::string_view name = Text.view();
};

struct stored_name {
    std::string_view name;
};

// A named guard or action derives from the wrapped one, so that it is a guard or an action of
// the same kind (bsc_guard, bsc_action) and keeps its size: holding it as a member would place
// two guard_base (or action_base) subobjects side by side, which takes a byte more.

/// A bsc guard with a name: a guard itself, so !, && and || apply to it.
template <class Name, class G>
struct named_guard : G, Name {};

/// A bsc action with a name: an action itself, so `,` and bsc::seq sequence it. A named
/// sequence sequenced further is flattened into its parts, as any sequence is.
template <class Name, class A>
struct named_action : A, Name {};

/// A plain callable with a name: called exactly as the callable is, so that bsc still picks
/// the longest argument list it accepts.
template <class Name, class F>
struct named_callable : Name {
    [[no_unique_address]] F fn;
    template <class... Args>
        requires callable_with<F, Args...>
    constexpr decltype(auto) operator()(Args&&... args) const noexcept(nothrow_callable_with<F, Args...>) {
        return fn(std::forward<Args>(args)...);
    }
};

// Naming a named guard or action again replaces its name.
template <class T>
constexpr T without_name(T t) {
    return t;
}
template <class Name, class G>
constexpr G without_name(named_guard<Name, G> g) {
    return static_cast<G&&>(g);
}
template <class Name, class A>
constexpr A without_name(named_action<Name, A> a) {
    return static_cast<A&&>(a);
}
template <class Name, class F>
constexpr F without_name(named_callable<Name, F> c) {
    return std::move(c.fn);
}

template <class Name, class F>
constexpr auto make_named(Name name, F f) {
    if constexpr (bsc_guard<F>)
        return named_guard<Name, F>{std::move(f), name};
    else if constexpr (bsc_action<F>)
        return named_action<Name, F>{std::move(f), name};
    else
        return named_callable<Name, F>{name, std::move(f)};
}

}  // namespace bsc::detail

namespace bsc {

/// Gives a guard or an action a name for the diagram exports: `bsc::named<"released">(g)`.
/// The name is part of the type: it costs nothing at run time.
template <detail::fixed_string Name, class F>
constexpr auto named(F f) {
    return detail::make_named(detail::static_name<Name>{}, detail::without_name(std::move(f)));
}

/// Gives a guard or an action a name held as a std::string_view (which must outlive the chart,
/// as a string literal or a bsc::name_of does): `bsc::named("released", g)`.
template <class F>
constexpr auto named(std::string_view name, F f) {
    return detail::make_named(detail::stored_name{name}, detail::without_name(std::move(f)));
}

}  // namespace bsc
// end include/bsc/dsl/named.hpp
// begin include/bsc/event_name.hpp
// The name of an event type, as bsc::event_set, dispatch_by_name and bsc::logger use it.

#include <array>
#include <concepts>
#include <cstddef>
#include <string_view>
#include <type_traits>


namespace bsc {

namespace detail {
// A static member `name` (a data member called name, e.g. `std::string name;` in an event that
// carries a name as data, is not the event's name).
template <class E>
concept names_itself = requires {
    requires std::convertible_to<decltype(E::name), std::string_view>;
    requires !std::is_member_object_pointer_v<decltype(&E::name)>;
};

// "done.state." and the state's name, in static storage.
template <class S>
inline constexpr auto done_event_text = [] {
    constexpr std::string_view prefix = "done.state.";
    constexpr std::string_view state = name_of<S>;
    std::array<char, prefix.size() + state.size()> text{};
    std::size_t n = 0;
    for (char c : prefix) text[n++] = c;
    for (char c : state) text[n++] = c;
    return text;
}();
}  // namespace detail

/// The name of event type E: its static member `name` if it declares one
/// (`static constexpr std::string_view name = "ON_P";`), otherwise bsc::name_of<E>. SCXML's
/// names for the two events bsc defines: "done.state.S" for bsc::done<S>, "*" for
/// bsc::any_event.
template <class E>
inline constexpr std::string_view event_name = [] {
    if constexpr (detail::names_itself<E>)
        return std::string_view{E::name};
    else
        return name_of<E>;
}();
template <class S>
inline constexpr std::string_view event_name<done<S>> = {detail::done_event_text<S>.data(),
                                                         detail::done_event_text<S>.size()};
template <>
inline constexpr std::string_view event_name<any_event> = "*";

}  // namespace bsc
// end include/bsc/event_name.hpp

namespace bsc::detail {

// The writers run twice: once counting characters, once filling a fixed_string of that size.
struct text_counter {
    std::size_t size = 0;
    constexpr void operator()(std::string_view s) { size += s.size(); }
};
template <std::size_t N>
struct text_filler {
    fixed_string<N>* out;
    std::size_t at = 0;
    constexpr void operator()(std::string_view s) {
        for (char const c : s) out->chars[at++] = c;
    }
};

// Operator precedence of a guard expression, for parentheses: || below && below !.
enum class guard_precedence { any, disjunction, conjunction, negation };

// The name a guard or an action carries in its type (bsc::named<"text">), or "" if none: a
// named guard or action derives from its static_name, and a named plain callable sits in the
// guard_fn, action_fn or state_action that wraps it (member fn).
template <class T>
constexpr std::string_view static_name_of() {
    if constexpr (names_itself<T>)
        return T::name;
    else if constexpr (requires { &T::fn; })
        return static_name_of<decltype(T::fn)>();
    else
        return {};
}

// A guard part: its name if it has one, else "guard" (compositions are specialised below).
template <class G>
struct guard_words {
    template <class Out>
    static constexpr void write(Out& out, guard_precedence) {
        out(static_name_of<G>().empty() ? std::string_view{"guard"} : static_name_of<G>());
    }
};
template <class S>
struct guard_words<in_guard<S>> {  // bsc::in<S>: "In(S)", as the exports write it
    template <class Out>
    static constexpr void write(Out& out, guard_precedence) {
        out("In(");
        out(name_of<S>);
        out(")");
    }
};
template <class G>
struct guard_words<not_guard<G>> {
    template <class Out>
    static constexpr void write(Out& out, guard_precedence) {
        out("!");
        guard_words<G>::write(out, guard_precedence::negation);
    }
};
template <class L, class R>
struct guard_words<and_guard<L, R>> {
    template <class Out>
    static constexpr void write(Out& out, guard_precedence outer) {
        bool const parens = outer > guard_precedence::conjunction;
        if (parens) out("(");
        guard_words<L>::write(out, guard_precedence::conjunction);
        out(" && ");
        guard_words<R>::write(out, guard_precedence::conjunction);
        if (parens) out(")");
    }
};
template <class L, class R>
struct guard_words<or_guard<L, R>> {
    template <class Out>
    static constexpr void write(Out& out, guard_precedence outer) {
        bool const parens = outer > guard_precedence::disjunction;
        if (parens) out("(");
        guard_words<L>::write(out, guard_precedence::disjunction);
        out(" || ");
        guard_words<R>::write(out, guard_precedence::disjunction);
        if (parens) out(")");
    }
};

template <class A>
struct action_words {
    template <class Out>
    static constexpr void write(Out& out) {
        out(static_name_of<A>().empty() ? std::string_view{"action"} : static_name_of<A>());
    }
};
template <class A>
struct action_words<state_action<A>> : action_words<A> {};
template <>
struct action_words<defer_action> {
    template <class Out>
    static constexpr void write(Out& out) {
        out("defer");
    }
};
template <class... As>
struct action_words<action_seq<As...>> {
    template <class Out>
    static constexpr void write(Out& out) {
        bool first = true;
        ((out(first ? "(" : ", "), action_words<As>::write(out), first = false), ...);
        out(")");
    }
};

template <class Row>
struct row_words;

// An event as written: its name; a completion event as `done<S>`, with S's name.
template <class E>
struct event_words {
    template <class Out>
    static constexpr void write(Out& out) {
        out(name_of<E>);
    }
};
template <class S>
struct event_words<done<S>> {
    template <class Out>
    static constexpr void write(Out& out) {
        out("done<");
        out(name_of<S>);
        out(">");
    }
};

template <class S, class Trigger, class G, class A, class T>
struct row_words<transition_row<S, Trigger, G, A, T>> {
    template <class Out>
    static constexpr void write(Out& out) {
        out(name_of<S>);
        if constexpr (std::is_same_v<Trigger, timeout_trigger>) {
            out(" + after(...)");
        } else if constexpr (!std::is_same_v<Trigger, eventless_trigger>) {
            out(" + ");
            event_words<typename Trigger::event>::write(out);
        }
        if constexpr (!std::is_same_v<G, no_guard>) {
            out(" [");
            guard_words<G>::write(out, guard_precedence::any);
            out("]");
        }
        if constexpr (!std::is_same_v<A, no_action>) {
            out(" / ");
            action_words<A>::write(out);
        }
        if constexpr (target_parts<T>::all::size > 1) {
            out(" = targets(");
            // clang-format off
            [&]<class... Targets>(type_list<Targets...>) {
                bool first = true;
                ((out(first ? "" : ", "), out(name_of<Targets>), first = false), ...);
            }(typename target_parts<T>::all{});
            // clang-format on
            out(")");
        } else if constexpr (target_parts<T>::local) {
            out(" = local(");
            out(name_of<typename target_parts<T>::state>);
            out(")");
        } else if constexpr (!std::is_same_v<T, no_target>) {
            out(" = ");
            out(name_of<T>);
        }
    }
};
template <class S, class A>
struct row_words<entry_row<S, A>> {
    template <class Out>
    static constexpr void write(Out& out) {
        out(name_of<S>);
        out(" + on_entry / ");
        action_words<A>::write(out);
    }
};
template <class S, class A>
struct row_words<initial_row<S, A>> {
    template <class Out>
    static constexpr void write(Out& out) {
        out(name_of<S>);
        out(" + on_initial / ");
        action_words<A>::write(out);
    }
};
template <class S, class A>
struct row_words<exit_row<S, A>> {
    template <class Out>
    static constexpr void write(Out& out) {
        out(name_of<S>);
        out(" + on_exit / ");
        action_words<A>::write(out);
    }
};

template <class Row>
constexpr std::size_t row_text_size() {
    text_counter count;
    row_words<Row>::write(count);
    return count.size;
}

/// The text of a row, e.g. "Idle + go [ready] = Busy".
template <class Row>
constexpr auto row_text() {
    fixed_string<row_text_size<Row>() + 1> text{};
    text_filler<row_text_size<Row>() + 1> fill{&text};
    row_words<Row>::write(fill);
    return text;
}

}  // namespace bsc::detail
// end include/bsc/detail/checks/row_text.hpp
// begin include/bsc/detail/checks/signatures.hpp
// Guards and actions that cannot be called, found where the chart is declared so that the
// error names the row they belong to (bsc::error::in_row) instead of surfacing later inside a
// machine's dispatch. A guard is called as g(context const&, event const&), g(context const&)
// or g(); an action as a(context&, event const&, raise&), a(context&, event const&), a(context&)
// or a(); an entry or exit action as a(context&, raise&), a(context&) or a() (the predicates of
// detail/invoke.hpp, which calls them so). Guards and actions combined with bsc::guard and bsc::action (!, &&, ||, the
// comma) are checked part by part; a callable of another kind is left to the machine.

#include <type_traits>


namespace bsc::detail {

// The first callable of a guard that cannot be called on (Ctx, E), as a one-element list.
template <class G, class Ctx, class E>
struct bad_guard {
    using type = type_list<>;
};
template <class F, class Ctx, class E>
struct bad_guard<guard_fn<F>, Ctx, E> {
    using type = std::conditional_t<guard_callable<F, Ctx, E>, type_list<>, type_list<F>>;
};
template <class G, class Ctx, class E>
struct bad_guard<not_guard<G>, Ctx, E> : bad_guard<G, Ctx, E> {};
template <class L, class R, class Ctx, class E>
struct bad_guard<and_guard<L, R>, Ctx, E> {
    using type = concat_t<typename bad_guard<L, Ctx, E>::type, typename bad_guard<R, Ctx, E>::type>;
};
template <class L, class R, class Ctx, class E>
struct bad_guard<or_guard<L, R>, Ctx, E> {
    using type = concat_t<typename bad_guard<L, Ctx, E>::type, typename bad_guard<R, Ctx, E>::type>;
};

// The states a guard tests with bsc::in<S>, in order, as a list: what make_chart checks are
// states of the chart that can be active (detail/checks/checks.hpp, check_in_guards). A guard
// with bsc::in<S> is called with the configuration (dsl/guard.hpp): its signature is valid.
template <class G>
struct in_states {
    using type = type_list<>;
};
template <class S>
struct in_states<in_guard<S>> {
    using type = type_list<S>;
};
template <class Name, class G>
struct in_states<named_guard<Name, G>> : in_states<G> {};
template <class G>
struct in_states<not_guard<G>> : in_states<G> {};
template <class L, class R>
struct in_states<and_guard<L, R>> {
    using type = concat_t<typename in_states<L>::type, typename in_states<R>::type>;
};
template <class L, class R>
struct in_states<or_guard<L, R>> {
    using type = concat_t<typename in_states<L>::type, typename in_states<R>::type>;
};

// The same for actions; Raise is what the checks hand them as the raise argument
// (raise_stand_in, dsl/action.hpp).
template <class A, class Ctx, class E, class Raise>
struct bad_action {
    using type = type_list<>;
};
template <class F, class Ctx, class E, class Raise>
struct bad_action<action_fn<F>, Ctx, E, Raise> {
    using type = std::conditional_t<action_callable<F, Ctx, E, Raise>, type_list<>, type_list<F>>;
};
template <class... As, class Ctx, class E, class Raise>
struct bad_action<action_seq<As...>, Ctx, E, Raise> {
    using type = concat_t<typename bad_action<As, Ctx, E, Raise>::type...>;
};
template <class A, class Ctx, class Raise>
struct bad_state_action {
    using type = std::conditional_t<state_action_callable<A, Ctx, Raise>, type_list<>, type_list<A>>;
};
template <class A, class Ctx, class Raise>
    requires bsc_action<A>
struct bad_state_action<A, Ctx, Raise> : bad_action<A, Ctx, state_change, Raise> {};

// An entry or exit row's action: state_action<F> as on_entry / on_exit make it; another
// kind is left to the machine.
template <class A, class Ctx, class Raise>
struct bad_entry_action {
    using type = type_list<>;
};
template <class F, class Ctx, class Raise>
struct bad_entry_action<state_action<F>, Ctx, Raise> : bad_state_action<F, Ctx, Raise> {};

// What a guard or action of a transition row is handed as its event.
template <class Trigger>
struct event_of_trigger {
    using type = eventless;  // eventless transitions and timeouts
};
template <class E>
struct event_of_trigger<event_trigger<E>> {
    using type = E;
};

// What a guard that cannot be called is: a bool value (plain lambdas under `!`, `&&`, `||`),
// or a callable of another signature.
template <class G>
struct guard_error {
    using type = error::guard_signature_not_supported<G>;
};
template <>
struct guard_error<bool> {
    using type = error::guard_is_a_bool_value<bool>;
};

// The errors of one row: at most one, wrapped in error::in_row so that it names the row.
template <class Ctx, class Raise, class Row>
constexpr auto signature_errors(Row const*) {
    if constexpr (is_transition_row<Row>) {
        using E = typename event_of_trigger<typename Row::trigger>::type;
        using trigger =
            std::conditional_t<std::is_same_v<typename Row::trigger, event_trigger<E>>, E, typename Row::trigger>;
        using guards = typename bad_guard<std::remove_cv_t<decltype(Row::guard)>, Ctx, E>::type;
        using actions = typename bad_action<std::remove_cv_t<decltype(Row::action)>, Ctx, E, Raise>::type;
        if constexpr (guards::size > 0)
            return type_list<error::in_row<typename Row::source, trigger, typename Row::target,
                                           typename guard_error<at<0, guards>>::type>>{};
        else if constexpr (actions::size > 0)
            return type_list<error::in_row<typename Row::source, trigger, typename Row::target,
                                           error::action_signature_not_supported<at<0, actions>>>>{};
        else
            return type_list<>{};
    } else {
        using keyword = std::conditional_t<is_entry_row<Row>, entry_keyword,
                                           std::conditional_t<is_initial_row<Row>, initial_keyword, exit_keyword>>;
        using actions = typename bad_entry_action<std::remove_cv_t<decltype(Row::action)>, Ctx, Raise>::type;
        if constexpr (actions::size > 0)
            return type_list<error::in_row<typename Row::source, keyword, no_target,
                                           error::action_signature_not_supported<at<0, actions>>>>{};
        else
            return type_list<>{};
    }
}

// The position of the first row of a chart whose guard or action cannot be called (-1: none),
// and that row's error.
template <class Ctx, class... Rows>
constexpr int first_signature_error(type_list<Rows...>) {
    constexpr bool bad[] = {
        (decltype(signature_errors<Ctx, raise_stand_in>(static_cast<Rows const*>(nullptr)))::size > 0)..., false};
    for (std::size_t i = 0; i < sizeof...(Rows); ++i)
        if (bad[i]) return static_cast<int>(i);
    return -1;
}
template <class Ctx, class Row>
using signature_error = at<0, decltype(signature_errors<Ctx, raise_stand_in>(static_cast<Row const*>(nullptr)))>;

}  // namespace bsc::detail
// end include/bsc/detail/checks/signatures.hpp
// begin include/bsc/detail/checks/structure.hpp
// Structural checks: every state declared once, every row's states in the tree, exactly one
// initial child per composite, no transition between orthogonal regions, every local
// transition's target inside its source.


namespace bsc::detail {

// The second declaration of a state declared twice, or -1.
template <class... Tags>
constexpr int find_duplicate(type_list<Tags...>) {
    constexpr int first[] = {position_in<Tags, type_list<Tags...>>::value..., 0};
    for (int i = 0; i < static_cast<int>(sizeof...(Tags)); ++i)
        if (first[i] != i) return i;
    return -1;
}

template <std::size_t N>
constexpr int find_initial_problem(topology<N> const& t) {
    for (std::size_t s = 1; s < N; ++s)
        if (t.kinds[s] == kind::composite && t.initial_count[s] != 1) return static_cast<int>(s);
    return -1;
}

template <std::size_t R>
constexpr int find_unknown_state(row_table<R> const& r) {
    for (std::size_t i = 0; i < R; ++i) {
        if (r.source[i] == unknown_state || r.target[i] == unknown_state) return static_cast<int>(i);
        for (int m : r.more_targets[i])
            if (m == unknown_state) return static_cast<int>(i);
    }
    return -1;
}

template <std::size_t N, std::size_t R>
constexpr int find_orthogonal_transition(topology<N> const& t, row_table<R> const& r) {
    for (std::size_t i = 0; i < R; ++i) {
        int const s = r.source[i], d = r.target[i];
        if (r.kinds[i] != row_kind::transition || d < 0) continue;
        int const l = t.lca(s, d);
        if (t.kinds[static_cast<std::size_t>(l)] == kind::parallel && l != s && l != d) return static_cast<int>(i);
    }
    return -1;
}

// The first history pseudo-state that is not a child of a composite, whose default does not
// lie inside its composite (or is a history state), or that is the source of a row other than
// on_initial; -1 if none.
template <std::size_t N, std::size_t R>
constexpr int find_invalid_history(topology<N> const& t, row_table<R> const& r) {
    for (std::size_t s = 1; s < N; ++s) {
        if (t.kinds[s] != kind::history) continue;
        auto const p = static_cast<std::size_t>(t.parent[s]);
        int const d = t.initial_target[s];
        if (t.kinds[p] != kind::composite || d < 0 || t.kinds[static_cast<std::size_t>(d)] == kind::history)
            return static_cast<int>(s);
    }
    for (std::size_t i = 0; i < R; ++i)
        if (r.kinds[i] != row_kind::initial && r.source[i] >= 0 &&
            t.kinds[static_cast<std::size_t>(r.source[i])] == kind::history)
            return r.source[i];
    return -1;
}

// The first on_initial row of a state that takes no initial transition (not a composite, or
// one with a history marker, which takes its history instead), or -1.
template <std::size_t N, std::size_t R>
constexpr int find_misplaced_initial_action(topology<N> const& t, row_table<R> const& r) {
    for (std::size_t i = 0; i < R; ++i) {
        if (r.kinds[i] != row_kind::initial) continue;
        auto const s = static_cast<std::size_t>(r.source[i]);
        if (t.kinds[s] == kind::history) continue;  // the action of a history state's default transition
        if (t.kinds[s] != kind::composite || t.hist[s] != history::none) return static_cast<int>(i);
    }
    return -1;
}

// The first row that defers but has no event trigger (eventless, a timeout), takes
// bsc::any_event (which would keep only its tag), or has a target; -1 if none.
template <std::size_t R>
constexpr int find_invalid_deferral(row_table<R> const& r, int any_event_trigger) {
    for (std::size_t i = 0; i < R; ++i)
        if (r.defers[i] && (r.trigger[i] < 0 || r.trigger[i] == any_event_trigger || r.target[i] >= 0))
            return static_cast<int>(i);
    return -1;
}

// Whether the states in `all` (n of them) lie pairwise in different regions of parallel states.
template <std::size_t N, std::size_t M>
constexpr bool orthogonal_set(topology<N> const& t, std::array<int, M> const& all, std::size_t n) {
    for (std::size_t a = 0; a < n; ++a)
        for (std::size_t b = a + 1; b < n; ++b)
            if (all[a] < 0 || all[b] < 0 || t.contains(all[a], all[b]) || t.contains(all[b], all[a]) ||
                t.kinds[static_cast<std::size_t>(t.lca(all[a], all[b]))] != kind::parallel)
                return false;
    return true;
}

// The first composite with several initial states (bsc::initial<A, B>) one of which does not
// lie below it, or two of which are not in different regions of a parallel state; -1 if none.
template <std::size_t N>
constexpr int find_initial_set_problem(topology<N> const& t) {
    for (std::size_t s = 1; s < N; ++s) {
        if (t.kinds[s] != kind::composite || t.more_initial[s][0] == -1) continue;
        auto const all = t.initial_states(s);
        std::size_t n = 1;  // the first always (-1 if it is not below s); then up to the first -1
        while (n < all.size() && all[n] != -1) ++n;  // (unknown_state, -2, counts: it is reported)
        for (std::size_t k = 0; k < n; ++k)
            if (all[k] < 0 || !t.is_proper_ancestor(static_cast<int>(s), all[k])) return static_cast<int>(s);
        if (!orthogonal_set(t, all, n)) return static_cast<int>(s);
    }
    return -1;
}

// The first row with several targets two of which are not in different regions of a parallel
// state (one contains the other, or their nearest common ancestor is a composite); -1 if none.
template <std::size_t N, std::size_t R>
constexpr int find_targets_not_orthogonal(topology<N> const& t, row_table<R> const& r) {
    for (std::size_t i = 0; i < R; ++i) {
        if (!r.several(i)) continue;
        auto const all = r.targets_of(i);
        std::size_t n = 0;
        while (n < all.size() && all[n] >= 0) ++n;
        if (!orthogonal_set(t, all, n)) return static_cast<int>(i);
    }
    return -1;
}

// The first local row whose target is not a proper descendant of its source, or -1.
template <std::size_t N, std::size_t R>
constexpr int find_misplaced_local(topology<N> const& t, row_table<R> const& r) {
    for (std::size_t i = 0; i < R; ++i)
        if (r.local[i] && !t.is_proper_ancestor(r.source[i], r.target[i])) return static_cast<int>(i);
    return -1;
}

}  // namespace bsc::detail
// end include/bsc/detail/checks/structure.hpp

namespace bsc::detail {

template <class Row>
struct trigger_type {
    using type = typename trigger_event<Row>::type;
};
template <class S, class G, class A, class T>
struct trigger_type<transition_row<S, eventless_trigger, G, A, T>> {
    using type = eventless_trigger;
};
template <class S, class G, class A, class T>
struct trigger_type<transition_row<S, timeout_trigger, G, A, T>> {
    using type = timeout_trigger;
};

// An error about the row at Index of the chart's rows (error::at_row names its position and,
// where the compiler prints strings legibly, the row as written).
template <class Chart, int Index, class Error>
using row_error = error::at_row<static_cast<std::size_t>(Index) + 1, Error,
#if BSC_DETAIL_PRINTS_STRING_ARGUMENTS
                                error::as_written<row_text<typename chart_model<Chart>::template row_at<Index>>()>
#else
                                void
#endif
                                >;

// Whether the tree and the rows are well formed, computed without reporting anything, so
// that the other checks are not even instantiated on a malformed chart.
template <class Chart>
constexpr bool structure_valid() {
    using model = chart_model<Chart>;
    return find_duplicate(typename model::tags{}) < 0 && find_unknown_state(model::rows) < 0 &&
           find_initial_problem(model::tree) < 0 && find_invalid_history(model::tree, model::rows) < 0 &&
           find_initial_set_problem(model::tree) < 0;
}

template <class Chart>
constexpr auto check_structure() {
    using model = chart_model<Chart>;
    constexpr int duplicate = find_duplicate(typename model::tags{});
    if constexpr (duplicate >= 0) {
        using S = typename model::template tag_at<duplicate>;
        constexpr int first = model::template index_of_state<S>::value;
        constexpr int implicit = model::tree.implicit[duplicate] ? duplicate : model::tree.implicit[first] ? first : -1;
        if constexpr (implicit >= 0)
            return type_list<
                error::initial_not_a_child<typename model::template tag_at<model::tree.parent[implicit]>, S>>{};
        else
            return type_list<error::duplicate_state<S>>{};
    } else {
        constexpr int unknown = find_unknown_state(model::rows);
        if constexpr (unknown >= 0) {
            using row = typename model::template row_at<unknown>;
            if constexpr (model::rows.source[unknown] == unknown_state)
                return type_list<row_error<Chart, unknown, error::state_not_in_chart<typename row::source>>>{};
            else
                return type_list<row_error<Chart, unknown, error::state_not_in_chart<typename row::target>>>{};
        } else {
            constexpr int composite = find_initial_problem(model::tree);
            if constexpr (composite >= 0) {
                using S = typename model::template tag_at<composite>;
                if constexpr (model::tree.initial_count[composite] == 0)
                    return type_list<error::missing_initial_state<S>>{};
                else
                    return type_list<error::multiple_initial_states<S>>{};
            } else {
                constexpr int history_state = find_invalid_history(model::tree, model::rows);
                constexpr int initial_set = find_initial_set_problem(model::tree);
                if constexpr (history_state >= 0)
                    return type_list<error::invalid_history_state<typename model::template tag_at<history_state>>>{};
                else if constexpr (initial_set >= 0)
                    return type_list<
                        error::initial_states_not_orthogonal<typename model::template tag_at<initial_set>>>{};
                else
                    return type_list<>{};
            }
        }
    }
}

template <class Chart>
constexpr auto check_orthogonality() {
    using model = chart_model<Chart>;
    constexpr int row = find_orthogonal_transition(model::tree, model::rows);
    if constexpr (row >= 0) {
        using R = typename model::template row_at<row>;
        return type_list<row_error<
            Chart, row, error::transition_between_orthogonal_regions<typename R::source, typename R::target>>>{};
    } else {
        return type_list<>{};
    }
}

template <class Chart>
constexpr auto check_local_targets() {
    using model = chart_model<Chart>;
    constexpr int row = find_misplaced_local(model::tree, model::rows);
    if constexpr (row >= 0) {
        using R = typename model::template row_at<row>;
        return type_list<
            row_error<Chart, row, error::local_target_outside_source<typename R::source, typename R::target>>>{};
    } else {
        return type_list<>{};
    }
}

template <class Chart>
constexpr auto check_several_targets() {
    using model = chart_model<Chart>;
    constexpr int row = find_targets_not_orthogonal(model::tree, model::rows);
    if constexpr (row >= 0) {
        using R = typename model::template row_at<row>;
        // clang-format off
        using named = decltype([]<class... S>(type_list<S...>) { return error::target_states<S...>{}; }(typename R::targets{}));
        // clang-format on
        return type_list<row_error<Chart, row, error::targets_not_orthogonal<typename R::source, named>>>{};
    } else {
        return type_list<>{};
    }
}

template <class Chart>
constexpr auto check_deferrals() {
    using model = chart_model<Chart>;
    constexpr int row = find_invalid_deferral(model::rows, position_in<any_event, typename model::events>::value);
    if constexpr (row >= 0) {
        using R = typename model::template row_at<row>;
        return type_list<
            row_error<Chart, row, error::invalid_deferral<typename R::source, typename trigger_type<R>::type>>>{};
    } else {
        return type_list<>{};
    }
}

template <class Chart>
constexpr auto check_initial_actions() {
    using model = chart_model<Chart>;
    constexpr int row = find_misplaced_initial_action(model::tree, model::rows);
    if constexpr (row >= 0)
        return type_list<row_error<
            Chart, row,
            error::initial_action_without_initial_transition<typename model::template row_at<row>::source>>>{};
    else
        return type_list<>{};
}

template <class Chart>
constexpr auto check_event_families() {
    using events = typename chart_model<Chart>::events;
    constexpr auto const& nearest = event_families<events>::nearest;
    constexpr int tangled = [] {
        for (std::size_t t = 0; t < nearest.size(); ++t)
            if (nearest[t] == -2) return static_cast<int>(t);
        return -1;
    }();
    if constexpr (tangled >= 0)
        return type_list<error::event_in_two_families<at<static_cast<std::size_t>(tangled), events>>>{};
    else
        return type_list<>{};
}

template <class Chart>
constexpr auto check_determinism() {
    using model = chart_model<Chart>;
    constexpr determinism_findings found = find_nondeterminism(model::tree, model::rows);
    constexpr row_pair conflict = found.conflict;
    constexpr row_pair shadowed = found.shadowed;
    if constexpr (conflict.found()) {
        using R = typename model::template row_at<conflict.second>;
        return type_list<
            row_error<Chart, conflict.second,
                      error::conflicting_transitions<typename R::source, typename trigger_type<R>::type>>>{};
    } else if constexpr (shadowed.found()) {
        using R = typename model::template row_at<shadowed.second>;
        return type_list<row_error<
            Chart, shadowed.second,
            error::shadowed_transition<typename R::source, typename trigger_type<R>::type, typename R::target>>>{};
    } else {
        return type_list<>{};
    }
}

template <class Chart>
constexpr auto check_done_events() {
    using model = chart_model<Chart>;
    constexpr done_finding found = [] {
        if constexpr (takes_done_event(typename model::events{}))
            return find_dead_done_row(model::tree, model::rows,
                                      completed_states<typename model::tags>(typename model::events{}));
        else
            return done_finding{};  // most charts: nothing to look at
    }();
    if constexpr (found.fault == done_fault::none) {
        return type_list<>{};
    } else {
        using R = typename model::template row_at<found.row>;
        using S = typename completed_state<typename trigger_type<R>::type>::type;
        if constexpr (found.fault == done_fault::not_in_chart)
            return type_list<row_error<Chart, found.row, error::done_of_state_not_in_chart<S>>>{};
        else if constexpr (found.fault == done_fault::never_raised)
            return type_list<row_error<Chart, found.row, error::done_never_raised<S>>>{};
        else
            return type_list<row_error<Chart, found.row, error::done_source_inactive<typename R::source, S>>>{};
    }
}

template <class Chart>
inline constexpr auto liveness_of = find_dead_transitions(chart_model<Chart>::tree, chart_model<Chart>::rows,
                                                          chart_model<Chart>::order);

template <class Chart>
constexpr auto check_dead_transitions() {
    using model = chart_model<Chart>;
    constexpr int row = liveness_of<Chart>.first_dead;
    if constexpr (row >= 0) {
        using R = typename model::template row_at<row>;
        constexpr int outer = liveness_of<Chart>.outer;
        if constexpr (outer >= 0)
            return type_list<row_error<
                Chart, row,
                error::dead_transition_behind_outer<typename R::source, typename trigger_type<R>::type,
                                                    typename R::target, typename model::template tag_at<outer>>>>{};
        else
            return type_list<row_error<
                Chart, row,
                error::dead_transition<typename R::source, typename trigger_type<R>::type, typename R::target>>>{};
    } else {
        return type_list<>{};
    }
}

template <class Chart>
constexpr auto check_reachability() {
    using model = chart_model<Chart>;
    constexpr auto const& dead = liveness_of<Chart>.dead;
    constexpr auto reach = reachable_states(model::tree, model::rows, dead);
    constexpr int unreachable = find_unreachable(model::tree, reach);
    if constexpr (unreachable >= 0) {
        return type_list<error::unreachable_state<typename model::template tag_at<unreachable>>>{};
    } else {
        constexpr int dead_end = find_dead_end(model::tree, model::rows, dead, reach);
        if constexpr (dead_end >= 0)
            return type_list<error::dead_end_state<typename model::template tag_at<dead_end>>>{};
        else
            return type_list<>{};
    }
}

template <class Chart>
constexpr auto check_livelock() {
    using model = chart_model<Chart>;
    constexpr std::size_t edges = count_eventless_edges(model::tree, model::rows, model::order);
    constexpr int source = find_eventless_cycle<edges>(model::tree, model::rows, model::order);
    if constexpr (source >= 0)
        return type_list<error::eventless_livelock<typename model::template tag_at<source>>>{};
    else
        return type_list<>{};
}

template <class Chart>
constexpr auto check_signatures() {
    using model = chart_model<Chart>;
    using context = typename Chart::context_type;
    constexpr int row = first_signature_error<context>(typename Chart::row_types{});
    if constexpr (row >= 0)
        return type_list<row_error<Chart, row, signature_error<context, typename model::template row_at<row>>>>{};
    else
        return type_list<>{};
}

// bsc::in<S> in a guard: S must be a state of the chart, and not a history state (never
// active). The first such S of each row's guard, as its error; nothing for a chart without
// bsc::in, which is most.
template <class Model, class S>
constexpr auto in_state_errors() {
    constexpr int s = state_index<S, typename Model::tags>::value;
    if constexpr (s < 0)
        return type_list<error::in_of_state_not_in_chart<S>>{};
    else if constexpr (Model::tree.kinds[static_cast<std::size_t>(s)] == kind::history)
        return type_list<error::in_of_history_state<S>>{};
    else
        return type_list<>{};
}
template <class Model, class Row>
constexpr auto in_guard_errors(Row const*) {
    if constexpr (row_tests_configuration<Row>) {
        using states = typename in_states<std::remove_cv_t<decltype(Row::guard)>>::type;
        // clang-format off
        return []<class... S>(type_list<S...>) {
            return concat_t<decltype(in_state_errors<Model, S>())...>{};
        }(states{});
        // clang-format on
    } else {
        return type_list<>{};
    }
}
template <class Model, class... Rows>
constexpr int first_in_guard_error(type_list<Rows...>) {
    constexpr bool bad[] = {(decltype(in_guard_errors<Model>(static_cast<Rows const*>(nullptr)))::size > 0)..., false};
    for (std::size_t i = 0; i < sizeof...(Rows); ++i)
        if (bad[i]) return static_cast<int>(i);
    return -1;
}

template <class Chart>
constexpr auto check_in_guards() {
    using model = chart_model<Chart>;
    if constexpr (!any_row_tests_configuration<typename Chart::row_types>) {
        return type_list<>{};
    } else {
        constexpr int row = first_in_guard_error<model>(typename Chart::row_types{});
        if constexpr (row >= 0) {
            using errors = decltype(in_guard_errors<model>(
                static_cast<typename model::template row_at<row> const*>(nullptr)));
            return type_list<row_error<Chart, row, at<0, errors>>>{};
        } else {
            return type_list<>{};
        }
    }
}

// The errors of a chart, as a type_list; empty for a well-formed chart.
template <class Chart>
constexpr auto check_chart() {
    if constexpr (!structure_valid<Chart>())
        return check_structure<Chart>();
    else
        // Each check runs, so one build reports every kind of problem it finds.
        return concat_t<decltype(check_orthogonality<Chart>()), decltype(check_local_targets<Chart>()),
                        decltype(check_several_targets<Chart>()), decltype(check_initial_actions<Chart>()),
                        decltype(check_deferrals<Chart>()), decltype(check_event_families<Chart>()),
                        decltype(check_determinism<Chart>()), decltype(check_done_events<Chart>()),
                        decltype(check_dead_transitions<Chart>()), decltype(check_reachability<Chart>()),
                        decltype(check_livelock<Chart>()), decltype(check_signatures<Chart>()),
                        decltype(check_in_guards<Chart>())>{};
}

}  // namespace bsc::detail
// end include/bsc/detail/checks/checks.hpp
// begin include/bsc/detail/row_storage.hpp
// The rows of a chart, held as one object: each row in a base of its own, keyed by its
// position. A row is read with row_at<I>(rows), a function template whose arguments are the
// position and that row's type alone (deduced from the base), so the symbols the compiler makes
// for a read do not spell every row of the chart, as a tuple's get<I> would: for a large chart
// those names, one per row read, were a large part of its compile time. An empty row (a guard
// and an action that capture nothing) takes no room.

#include <cstddef>
#include <utility>

namespace bsc::detail {

template <std::size_t I, class Row>
struct row_slot {
    [[no_unique_address]] Row row;
};

template <class Positions, class... Rows>
struct row_slots;
template <std::size_t... I, class... Rows>
struct row_slots<std::index_sequence<I...>, Rows...> : row_slot<I, Rows>... {};

template <class... Rows>
using row_storage = row_slots<std::index_sequence_for<Rows...>, Rows...>;

/// The row at position I (from 0, in make_chart's order).
template <std::size_t I, class Row>
constexpr Row const& row_at(row_slot<I, Row> const& slot) {
    return slot.row;
}

/// The row at position I, to move from (the row's type deduced from the base, as row_at's).
template <std::size_t I, class Row>
constexpr Row&& take_row(row_slot<I, Row>& slot) {
    return static_cast<Row&&>(slot.row);
}

/// Calls f with every row, in order.
template <class F, std::size_t... I, class... Rows>
constexpr decltype(auto) with_rows(row_slots<std::index_sequence<I...>, Rows...> const& rows, F&& f) {
    return std::forward<F>(f)(detail::row_at<I>(rows)...);
}

}  // namespace bsc::detail
// end include/bsc/detail/row_storage.hpp

namespace bsc::detail {
// Rows grouped by bsc::rows, held as a chart holds its rows (detail/row_storage.hpp).
template <class... Rows>
struct row_group {
    row_storage<Rows...> rows;
};
template <class A>
inline constexpr bool is_row_group = false;
template <class... Rows>
inline constexpr bool is_row_group<row_group<Rows...>> = true;

// How many rows an argument of bsc::rows or make_chart brings: a row one, a group its own.
template <class A>
inline constexpr std::size_t rows_in = 1;
template <class... Rows>
inline constexpr std::size_t rows_in<row_group<Rows...>> = sizeof...(Rows);

// Where each row of the flattened list comes from: its argument, and its position there.
template <class... A>
struct flat_positions {
    static constexpr std::size_t size = [] {
        std::size_t n = 0;
        for (std::size_t k : {rows_in<A>..., std::size_t{0}}) n += k;  // (a list: detail::max_fold)
        return n;
    }();
    struct from {
        std::size_t argument = 0;
        std::size_t position = 0;
    };
    static constexpr std::array<from, size> of = [] {
        std::array<from, size> out{};
        std::size_t j = 0, k = 0;
        for (std::size_t n : {rows_in<A>...}) {
            for (std::size_t i = 0; i < n; ++i) out[j++] = {k, i};
            ++k;
        }
        return out;
    }();
};

// An argument of bsc::rows or make_chart as a group: a group as it is, a row as a group of one;
// and the rows of a group.
template <class A>
struct group_of {
    using type = row_group<A>;
};
template <class... Rows>
struct group_of<row_group<Rows...>> {
    using type = row_group<Rows...>;
};
template <class Group>
struct rows_of;
template <class... Rows>
struct rows_of<row_group<Rows...>> {
    using type = type_list<Rows...>;
};
template <class A>
constexpr typename group_of<A>::type as_group(A&& a) {
    if constexpr (is_row_group<A>)
        return static_cast<A&&>(a);
    else
        return {{{static_cast<A&&>(a)}}};
}

// The rows and groups of rows A..., as one group. Each row is moved from the slot that holds
// it, named by its position and type (a cast to a known base), not found by a deduction among
// every row, which made a group of n rows cost O(n^2), nor by a function per row, whose name
// would spell the group. (Not std::tuple_cat and std::apply: their instantiations, a recursion
// over the tuples and a noexcept test of a call with every row, were most of what a chart of
// many groups cost to declare.)
template <class... A>
constexpr auto flatten_rows(A... a) {
    using positions = flat_positions<A...>;
    using groups = type_list<typename group_of<A>::type...>;
    using flat = concat_t<typename rows_of<typename group_of<A>::type>::type...>;
    row_storage<typename group_of<A>::type...> arguments{{as_group(static_cast<A&&>(a))}...};
    // clang-format off
    return [&]<std::size_t... J, class... Rs>(std::index_sequence<J...>, type_list<Rs...>) {
        return row_group<Rs...>{{{static_cast<Rs&&>(
            static_cast<row_slot<positions::of[J].position, Rs>&>(
                static_cast<row_slot<positions::of[J].argument, at<positions::of[J].argument, groups>>&>(arguments)
                    .row.rows)
                .row)}...}};
    }(std::make_index_sequence<positions::size>{}, flat{});
    // clang-format on
}

template <class Root>
constexpr bool is_compound_root() {
    if constexpr (is_node<Root>)
        return Root::node_kind == kind::composite || Root::node_kind == kind::parallel;
    else
        return false;
}
}  // namespace bsc::detail

namespace bsc {

/// A statechart over the context type `Context`: the state tree `Root`, the priority `Order`
/// among nested transitions (bsc/priority.hpp) and the rows.
/// Obtain one with make_chart; run it with bsc::machine.
template <class Context, class Root, priority Order, class... Rows>
struct chart {
    using context_type = Context;
    using root_type = Root;
    static constexpr priority order = Order;
    using row_types = detail::type_list<Rows...>;
    detail::row_storage<Rows...> rows;
};

namespace detail {
// The dead transitions that only the delays tell (detail/checks/dead_transitions.hpp finds the others):
// a timeout row that an unguarded timeout row, with a target, always beats. That row, of state
// C, leaves the states from C up to its domain no later than its delay after C's entry. Each
// such state P whose entry starts C's clock too (C is P, or C is active whenever P is: every
// composite between them has C's branch as its only child, and no row whose domain lies inside
// P exits C) leaves, with its clock, every state D below P that is likewise active with P. A
// timeout row of such a D with a longer delay never fires; with an equal delay, neither does
// one of C declared later, or one of an ancestor of C in C's [BSC] component (child first: the
// deeper state's row is tried first), or one of a descendant of C (parent first, or across a
// parallel state: the outer row is tried first, or its component takes its turn first). For D
// other than C, only where no other condition-driven row is tried before C's in C's component:
// one that fires in the cycle C's row comes due holds it back, one transition per component per
// cycle, and D's may come due meanwhile. (C's own timeouts compete by due time.)
// (make_chart reports it through the dead row's copy: dsl/row.hpp, timeout_trigger.) Returns
// the positions (from 1) of the first dead row found and of the row that beats it; {0, 0} if
// there is none.
struct dead_timeout {
    std::size_t row = 0;
    std::size_t fires_first = 0;
};

// Whether state d (p itself or below p) is active whenever p is, with the clock it had when p
// was entered.
template <std::size_t N, std::size_t Count>
constexpr bool active_with(topology<N> const& t, row_table<Count> const& r, int p, int d) {
    for (int below = d; below != p;) {
        int const x = t.parent[static_cast<std::size_t>(below)];
        auto const xi = static_cast<std::size_t>(x);
        if (t.kinds[xi] == kind::composite)  // a parallel state enters every region
            for (int other = t.first_child[xi]; other >= 0; other = t.next_sibling[static_cast<std::size_t>(other)])
                if (other != below && t.kinds[static_cast<std::size_t>(other)] != kind::history) return false;
        below = x;
    }
    for (std::size_t k = 0; k < Count; ++k)
        if (r.kinds[k] == row_kind::transition && r.domain[k] >= 0 && t.contains(p, r.domain[k]) &&
            t.is_proper_ancestor(r.domain[k], d))
            return false;
    return true;
}

// The [BSC] component of state s: the root, or the child of a parallel state that s lies in.
template <std::size_t N>
constexpr int component_of(topology<N> const& t, int s) {
    for (int a = s; a > 1; a = t.parent[static_cast<std::size_t>(a)])
        if (t.kinds[static_cast<std::size_t>(t.parent[static_cast<std::size_t>(a)])] == kind::parallel) return a;
    return 1;
}

// Whether a condition-driven row other than `first` and `other` is tried before `first` in its
// component: a guarded or internal one could fire in the cycle `first` comes due instead of it.
template <std::size_t N, std::size_t Count>
constexpr bool held_back(topology<N> const& t, row_table<Count> const& r, std::size_t first, std::size_t other,
                         priority order) {
    int const c = r.source[first];
    for (std::size_t k = 0; k < Count; ++k) {
        int const s = r.source[k];
        if (k == first || k == other || r.kinds[k] != row_kind::transition || r.trigger[k] >= 0) continue;
        if (s == c) {
            if (r.trigger[k] == eventless_id && k < first) return true;  // its timeouts compete by due time
        } else if (component_of(t, s) == component_of(t, c) &&
                   (order == priority::child_first ? t.is_proper_ancestor(c, s) : t.is_proper_ancestor(s, c))) {
            return true;
        }
    }
    return false;
}

template <std::size_t N, std::size_t Count>
constexpr dead_timeout find_dead_timeout(topology<N> const& t, row_table<Count> const& r,
                                         std::array<duration, Count> const& delay, priority order) {
    std::array<std::size_t, Count> timeouts{};
    std::size_t count = 0;
    for (std::size_t i = 0; i < Count; ++i)
        if (r.kinds[i] == row_kind::transition && r.trigger[i] <= -2) timeouts[count++] = i;
    for (std::size_t a = 0; a < count; ++a) {
        std::size_t const first = timeouts[a];
        if (r.guarded[first] || r.target[first] < 0 || r.domain[first] < 0) continue;
        int const c = r.source[first];
        for (int p = c; p >= 0 && !t.contains(p, r.domain[first]); p = t.parent[static_cast<std::size_t>(p)]) {
            if (p != c && !active_with(t, r, p, c)) break;  // nor is C for the states above
            for (std::size_t b = 0; b < count; ++b) {
                std::size_t const j = timeouts[b];
                int const d = r.source[j];
                if (j == first || !t.contains(p, d) || (d != p && !active_with(t, r, p, d))) continue;
                if (d != c && held_back(t, r, first, j, order)) continue;
                bool const inner_first = order == priority::child_first && component_of(t, c) == component_of(t, d);
                bool const tried_first = d == c        ? first < j
                                         : inner_first ? t.is_proper_ancestor(d, c)
                                                       : t.is_proper_ancestor(c, d);
                bool const beaten = delay[first] < delay[j] || (delay[first] == delay[j] && tried_first);
                if (beaten) return {j + 1, first + 1};
            }
        }
    }
    return {};
}

// Marks the dead row's parameter (timeout_trigger's destructor reports it).
template <class... Rows>
constexpr void mark_dead_timeout(dead_timeout const& dead, Rows&... rows) {
    std::size_t position = 0;
    auto const mark = [&](auto& row) {
        ++position;
        if constexpr (is_timeout_row<std::remove_cvref_t<decltype(row)>>)
            if (position == dead.row) row.trigger_value.delay = timeout_trigger::dead_mark(dead.row, dead.fires_first);
    };
    [[maybe_unused]] int const marked[] = {(mark(rows), 0)..., 0};  // (a list: detail::max_fold)
}

template <class... Rows>
constexpr std::array<duration, sizeof...(Rows)> delays_of(Rows const&... rows) {
    return {[&] {
        if constexpr (is_timeout_row<Rows>)
            return rows.trigger_value.delay;
        else
            return duration::zero();
    }()...};
}

template <class Errors>
struct rejected_chart_of;
template <class... Errors>
struct rejected_chart_of<type_list<Errors...>> {
    template <class Context>
    using type = rejected_chart<Context, Errors...>;
};

}  // namespace detail

/// Declares a chart: first the state tree, then the rows (transitions, entry and exit actions).
/// The static checks run here; a malformed chart fails to compile with an error that names
/// the offending state (see docs/checks.md).
/// Groups rows so that a set of rules can be defined once and reused in several charts:
/// `inline constexpr auto pause_rules = bsc::rows(row1, row2);` then
/// `bsc::make_chart<C>(tree, base_rules, pause_rules, row3)`. Groups may nest.
template <class... Rows>
constexpr auto rows(Rows... rows) {
    return detail::flatten_rows(std::move(rows)...);
}

/// `make_chart<Context, Priority, bsc::allow<Findings...>>(tree, rows...)` declares a chart that
/// allows the findings named (bsc/allow.hpp): the checks run, and those findings are dropped.
/// `make_chart<Context, bsc::parent_first>(tree, rows...)` declares a chart whose outer
/// transitions have priority over inner ones (bsc/priority.hpp); `make_chart<Context>` is
/// `make_chart<Context, bsc::child_first>`.
// (One function, the priority a defaulted parameter: a forwarding overload would move the rows
// into a second call, whose frame, spelling every row, a dead timeout's error would then carry.)
template <class Context, priority Order = priority::child_first, class Allowed = allow<>, class Root, class... Rows>
constexpr auto make_chart(Root root, Rows... rows) {
    if constexpr (!detail::is_allow<Allowed> || !detail::all_allowable<Allowed>) {
        return detail::rejected_chart<Context, error::finding_not_allowable<Allowed>>{};
    } else if constexpr (detail::any_true({detail::is_row_group<Rows>..., false})) {
        auto group = detail::flatten_rows(std::move(rows)...);
        // clang-format off
        return [&]<std::size_t... I, class... Rs>(detail::row_slots<std::index_sequence<I...>, Rs...>& slots) {
            return make_chart<Context, Order, Allowed>(
                std::move(root), static_cast<Rs&&>(static_cast<detail::row_slot<I, Rs>&>(slots).row)...);
        }(group.rows);
        // clang-format on
    } else if constexpr (!detail::is_compound_root<Root>()) {
        return detail::rejected_chart<Context, error::root_must_be_composite<Root>>{};
    } else if constexpr (!detail::all_true({detail::is_row<Rows>...})) {
        constexpr int bad =
            detail::position_in<std::false_type, detail::type_list<std::bool_constant<detail::is_row<Rows>>...>>::value;
        return detail::rejected_chart<
            Context, error::not_a_row<detail::at<static_cast<std::size_t>(bad), detail::type_list<Rows...>>>>{};
    } else {
        // The chart, or, when its checks find errors, the rejected_chart whose destruction
        // reports them.
        using chart_type = chart<Context, Root, Order, Rows...>;
        using errors = typename detail::without_allowed<Allowed, decltype(detail::check_chart<chart_type>())>::type;
        if constexpr (errors::size == 0) {
            if constexpr (detail::any_true({detail::is_timeout_row<Rows>..., false})) {
                auto const dead = detail::find_dead_timeout(detail::chart_model<chart_type>::tree,
                                                            detail::chart_model<chart_type>::rows,
                                                            detail::delays_of(rows...), Order);
                if (dead.row != 0) {
                    if (!std::is_constant_evaluated())
                        detail::bsc_dead_transition_timeout_behind_a_shorter_unguarded_timeout(dead.row,
                                                                                               dead.fires_first);
                    // In a constant expression, the error comes from the marked parameter's
                    // destruction, after this returns (detail::timeout_trigger).
                    chart_type built{{{std::move(rows)}...}};
                    detail::mark_dead_timeout(dead, rows...);
                    return built;
                }
            }
            return chart_type{{{std::move(rows)}...}};
        } else {
            return typename detail::rejected_chart_of<errors>::template type<Context>{};
        }
    }
}

}  // namespace bsc
// end include/bsc/chart.hpp
// begin include/bsc/chart_ref.hpp
// bsc::chart_ref<chart>: the type of a chart, named after the constexpr variable that holds it.
//
// A chart's own type spells out its whole state tree and every row, so each function the
// compiler generates for `bsc::machine<decltype(chart)>` carries that spelling in its symbol
// name, and for large charts building those names dominates compile time (it grows faster
// than the chart). `bsc::machine<bsc::chart_ref<chart>>` is the same machine, with the same
// behaviour, whose symbols name the variable instead:
//
//   inline constexpr auto chart = bsc::make_chart<io>(...);
//   using controller = bsc::machine<bsc::chart_ref<chart>>;
//   controller m{chart};
//
// Since the type names the variable, a machine of it stores no copy of the chart: every such
// machine reads one constant copy of `chart` (detail::shared_chart), so what the rows hold,
// delays, captured values, raised events, is folded into the code, and the machine is smaller
// by the chart's size.
//
// Requirements: `Chart` is a chart (from bsc::make_chart) declared as a constexpr variable
// with static storage duration (namespace scope, or a static data member). A chart_ref is made
// from `Chart` itself, or default-constructed; made from any other chart, even an equal one,
// it does not compile (bsc::detail::bsc_chart_ref_made_from_another_chart), since the machine
// would silently run `Chart` instead.

#include <type_traits>

namespace bsc::detail {
// Deliberately not constexpr: reaching it in the constant evaluation of chart_ref's constructor
// is the compile error, and its name says what is wrong.
inline void bsc_chart_ref_made_from_another_chart() {}
}  // namespace bsc::detail

namespace bsc {

template <auto const& Chart>
struct chart_ref : std::remove_cvref_t<decltype(Chart)> {
    using chart_type = std::remove_cvref_t<decltype(Chart)>;
    constexpr chart_ref() : chart_type(Chart) {}
    // Implicit, so that a machine of chart_ref<chart> is constructed from `chart` itself; an
    // immediate function, so that it can check that it is `chart` indeed.
    consteval chart_ref(chart_type const& other) : chart_type(other) {  // NOLINT(google-explicit-constructor)
        if (&other != &Chart) detail::bsc_chart_ref_made_from_another_chart();
    }
};

}  // namespace bsc

namespace bsc::detail {
template <class T>
inline constexpr bool is_chart_ref = false;
template <auto const& Chart>
inline constexpr bool is_chart_ref<chart_ref<Chart>> = true;
}  // namespace bsc::detail
// end include/bsc/chart_ref.hpp
// begin include/bsc/configuration.hpp
// The active configuration, and the list of active state names it yields for traces.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace bsc {

/// The active configuration: one ordinal per composite state, the position of its active child
/// (a byte; two bytes in a chart where a composite has more than 255 children). An inactive
/// composite keeps the child it had when it was last active, which is all that shallow and deep
/// history need. Parallel and basic states take no storage.
template <std::size_t Composites, class Ordinal = std::uint8_t>
struct configuration {
    using ordinal_type = Ordinal;
    std::array<Ordinal, Composites> active{};
    friend constexpr bool operator==(configuration const&, configuration const&) = default;
};
template <class Ordinal>
struct configuration<0, Ordinal> {
    using ordinal_type = Ordinal;
    friend constexpr bool operator==(configuration const&, configuration const&) = default;
};

/// The names of the active states, outermost first in document order (no allocation).
template <std::size_t Capacity>
class state_names {
public:
    constexpr void push_back(std::string_view name) { names_[size_++] = name; }
    constexpr std::size_t size() const { return size_; }
    constexpr bool empty() const { return size_ == 0; }
    constexpr std::string_view operator[](std::size_t i) const { return names_[i]; }
    constexpr auto begin() const { return names_.begin(); }
    constexpr auto end() const { return names_.begin() + static_cast<std::ptrdiff_t>(size_); }
    constexpr bool contains(std::string_view name) const {
        for (auto n : *this)
            if (n == name) return true;
        return false;
    }
    /// The same names in the same order.
    friend constexpr bool operator==(state_names const& a, state_names const& b) {
        if (a.size_ != b.size_) return false;
        for (std::size_t i = 0; i < a.size_; ++i)
            if (a.names_[i] != b.names_[i]) return false;
        return true;
    }
    /// The names joined by `separator`, e.g. "Mcs On Auto Mem".
    std::string joined(std::string_view separator = " ") const {
        std::string out;
        for (std::size_t i = 0; i < size_; ++i) {
            if (i) out += separator;
            out += names_[i];
        }
        return out;
    }

private:
    std::array<std::string_view, Capacity> names_{};
    std::size_t size_ = 0;
};

}  // namespace bsc
// end include/bsc/configuration.hpp
// begin include/bsc/data/channel.hpp
// Data channels of a Basic Statechart (the Basic Statechart paper [BSC], docs/references.md):
// the context's members through which a chart talks to its environment and to other charts.
// Plain members of the context are the chart's internal variables: an action's write is visible
// at once to every later guard.
//
// Who writes what follows the formalism, and the types say it: inputs are the plant's (the
// environment's), outputs the chart's. The environment holds a machine's context as const
// (machine::context() returns a const reference), the chart's actions receive it as non-const
// (Context&), and each channel's `set` is const or not accordingly:
//   bsc::input<T>   set(v) const: the environment writes; an action's write is a compile error
//                   (bsc::error::input_written_by_the_chart)
//   bsc::output<T>  set(v): actions write; the environment's write is a compile error
//                   (bsc::error::output_written_from_outside)
//   bsc::inout<T>   set(v) const: both write
// A channel's initial value is given by its constructor (bsc::input<bool> start{true}), not by a
// write before the machine runs.

#include <type_traits>
#include <utility>

// begin include/bsc/detail/access.hpp
// The one door to what users may not touch: a channel's latch and commit, a timer's update
// and its internal state, a machine's writable context, configuration, clock, timeout slots and
// queue. Only the machines, the explorer, the retentive state (bsc/retain.hpp), the VCD
// recorder and the project's own tests go through it; every class it opens names it as its
// only friend.

#include <cstddef>
#include <cstdint>
#include <type_traits>


namespace bsc::detail {

struct access {
    // ---- channels and timers: driven by the machine around each cycle and dispatch ----------
    template <class Channel>
    static constexpr void latch(Channel& c) {
        c.latch();
    }
    template <class Channel>
    static constexpr void commit(Channel& c) {
        c.commit();
    }
    // Both values of a channel at once, as a restored or decoded state has them: what it holds
    // now and what the next cycle boundary takes. (Not through set: an input's set is the
    // environment's, an output's the chart's; a restore is neither.)
    template <class Channel, class T>
    static constexpr void set_channel(Channel& c, T const& current, T const& pending) {
        c.now_ = current;
        c.next_ = pending;
    }
    template <class Timer>
    static constexpr void update(Timer& t, duration now) {
        t.update(now);
    }
    template <class Timer>
    static constexpr std::uint8_t timer_phase(Timer const& t) {
        return static_cast<std::uint8_t>(t.phase_);
    }
    template <class Timer>
    static constexpr duration timer_started(Timer const& t) {
        return t.started_;
    }
    template <class Timer>
    static constexpr void set_timer(Timer& t, std::uint8_t phase, bool expired, duration started, duration elapsed) {
        t.phase_ = static_cast<typename Timer::phase>(phase);
        t.expired_ = expired;
        t.started_ = started;
        t.elapsed_ = elapsed;
    }
    template <class Timer>
    static constexpr void set_timer_limit(Timer& t, duration limit) {
        t.limit_ = limit;
    }

    // ---- machines: read and written by the explorer, read by the tests ---------------------
    // (through the shared driver, which holds the data and names this class its friend)

    // The machine's context, writable: for what restores or decodes a machine's whole state
    // (retain, the explorer). The public context() is const: the environment's view.
    template <class M>
    static constexpr auto& context(M& m) {
        if constexpr (requires { typename std::remove_const_t<M>::driver_type; })
            return driver_of(m).context_.value;
        else
            return m.context_;  // a machine of a rejected chart (detail/runtime/rejected.hpp)
    }
    // The chart a machine runs: to build another machine of it (bsc/benchmark.hpp replays a
    // dispatch with a logger).
    template <class M>
    static constexpr auto const& chart(M const& m) {
        return driver_of(m).chart();
    }
    template <class M>
    static constexpr auto& configuration(M& m) {
        return driver_of(m).config_;
    }
    // The machine's clock (zero for a machine that keeps none: nothing it does depends on time).
    template <class M>
    static constexpr duration clock(M const& m) {
        return driver_of(m).cycle_time();
    }
    // Whether a cycle has run (the clock is the caller's time); false without a clock.
    template <class M>
    static constexpr bool clock_started(M const& m) {
        return driver_of(m).clock_started();
    }
    // Sets a machine's clock as if a cycle had run at `now` (or, started = false, as if none had).
    template <class M>
    static constexpr void set_clock(M& m, duration now, bool started = true) {
        driver_of(m).set_clock(now, started);
    }
    // Inside a dispatch, a cycle or the construction: the machine's data is in flux.
    template <class M>
    static constexpr bool running(M const& m) {
        return driver_of(m).running();
    }
    // Forgets the exception of the last failed run (a restored machine's last run was not its own).
    template <class M>
    static constexpr void forget_failure(M& m) {
        auto& d = driver_of(m);
        d.failure_.reset();
        if constexpr (requires { d.reported_.reset(); }) d.reported_.reset();
    }
    template <class M>
    static constexpr auto& armed(M& m) {
        return driver_of(m).armed_;
    }
    // The last outcome as the machine keeps it (outcome::ignored under a policy that keeps none).
    template <class M>
    static constexpr outcome last_outcome(M const& m) {
        return driver_of(m).kept_outcome();
    }
    template <class M>
    static constexpr void set_last_outcome(M& m, outcome last) {
        driver_of(m).record(last);
    }
    template <class M>
    static constexpr auto& queue(M& m) {
        return driver_of(m).queue_;
    }
    // The events a chart that defers keeps (an event_queue, or no_deferral for one that does not).
    template <class M>
    static constexpr auto& deferred(M& m) {
        return driver_of(m).deferred_;
    }
    // Whether a transition changed the configuration since the deferred events were last retried.
    template <class M>
    static constexpr bool deferral_pending_retry(M const& m) {
        if constexpr (std::remove_cvref_t<decltype(driver_of(m))>::defers)
            return driver_of(m).deferral_.changed;
        else
            return false;
    }
    template <class M>
    static constexpr void set_deferral_pending_retry(M& m, bool changed) {
        if constexpr (std::remove_cvref_t<decltype(driver_of(m))>::defers) {
            driver_of(m).deferral_.changed = changed;
            driver_of(m).deferral_.retry = 0;
        }
    }
    template <class M>
    static constexpr auto longest_timeout(M const& m) {
        return driver_of(m).longest_timeout();
    }
    template <class M>
    static constexpr auto row_delays(M const& m) {
        return driver_of(m).row_delays();
    }
    template <class M>
    static constexpr auto canonical_configuration(M const& m) {
        return driver_of(m).canonical_configuration();
    }
    template <class M>
    static constexpr bool timeout_armed(M const& m, std::size_t slot) {
        return driver_of(m).timeout_armed(slot);
    }
    template <class M>
    static constexpr auto active_flags(M const& m) {
        return driver_of(m).active_flags();
    }

private:
    template <class M>
    static constexpr auto& driver_of(M& m) {
        using driver = typename std::remove_const_t<M>::driver_type;
        if constexpr (std::is_const_v<M>)
            return static_cast<driver const&>(m);
        else
            return static_cast<driver&>(m);
    }
};

}  // namespace bsc::detail
// end include/bsc/detail/access.hpp

namespace bsc::detail {
// Lets the machine find channels among the context's members. Equal to any other, so that
// the channels' defaulted == compare their values.
struct channel_base {
    friend constexpr bool operator==(channel_base const&, channel_base const&) = default;
};

// The pending value of an input or inout, writable through the const context the environment
// holds: mutable storage. It is not declared `mutable` because GCC (12 at least) refuses to read
// a mutable member in constant evaluation, even of an object created there, and a machine with
// an input could then no longer run in a static_assert. Writing through the const view is
// defined: the channel itself is not a const object (a machine's context is not; only the view
// of it that context() returns is), so an input must not be set on a context or a machine
// declared const.
template <class T>
constexpr T& wire(T const& pending) {
    return const_cast<T&>(pending);  // NOLINT(cppcoreguidelines-pro-type-const-cast)
}
}  // namespace bsc::detail

namespace bsc {

/// An input channel: written by the environment between cycles (`set`), latched at the start
/// of each cycle (and each dispatch), so that every component of a cycle reads the same value.
/// Requirements: T is copyable.
template <class T>
class input : detail::channel_base {
public:
    constexpr input() = default;
    constexpr explicit input(T initial) : next_(initial), now_(initial) {}
    /// The latched value, as guards and actions see it during this cycle.
    constexpr T const& get() const { return now_; }
    constexpr operator T const&() const { return now_; }  // NOLINT
    /// Written by the environment (which holds the machine's context as const) and by the links
    /// of a bsc::system; visible from the next cycle on.
    constexpr void set(T value) const { detail::wire(next_) = value; }
    /// Chosen for a non-const input, whatever the argument: the chart's actions receive the
    /// context as non-const, and a chart does not write its own inputs. A compile error.
    template <class U = T>
    constexpr void set(U&&) {
        detail::report<error::input_written_by_the_chart<T>>();
    }
    /// The value that the next cycle will latch.
    constexpr T const& pending() const { return next_; }
    friend constexpr bool operator==(input const&, input const&) = default;

private:
    friend struct detail::access;  // the machine latches and commits
    constexpr void latch() { now_ = next_; }
    constexpr void commit() {}
    // The pending value is the plant's wire, not the machine's state, until the next cycle
    // latches it: the environment writes it through the const context it holds, so it is
    // mutable storage (detail::wire). What the chart reads (now_) changes only when the
    // machine latches.
    T next_{};
    T now_{};
};

/// An output channel, double-buffered: actions write the next value (`set`); the published
/// value (`get`) changes at the end of the cycle (or dispatch), when every component has run.
template <class T>
class output : detail::channel_base {
public:
    constexpr output() = default;
    constexpr explicit output(T initial) : next_(initial), now_(initial) {}
    /// The published value: what the environment and other charts read.
    constexpr T const& get() const { return now_; }
    constexpr operator T const&() const { return now_; }  // NOLINT
    /// Written by actions; published at the end of the cycle.
    constexpr void set(T value) { next_ = value; }
    /// Chosen for a const output: the environment holds the machine's context as const, and
    /// only the chart writes its outputs. A compile error. (The parameter is T, as the action's
    /// overload's, so that a non-const output always takes that one, whatever the argument.)
    template <class U = T>
    constexpr void set(std::type_identity_t<U>) const {
        detail::report<error::output_written_from_outside<T>>();
    }
    constexpr T const& pending() const { return next_; }
    friend constexpr bool operator==(output const&, output const&) = default;

private:
    friend struct detail::access;  // the machine latches and commits
    constexpr void latch() {}
    constexpr void commit() { now_ = next_; }
    T next_{};
    T now_{};
};

/// A channel that is both input and output ([BSC] allows it): written by the environment or
/// by actions (`set` works on the const context and on the non-const one), read as the value
/// latched at the start of the cycle; writes take effect at the next cycle boundary.
template <class T>
class inout : detail::channel_base {
public:
    constexpr inout() = default;
    constexpr explicit inout(T initial) : next_(initial), now_(initial) {}
    constexpr T const& get() const { return now_; }
    constexpr operator T const&() const { return now_; }  // NOLINT
    constexpr void set(T value) const { detail::wire(next_) = value; }
    constexpr T const& pending() const { return next_; }
    friend constexpr bool operator==(inout const&, inout const&) = default;

private:
    friend struct detail::access;  // the machine latches and commits
    constexpr void latch() { now_ = next_; }
    constexpr void commit() { now_ = next_; }
    // Mutable storage as an input's (detail::wire): the environment writes it through the const
    // context.
    T next_{};
    T now_{};
};

template <class T>
inline constexpr bool is_channel = std::is_base_of_v<detail::channel_base, T>;

}  // namespace bsc

namespace bsc::detail {
// Channel kinds: bsc::input, bsc::output, bsc::inout (each only itself).
template <class T>
inline constexpr bool is_input_channel = false;
template <class T>
inline constexpr bool is_input_channel<input<T>> = true;
template <class T>
inline constexpr bool is_output_channel = false;
template <class T>
inline constexpr bool is_output_channel<output<T>> = true;
template <class T>
inline constexpr bool is_inout_channel = false;
template <class T>
inline constexpr bool is_inout_channel<inout<T>> = true;

// The type of a channel's value.
template <class Channel>
using channel_value = std::remove_cvref_t<decltype(std::declval<Channel const&>().get())>;
}  // namespace bsc::detail
// end include/bsc/data/channel.hpp
// begin include/bsc/data/timer.hpp
// BSC timers (the Basic Statechart paper [BSC] in docs/references.md, section III.C): data in
// the context, started or reset by actions, updated by the machine at the beginning of each
// cycle. A timer started during cycle k begins timing at cycle k+1; its expired flag `tm()` turns
// true at the first cycle whose time is at least the limit after that.

#include <cstdint>


namespace bsc {

namespace detail {
struct timer_base {};
}  // namespace detail

/// A timer with a fixed limit. Requirements: limit >= 0.
class timer : detail::timer_base {
public:
    constexpr timer() = default;
    constexpr explicit timer(duration limit) : limit_(limit) {}

    /// Starts (or restarts) the timer; timing begins at the next cycle. Clears tm().
    constexpr void start() {
        phase_ = phase::pending;
        expired_ = false;
        elapsed_ = duration::zero();
    }
    /// Stops the timer and clears tm() and elapsed().
    constexpr void reset() {
        phase_ = phase::idle;
        expired_ = false;
        elapsed_ = duration::zero();
    }
    /// The paper's `tm`: the limit has been reached or passed.
    constexpr bool tm() const { return expired_; }
    constexpr bool expired() const { return expired_; }
    constexpr bool running() const { return phase_ == phase::running && !expired_; }
    constexpr duration limit() const { return limit_; }
    /// Time since timing began (zero unless running or expired).
    constexpr duration elapsed() const { return elapsed_; }

    friend constexpr bool operator==(timer const& a, timer const& b) {
        return a.limit_ == b.limit_ && a.started_ == b.started_ && a.elapsed_ == b.elapsed_ && a.phase_ == b.phase_ &&
               a.expired_ == b.expired_;
    }

private:
    friend struct detail::access;  // the machine updates it; the explorer encodes it
    // Called by the machine at the beginning of each cycle with the cycle's time.
    constexpr void update(duration now) {
        if (phase_ == phase::pending) {
            phase_ = phase::running;
            started_ = now;
        }
        if (phase_ == phase::running) {
            elapsed_ = detail::elapsed(started_, now);
            if (elapsed_ >= limit_) expired_ = true;
        } else {
            elapsed_ = duration::zero();
        }
    }

    enum class phase : std::uint8_t { idle, pending, running };
    duration limit_{};
    duration started_{};
    duration elapsed_{};
    phase phase_ = phase::idle;
    bool expired_ = false;
};

}  // namespace bsc
// end include/bsc/data/timer.hpp
// begin include/bsc/dsl/delayed.hpp
// Delayed events to self: the actions bsc::raise_after and bsc::cancel_delayed. They reach the
// machine's pending events (detail/runtime/delayed_events.hpp) through the raise argument that every
// action receives; a chart that uses them gets a queue with slots for them (detail/runtime/queue_for.hpp).

#include <cstdlib>
#include <stdexcept>
#include <type_traits>
#include <utility>


namespace bsc::detail {

// bsc::raise_after and bsc::cancel_delayed: actions that reach the machine's delayed events
// (detail/runtime/delayed_events.hpp) through the raise argument.
template <class E>
struct delayed_raise : action_base {
    duration delay;
    E event;
    int id;
    template <class Ctx, class Ev, class Raise>
    constexpr void operator()(Ctx&, Ev const&, Raise& raise) const noexcept(std::is_nothrow_copy_constructible_v<E>) {
        (void)raise.schedule(delay, event, id);
    }
};
struct cancel_delayed_action : action_base {
    int id;
    template <class Ctx, class Ev, class Raise>
    constexpr void operator()(Ctx&, Ev const&, Raise& raise) const noexcept {
        raise.cancel(id);
    }
};

// Deliberately not constexpr (as bsc_after_negative_delay in dsl/row.hpp): in a constexpr chart,
// reaching it is the compile error, and its name says what is wrong; a chart built at run time
// throws (or aborts without exceptions). 0 is "no id": bsc::raise_after without an id sends
// under it, and nothing can be cancelled by it.
[[noreturn]] inline void bsc_cancel_delayed_id_zero_names_no_delayed_event() {
#if defined(__cpp_exceptions)
    throw std::invalid_argument(
        "bsc::cancel_delayed: id 0 names no delayed event (it is the id of none); send with "
        "bsc::raise_after(delay, e, id) and cancel with the same nonzero id");
#else
    std::abort();
#endif
}

template <class A>
inline constexpr bool is_delayed_raise = false;
template <class E>
inline constexpr bool is_delayed_raise<delayed_raise<E>> = true;

// Whether an action sends or cancels delayed events: then the machine keeps slots for them.
template <class A>
inline constexpr bool sends_delayed = false;
template <class E>
inline constexpr bool sends_delayed<delayed_raise<E>> = true;
template <>
inline constexpr bool sends_delayed<cancel_delayed_action> = true;
template <class... As>
inline constexpr bool sends_delayed<action_seq<As...>> = (sends_delayed<As> || ...);
template <class A>
inline constexpr bool sends_delayed<state_action<A>> = sends_delayed<A>;

}  // namespace bsc::detail

namespace bsc {

/// An action that raises `e` to the machine after `delay` (SCXML's `<send delay>` to itself):
/// the first `step(now)` whose time is at least the machine's clock when the action ran plus
/// `delay` processes it, after the components' turns, as a raised event. It is not tied to the
/// state that sent it; `bsc::cancel_delayed(id)` cancels it while it is pending (an id of 0 is
/// none). The machine keeps `Policy::delayed_capacity` pending events; one more is dropped and
/// the run reports `outcome::queue_overflow`. An event whose due time would lie past
/// bsc::duration::max() never comes due, and is not kept (detail/runtime/delayed_events.hpp).
/// Requirements: `e` is an event of the chart (or of a family of one); 0 <= delay <=
/// bsc::duration::max() (as for bsc::after: otherwise a constexpr chart does not compile, and
/// one built at run time throws std::invalid_argument / std::out_of_range).
template <class Rep, class Period, class E>
constexpr auto raise_after(std::chrono::duration<Rep, Period> delay, E e, int id = 0) {
    return detail::delayed_raise<E>{{}, detail::checked_delay(delay), std::move(e), id};
}

/// An action that cancels the delayed events still pending under `id` (bsc::raise_after).
/// Requirements: id != 0 (0 is no id; a constexpr chart with cancel_delayed(0) does not compile,
/// the error naming bsc_cancel_delayed_id_zero_names_no_delayed_event, and one built at run time
/// throws std::invalid_argument).
constexpr auto cancel_delayed(int id) {
    if (id == 0) detail::bsc_cancel_delayed_id_zero_names_no_delayed_event();
    return detail::cancel_delayed_action{{}, id};
}

}  // namespace bsc
// end include/bsc/dsl/delayed.hpp
// begin include/bsc/fields.hpp
// bsc::fields<T>: what the members of a context type are, for a type that is not a plain
// aggregate (a class with private members, constructors or base classes, or more than 128
// members). Every part of bsc that walks a machine's state uses it: channels' latch and commit,
// timers' update, retentive state, the explorer, the waveform and the network. Aggregates need
// nothing: their members are found without it. <bsc/adapt/hana.hpp> specialises it for every
// type adapted with Boost.Hana.

namespace bsc {

/// Specialise for a type whose members bsc cannot find by itself:
///
///     template <> struct bsc::fields<axis> {
///         static constexpr std::array<std::string_view, 2> names{"speed", "limit"};
///         template <class Self, class F>   // Self: axis or axis const
///         static constexpr decltype(auto) apply(Self& self, F&& f) { return f(self.speed_, self.limit_); }
///     };
///
/// Requirements: `names` holds one name per member, in the order in which `apply` passes them
/// to `f`, each as an lvalue of the object. Members left out are not part of the machine's state
/// (neither saved, explored nor recorded) and their channels and timers are not driven.
template <class T>
struct fields {};

}  // namespace bsc
// end include/bsc/fields.hpp
// begin include/bsc/machine.hpp
// bsc::machine: the compiled back end. For an event type, dispatch is a nest of switches on
// the configuration bytes that visits only the states where a transition on that event can
// leave; at each basic state the candidate transitions, their exits, action and entries are
// straight-line code fixed at compile time. Parallel regions select first and fire after,
// as SCXML's microstep does. The public interface and the run to completion are the shared
// driver's (detail/runtime/driver.hpp); this file selects and fires.

#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

// begin include/bsc/detail/compiled/plan.hpp
// Compile-time dispatch plans: for a trigger, which states lead to a transition and, for each
// basic state, which transitions are its candidates in the chart's priority order (deepest
// source first, or outermost first; then declaration order). The compiled machine expands these into switches and straight-line
// code; nothing here exists at run time.

#include <array>

// begin include/bsc/detail/model/layout.hpp
// What every back end lays out the same way, computed once from the chart model: the
// components of a BSC cycle, the timeout slots, the children of each state, the bytes of the
// initial configuration, the transitions in declaration order and the entry and exit rows of
// each state. Both back ends number these alike because both read them from here.

#include <array>
#include <cstddef>
#include <cstdint>


namespace bsc::detail {

template <class Model>
struct chart_layout {
    static constexpr auto const& tree = Model::tree;
    using ordinal_type = typename Model::ordinal_type;
    static constexpr auto const& rows = Model::rows;
    static constexpr int N = Model::N;
    static constexpr int R = Model::R;
    static constexpr int root = 1;  // state 0 is the implicit top above the chart's root

    // Whether row `row` is a transition on `trigger`: an event's position, eventless_id, or
    // any_condition (eventless or timeout).
    static constexpr bool is_transition_on(int row, int trigger) {
        auto const r = static_cast<std::size_t>(row);
        if (rows.kinds[r] != row_kind::transition) return false;
        if (trigger == any_condition) return rows.trigger[r] < 0;
        // A row on a family of the trigger's event takes it too (detail/model/event_families.hpp).
        if constexpr (Model::has_families)
            return rows.takes(rows.trigger[r], trigger);
        else
            return rows.trigger[r] == trigger;
    }

    static constexpr bool has_trigger(int trigger) {
        for (int r = 0; r < R; ++r)
            if (is_transition_on(r, trigger)) return true;
        return false;
    }

    static constexpr bool is_timeout_row(int row) {
        auto const r = static_cast<std::size_t>(row);
        return rows.kinds[r] == row_kind::transition && rows.trigger[r] <= timeout_trigger_id(0);
    }

    // The children of state S, in document order.
    template <int S>
    static constexpr auto children = [] {
        std::array<int, static_cast<std::size_t>(tree.child_count[static_cast<std::size_t>(S)])> out{};
        std::size_t n = 0;
        for (int c = tree.first_child[static_cast<std::size_t>(S)]; c >= 0;
             c = tree.next_sibling[static_cast<std::size_t>(c)])
            out[n++] = c;
        return out;
    }();

    // BSC components: the root and every child of a parallel state, in document order. In a
    // cycle each fires at most one condition-driven transition, chosen from the states between
    // its active frontier (a basic state, or a parallel state whose children are components of
    // their own) and its root.
    static constexpr int component_count() {
        int n = 1;
        for (int s = 2; s < N; ++s)
            n += tree.kinds[static_cast<std::size_t>(tree.parent[static_cast<std::size_t>(s)])] == kind::parallel;
        return n;
    }
    static constexpr auto components = [] {
        std::array<int, static_cast<std::size_t>(component_count())> out{};
        std::size_t n = 0;
        out[n++] = root;
        for (int s = 2; s < N; ++s)
            if (tree.kinds[static_cast<std::size_t>(tree.parent[static_cast<std::size_t>(s)])] == kind::parallel)
                out[n++] = s;
        return out;
    }();

    // Every timeout row has a slot for the time from which its delay counts: the entry of its
    // source, or the cycle it last fired in for an internal timeout (which re-arms itself).
    // Slots are numbered by source state in document order, then by row, so the slots of one
    // state are contiguous: timeout_slot[s] is the first (-1 if none), timeout_slot_count[s]
    // how many; row_timeout_slot[r] is row r's (-1 for other rows).
    static constexpr auto timeout_slot_count = [] {
        std::array<int, static_cast<std::size_t>(N)> count{};
        for (int r = 0; r < R; ++r)
            if (is_timeout_row(r)) ++count[static_cast<std::size_t>(rows.source[static_cast<std::size_t>(r)])];
        return count;
    }();
    static constexpr auto timeout_slot = [] {
        std::array<int, static_cast<std::size_t>(N)> first{};
        int n = 0;
        for (std::size_t s = 0; s < first.size(); ++s) {
            first[s] = timeout_slot_count[s] > 0 ? n : -1;
            n += timeout_slot_count[s];
        }
        return first;
    }();
    static constexpr int timeout_slots = [] {
        int n = 0;
        for (int count : timeout_slot_count) n += count;
        return n;
    }();
    static constexpr auto row_timeout_slot = [] {
        std::array<int, static_cast<std::size_t>(R)> slot{};
        std::array<int, static_cast<std::size_t>(N)> used{};
        for (int r = 0; r < R; ++r) {
            auto const source = static_cast<std::size_t>(rows.source[static_cast<std::size_t>(r)]);
            slot[static_cast<std::size_t>(r)] = is_timeout_row(r) ? timeout_slot[source] + used[source]++ : -1;
        }
        return slot;
    }();
    // The state whose entry arms a slot.
    static constexpr auto timeout_slot_state = [] {
        std::array<int, static_cast<std::size_t>(timeout_slots)> state{};
        for (int s = 0; s < N; ++s)
            for (int k = 0; k < timeout_slot_count[static_cast<std::size_t>(s)]; ++k)
                state[static_cast<std::size_t>(timeout_slot[static_cast<std::size_t>(s)] + k)] = s;
        return state;
    }();
    // Whether some state has two timeout rows or more: only their timeouts compete by due time
    // (the one that came due first fires; docs/semantics.md, "Timers").
    static constexpr bool has_competing_timeouts = [] {
        for (int count : timeout_slot_count)
            if (count > 1) return true;
        return false;
    }();

    // Whether timeout row `row` competes with other timeouts of its state by due time.
    static constexpr bool competes_by_due_time(int row) {
        return has_competing_timeouts && is_timeout_row(row) &&
               timeout_slot_count[static_cast<std::size_t>(rows.source[static_cast<std::size_t>(row)])] > 1;
    }

    // Whether timeout row `row`, when it fires, leaves its state active and so counts again from
    // that cycle: an internal timeout (no domain), or a local one (its domain is its state).
    static constexpr bool rearms(int row) {
        auto const r = static_cast<std::size_t>(row);
        return is_timeout_row(row) && (rows.domain[r] < 0 || rows.domain[r] == rows.source[r]);
    }

    // The rows of each state, in declaration order, all kinds: those of state s are
    // from_source[from_source_begin[s]] to from_source[from_source_begin[s + 1]] (exclusive).
    // Built once, so that what is asked per state or per (state, trigger) reads that state's
    // rows and not all the chart's: the compile time stays linear in the chart.
    static constexpr auto from_source_begin = [] {
        std::array<int, static_cast<std::size_t>(N) + 1> begin{};
        for (int r = 0; r < R; ++r) ++begin[static_cast<std::size_t>(rows.source[static_cast<std::size_t>(r)]) + 1];
        for (std::size_t s = 0; s < static_cast<std::size_t>(N); ++s) begin[s + 1] += begin[s];
        return begin;
    }();
    static constexpr auto from_source = [] {
        std::array<int, static_cast<std::size_t>(R)> out{};
        auto next = from_source_begin;
        for (int r = 0; r < R; ++r)
            out[static_cast<std::size_t>(next[static_cast<std::size_t>(rows.source[static_cast<std::size_t>(r)])]++)] =
                r;
        return out;
    }();

    static constexpr int count_rows(row_kind k, int state) {
        int n = 0;
        if (state < 0) {
            for (int r = 0; r < R; ++r) n += rows.kinds[static_cast<std::size_t>(r)] == k;
        } else {
            for (int i = from_source_begin[static_cast<std::size_t>(state)];
                 i < from_source_begin[static_cast<std::size_t>(state) + 1]; ++i)
                n += rows.kinds[static_cast<std::size_t>(from_source[static_cast<std::size_t>(i)])] == k;
        }
        return n;
    }

    // The rows of kind K from state S (every state if S is -1), in declaration order: the
    // entry or exit rows of a state, or all transitions.
    template <row_kind K, int S>
    static constexpr auto rows_of = [] {
        std::array<int, static_cast<std::size_t>(count_rows(K, S))> out{};
        std::size_t n = 0;
        if constexpr (S < 0) {
            for (int r = 0; r < R; ++r)
                if (rows.kinds[static_cast<std::size_t>(r)] == K) out[n++] = r;
        } else {
            for (int i = from_source_begin[S]; i < from_source_begin[S + 1]; ++i)
                if (rows.kinds[static_cast<std::size_t>(from_source[static_cast<std::size_t>(i)])] == K)
                    out[n++] = from_source[static_cast<std::size_t>(i)];
        }
        return out;
    }();
    static constexpr auto const& transition_rows = rows_of<row_kind::transition, -1>;

    // How many basic states below s can be active at once: the most transitions one event
    // can select there.
    static constexpr int max_active_leaves(int s = root) {
        auto const i = static_cast<std::size_t>(s);
        if (tree.is_leaf(s)) return 1;
        int result = 0;
        for (int c = tree.first_child[i]; c >= 0; c = tree.next_sibling[static_cast<std::size_t>(c)]) {
            int const m = max_active_leaves(c);
            result = tree.kinds[i] == kind::parallel ? result + m : (m > result ? m : result);
        }
        return result;
    }

    static constexpr bool has_parallel = [] {
        for (int s = 0; s < N; ++s)
            if (tree.kinds[static_cast<std::size_t>(s)] == kind::parallel) return true;
        return false;
    }();

    // history_child[s]: the first history pseudo-state among the children of composite s, -1
    // if none; deep_history_child[s]: whether one of them is deep.
    static constexpr auto history_child = [] {
        std::array<int, static_cast<std::size_t>(N)> out{};
        for (int s = 0; s < N; ++s) {
            out[static_cast<std::size_t>(s)] = -1;
            for (int c = tree.first_child[static_cast<std::size_t>(s)]; c >= 0;
                 c = tree.next_sibling[static_cast<std::size_t>(c)])
                if (tree.kinds[static_cast<std::size_t>(c)] == kind::history && out[static_cast<std::size_t>(s)] < 0)
                    out[static_cast<std::size_t>(s)] = c;
        }
        return out;
    }();
    static constexpr auto deep_history_child = [] {
        std::array<bool, static_cast<std::size_t>(N)> out{};
        for (int s = 1; s < N; ++s)
            if (tree.kinds[static_cast<std::size_t>(s)] == kind::history &&
                tree.hist[static_cast<std::size_t>(s)] == history::deep)
                out[static_cast<std::size_t>(tree.parent[static_cast<std::size_t>(s)])] = true;
        return out;
    }();
    static constexpr bool has_history_states = [] {
        for (int s = 0; s < N; ++s)
            if (tree.kinds[static_cast<std::size_t>(s)] == kind::history) return true;
        return false;
    }();

    // The initial configuration: every composite's byte at its initial child; the byte of a
    // composite with history states at the first of them, which is never active: the mark of a
    // composite that has never been active, whose history states take their defaults.
    static constexpr auto initial_bytes = [] {
        std::array<ordinal_type, static_cast<std::size_t>(tree.slots)> bytes{};
        for (std::size_t s = 0; s < static_cast<std::size_t>(N); ++s)
            if (tree.slot[s] >= 0)
                bytes[static_cast<std::size_t>(tree.slot[s])] = static_cast<ordinal_type>(
                    tree.ordinal[static_cast<std::size_t>(history_child[s] >= 0 ? history_child[s] : tree.initial[s])]);
        return bytes;
    }();
    // Whether composite s's byte says it has never been active (it selects a history state).
    template <int S>
    static constexpr bool never_active_byte(int byte) {
        bool is_history = false;
        for (int c = tree.first_child[static_cast<std::size_t>(S)]; c >= 0;
             c = tree.next_sibling[static_cast<std::size_t>(c)])
            is_history = is_history || (tree.kinds[static_cast<std::size_t>(c)] == kind::history &&
                                        tree.ordinal[static_cast<std::size_t>(c)] == byte);
        return is_history;
    }

    // Which children of the root are final, by ordinal: the machine halts when its root's
    // byte selects one. Empty unless the root is a composite with a final child.
    static constexpr bool can_halt = [] {
        if (tree.kinds[root] != kind::composite) return false;
        for (int c = tree.first_child[root]; c >= 0; c = tree.next_sibling[static_cast<std::size_t>(c)])
            if (tree.kinds[static_cast<std::size_t>(c)] == kind::final_state) return true;
        return false;
    }();
    static constexpr auto final_root_children = [] {
        std::array<bool, can_halt ? static_cast<std::size_t>(tree.child_count[root]) : 0> out{};
        if constexpr (can_halt)
            for (int c = tree.first_child[root]; c >= 0; c = tree.next_sibling[static_cast<std::size_t>(c)])
                out[static_cast<std::size_t>(tree.ordinal[static_cast<std::size_t>(c)])] =
                    tree.kinds[static_cast<std::size_t>(c)] == kind::final_state;
        return out;
    }();

    // Two selected transitions conflict when their exit sets meet, i.e. when their domains nest.
    static constexpr bool conflict(int r1, int r2) {
        int const d1 = rows.domain[static_cast<std::size_t>(r1)], d2 = rows.domain[static_cast<std::size_t>(r2)];
        if (d1 < 0 || d2 < 0) return false;
        return tree.contains(d1, d2) || tree.contains(d2, d1);
    }
    // Of two conflicting transitions, the later-selected one preempts the earlier when its
    // source lies below the earlier one's (SCXML's removeConflictingTransitions).
    static constexpr bool preempts(int later, int earlier) {
        return tree.is_proper_ancestor(rows.source[static_cast<std::size_t>(earlier)],
                                       rows.source[static_cast<std::size_t>(later)]);
    }
};

}  // namespace bsc::detail
// end include/bsc/detail/model/layout.hpp

namespace bsc::detail {

template <class Model>
struct plan : chart_layout<Model> {
    using layout = chart_layout<Model>;
    using layout::tree;
    using layout::rows;
    using layout::N;
    using layout::R;
    using layout::is_transition_on;
    using layout::components;
    using layout::has_parallel;
    using layout::conflict;
    using layout::from_source;
    using layout::from_source_begin;

    // The transitions on each event, in declaration order, for a chart without event families
    // (where a row takes the events of its trigger only): those on event position t are
    // on_event[on_event_begin[t]] to on_event[on_event_begin[t + 1]] (exclusive). Built once,
    // so that each trigger's list is read, not found by a scan of every row.
    static constexpr int event_count = static_cast<int>(Model::events::size);
    static constexpr auto on_event_begin = [] {
        std::array<int, static_cast<std::size_t>(event_count) + 1> begin{};
        for (int r = 0; r < R; ++r)
            if (rows.kinds[static_cast<std::size_t>(r)] == row_kind::transition &&
                rows.trigger[static_cast<std::size_t>(r)] >= 0)
                ++begin[static_cast<std::size_t>(rows.trigger[static_cast<std::size_t>(r)]) + 1];
        for (std::size_t t = 0; t < static_cast<std::size_t>(event_count); ++t) begin[t + 1] += begin[t];
        return begin;
    }();
    static constexpr auto on_event = [] {
        std::array<int, static_cast<std::size_t>(on_event_begin[static_cast<std::size_t>(event_count)])> out{};
        auto next = on_event_begin;
        for (int r = 0; r < R; ++r)
            if (rows.kinds[static_cast<std::size_t>(r)] == row_kind::transition &&
                rows.trigger[static_cast<std::size_t>(r)] >= 0)
                out[static_cast<std::size_t>(
                    next[static_cast<std::size_t>(rows.trigger[static_cast<std::size_t>(r)])]++)] = r;
        return out;
    }();
    static constexpr bool indexed_by_event(int trigger) { return !Model::has_families && trigger >= 0; }

    static constexpr int transition_count(int trigger) {
        if (indexed_by_event(trigger))
            return on_event_begin[static_cast<std::size_t>(trigger) + 1] -
                   on_event_begin[static_cast<std::size_t>(trigger)];
        int n = 0;
        for (int r = 0; r < R; ++r) n += is_transition_on(r, trigger) ? 1 : 0;
        return n;
    }

    // The transitions on a trigger, in declaration order; the selection buffer stores positions
    // here. What follows reads this list.
    template <int Trigger>
    static constexpr auto transitions = [] {
        std::array<int, static_cast<std::size_t>(transition_count(Trigger))> out{};
        std::size_t n = 0;
        if constexpr (indexed_by_event(Trigger)) {
            for (int i = on_event_begin[static_cast<std::size_t>(Trigger)];
                 i < on_event_begin[static_cast<std::size_t>(Trigger) + 1]; ++i)
                out[n++] = on_event[static_cast<std::size_t>(i)];
        } else {
            for (int r = 0; r < R; ++r)
                if (is_transition_on(r, Trigger)) out[n++] = r;
        }
        return out;
    }();

    // State s needs visiting for the trigger: a transition on it leaves s, an ancestor or a
    // descendant. (Asked of the states a dispatch walks through, each asking reads the trigger's
    // transitions: no array of every state per trigger, which made the compile time quadratic.)
    template <int Trigger>
    static constexpr bool relevant(int s) {
        for (int const r : transitions<Trigger>) {
            int const src = rows.source[static_cast<std::size_t>(r)];
            if (tree.contains(src, s) || tree.contains(s, src)) return true;
        }
        return false;
    }

    // No transition on the trigger leaves a state strictly below s: every state below s takes
    // it by the rows of s and its ancestors only.
    template <int Trigger>
    static constexpr bool no_source_below(int s) {
        for (int const r : transitions<Trigger>) {
            int const src = rows.source[static_cast<std::size_t>(r)];
            if (src != s && tree.contains(s, src)) return false;
        }
        return true;
    }

    // The children of composite s toward the sources of the trigger's transitions below it,
    // in document order, each once; or `every`, if a source is s or above it (every child is
    // then relevant).
    template <int Trigger>
    struct children_found {
        std::array<int, transitions<Trigger>.size()> child{};
        std::size_t count = 0;
        bool every = false;
    };
    template <int Trigger>
    static constexpr children_found<Trigger> children_toward_sources(int s) {
        children_found<Trigger> found{};
        for (int const r : transitions<Trigger>) {
            int const src = rows.source[static_cast<std::size_t>(r)];
            if (tree.contains(src, s)) {
                found.every = true;
                return found;
            }
            if (!tree.contains(s, src)) continue;
            int const c = tree.child_toward(s, src);
            bool seen = false;
            for (std::size_t j = 0; j < found.count && !seen; ++j) seen = found.child[j] == c;
            if (seen) continue;
            std::size_t i = found.count++;  // insertion in document order
            for (; i > 0 && found.child[i - 1] > c; --i) found.child[i] = found.child[i - 1];
            found.child[i] = c;
        }
        return found;
    }

    // The children of composite S that are relevant to the trigger, in document order: the
    // only ones dispatch on the trigger compares S's byte with, so each trigger instantiates
    // code along its own paths only (linear in the transitions, not in states x triggers).
    template <int Trigger, int S>
    static constexpr auto relevant_children = [] {
        constexpr auto found = children_toward_sources<Trigger>(S);
        if constexpr (found.every) {
            return layout::template children<S>;
        } else {
            std::array<int, found.count> out{};
            for (std::size_t i = 0; i < found.count; ++i) out[i] = found.child[i];
            return out;
        }
    }();

    // Calls f(a) for each state a from `leaf` up to `top`, in the order their rows are tried:
    // `leaf` first under child-first priority, `top` first under parent-first (bsc/priority.hpp).
    // Fixed here, so that either order is the same straight-line code.
    template <class F>
    static constexpr void for_each_tried(int leaf, int top, F&& f) {
        if constexpr (Model::order == priority::child_first) {
            for (int a = leaf;; a = tree.parent[static_cast<std::size_t>(a)]) {
                f(static_cast<std::size_t>(a));
                if (a == top) break;
            }
        } else {
            int const levels = tree.depth[static_cast<std::size_t>(leaf)] - tree.depth[static_cast<std::size_t>(top)];
            for (int k = levels; k >= 0; --k) {
                int a = leaf;
                for (int i = 0; i < k; ++i) a = tree.parent[static_cast<std::size_t>(a)];
                f(static_cast<std::size_t>(a));
            }
        }
    }

    // The rows on `trigger` a state in `leaf` tries, up to `top`, in priority order.
    static constexpr int candidate_count(int leaf, int top, int trigger) {
        int n = 0;
        for_each_tried(leaf, top, [&](std::size_t a) {
            for (int i = from_source_begin[a]; i < from_source_begin[a + 1]; ++i)
                n += is_transition_on(from_source[static_cast<std::size_t>(i)], trigger) ? 1 : 0;
        });
        return n;
    }
    template <std::size_t Count>
    static constexpr std::array<int, Count> candidate_rows(int leaf, int top, int trigger) {
        std::array<int, Count> out{};
        std::size_t n = 0;
        for_each_tried(leaf, top, [&](std::size_t a) {
            for (int i = from_source_begin[a]; i < from_source_begin[a + 1]; ++i)
                if (is_transition_on(from_source[static_cast<std::size_t>(i)], trigger))
                    out[n++] = from_source[static_cast<std::size_t>(i)];
        });
        return out;
    }

    // The candidates of basic state Leaf on the trigger: its rows and its ancestors'.
    template <int Leaf, int Trigger>
    static constexpr auto candidates =
        candidate_rows<static_cast<std::size_t>(candidate_count(Leaf, 0, Trigger))>(Leaf, 0, Trigger);

    // The condition-driven rows a component's turn tries from its active frontier up to the
    // component itself ([BSC]: one transition per component per cycle).
    template <int Frontier, int Component>
    static constexpr auto component_candidates =
        candidate_rows<static_cast<std::size_t>(candidate_count(Frontier, Component, any_condition))>(Frontier,
                                                                                                      Component,
                                                                                                      any_condition);

    // The timeout rows of the source of timeout row `row` declared after it, in declaration
    // order: those it competes with by due time when its condition holds (the earlier ones did
    // not hold, or it would not be tried). Empty for a state with one timeout row.
    static constexpr int later_timeout_count(int row) {
        int const source = rows.source[static_cast<std::size_t>(row)];
        int n = 0;
        for (int i = from_source_begin[static_cast<std::size_t>(source)];
             i < from_source_begin[static_cast<std::size_t>(source) + 1]; ++i)
            n += from_source[static_cast<std::size_t>(i)] > row &&
                 layout::is_timeout_row(from_source[static_cast<std::size_t>(i)]);
        return n;
    }
    template <int Row>
    static constexpr auto later_timeouts = [] {
        std::array<int, static_cast<std::size_t>(layout::is_timeout_row(Row) ? later_timeout_count(Row) : 0)> out{};
        std::size_t n = 0;
        if constexpr (out.size() > 0) {
            constexpr int source = rows.source[static_cast<std::size_t>(Row)];
            for (int i = from_source_begin[static_cast<std::size_t>(source)];
                 i < from_source_begin[static_cast<std::size_t>(source) + 1]; ++i)
                if (from_source[static_cast<std::size_t>(i)] > Row &&
                    layout::is_timeout_row(from_source[static_cast<std::size_t>(i)]))
                    out[n++] = from_source[static_cast<std::size_t>(i)];
        }
        return out;
    }();

    template <int Trigger>
    static constexpr int position_of(int row) {
        for (std::size_t i = 0; i < transitions<Trigger>.size(); ++i)
            if (transitions<Trigger>[i] == row) return static_cast<int>(i);
        return -1;
    }

    static constexpr int index_in_components(int s) {
        for (std::size_t i = 0; i < components.size(); ++i)
            if (components[i] == s) return static_cast<int>(i);
        return -1;
    }

    // The component a state lies in, as an index into components. Within a component at most
    // one transition is selected per microstep: its basic states that lie below no further
    // parallel state are mutually exclusive.
    static constexpr auto component_of = [] {
        std::array<int, static_cast<std::size_t>(N)> out{};
        for (int s = 0; s < N; ++s) {
            out[static_cast<std::size_t>(s)] = 0;
            for (int a = s; a > 1; a = tree.parent[static_cast<std::size_t>(a)]) {
                int const i = index_in_components(a);
                if (i >= 0) {
                    out[static_cast<std::size_t>(s)] = i;
                    break;
                }
            }
        }
        return out;
    }();

    template <int Trigger>
    static constexpr int component_row_count(int component) {
        int n = 0;
        for (int const r : transitions<Trigger>)
            n += component_of[static_cast<std::size_t>(rows.source[static_cast<std::size_t>(r)])] == component;
        return n;
    }
    // The transitions on a trigger whose source lies in component C, in declaration order.
    template <int Trigger, int C>
    static constexpr auto component_rows = [] {
        std::array<int, static_cast<std::size_t>(component_row_count<Trigger>(C))> out{};
        std::size_t n = 0;
        for (int const r : transitions<Trigger>)
            if (component_of[static_cast<std::size_t>(rows.source[static_cast<std::size_t>(r)])] == C) out[n++] = r;
        return out;
    }();
    // What a region-local selection records for a row: 1 + its position in its component's rows.
    template <int Trigger, int Row>
    static constexpr int component_code = [] {
        constexpr auto const& list = component_rows<Trigger, component_of[static_cast<std::size_t>(rows.source[Row])]>;
        for (std::size_t i = 0; i < list.size(); ++i)
            if (list[i] == Row) return static_cast<int>(i) + 1;
        return 0;
    }();

    // A trigger is region-local when what SCXML's conflict resolution does at run time is known
    // at compile time to keep every selected transition: no transition on it leaves a state that
    // contains a parallel state (so each is selected by one basic state at most), and no two
    // transitions from different components have nesting domains (so none preempts another).
    // Its microstep then records one row per component and fires the components in document
    // order, with no run-time conflict check.
    template <int Trigger>
    static constexpr bool region_local = [] {
        if (!has_parallel) return false;  // nothing to resolve: every transition fires where selected
        constexpr auto const& on_trigger = transitions<Trigger>;
        for (std::size_t i = 0; i < on_trigger.size(); ++i) {
            int const r = on_trigger[i];
            int const src = rows.source[static_cast<std::size_t>(r)];
            for (int s = src; s < tree.end[static_cast<std::size_t>(src)]; ++s)
                if (tree.kinds[static_cast<std::size_t>(s)] == kind::parallel) return false;
            if (component_row_count<Trigger>(component_of[static_cast<std::size_t>(src)]) > 254) return false;
            for (std::size_t j = i + 1; j < on_trigger.size(); ++j) {
                int const r2 = on_trigger[j];
                if (component_of[static_cast<std::size_t>(rows.source[static_cast<std::size_t>(r2)])] !=
                        component_of[static_cast<std::size_t>(src)] &&
                    conflict(r, r2))
                    return false;
            }
        }
        return true;
    }();

    // A region-local trigger whose transitions can fire as they are selected, with the same
    // effects as selecting all first: none is guarded (so no selection can depend on another
    // component's action), and no state that one of them exits or enters has an entry or exit row
    // (so the only visible effects are the transition actions, which run in document order
    // either way). Each component's transition changes only the bytes inside its own domain.
    template <int Trigger>
    static constexpr bool fires_at_selection = [] {
        if (!region_local<Trigger>) return false;
        for (int const r : transitions<Trigger>) {
            if (rows.guarded[static_cast<std::size_t>(r)]) return false;
            int const d = rows.domain[static_cast<std::size_t>(r)];
            if (d < 0) continue;  // targetless: exits and enters nothing
            for (int r2 = 0; r2 < R; ++r2) {
                auto const k = rows.kinds[static_cast<std::size_t>(r2)];
                int const s = rows.source[static_cast<std::size_t>(r2)];
                if (k != row_kind::transition && s != d && tree.contains(d, s)) return false;
            }
        }
        return true;
    }();

    // The components in which a transition on the trigger can be selected under a parallel state.
    template <int Trigger>
    static constexpr int selecting_component_count() {
        int n = 0;
        for (std::size_t c = 1; c < components.size(); ++c) n += component_row_count<Trigger>(static_cast<int>(c)) > 0;
        return n;
    }
    template <int Trigger>
    static constexpr auto selecting_components = [] {
        std::array<int, static_cast<std::size_t>(selecting_component_count<Trigger>())> out{};
        std::size_t n = 0;
        for (std::size_t c = 1; c < components.size(); ++c)
            if (component_row_count<Trigger>(static_cast<int>(c)) > 0) out[n++] = static_cast<int>(c);
        return out;
    }();
};

}  // namespace bsc::detail
// end include/bsc/detail/compiled/plan.hpp
// begin include/bsc/detail/model/configuration_view.hpp
// What a guard that tests the configuration (bsc::in<S>, dsl/guard.hpp) sees of it: a view of the
// configuration bytes that answers is_active<S>(), for the guard of one row. Both back ends hand
// it to such guards (the compiled machine's guard_holds, the table's guard thunks).
//
// The test is resolved at compile time. A guard is evaluated only while its row's source is
// active (it is one of the candidates of an active state, or of an active component), so every
// common ancestor of S and the source is known to be active: only the states from S up to, not
// including, their lowest common ancestor remain, and of those only the ones whose parent is a
// composite need a byte compared (a region of a parallel state is active with its parent). For S
// a child of another region of a parallel state above the source that is one compare; for S the source
// or one of its ancestors, none (true); for S below another child of a composite above the
// source, none either (false: the composite's active child is the source's).

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace bsc::detail {

// One compare: the byte at `slot` selects the child at `ordinal`.
struct byte_test {
    int slot = 0;
    int ordinal = 0;
};

// Whether state s can never be active while state `known` is: they lie below different children
// of a composite, whose byte selects one (the states with a byte; a parallel state has none).
template <class Tree>
constexpr bool exclusive_states(Tree const& tree, int s, int known) {
    int const top = tree.lca(s, known);
    return top != s && top != known && tree.slot[static_cast<std::size_t>(top)] >= 0;
}

// The compares that tell whether state s is active while state `known` is: one per composite
// on the path from s up to, not including, their lowest common ancestor; innermost first.
template <class Tree>
constexpr int in_test_count(Tree const& tree, int s, int known) {
    int const top = tree.lca(s, known);
    int n = 0;
    for (int x = s; x != top; x = tree.parent[static_cast<std::size_t>(x)])
        n += tree.slot[static_cast<std::size_t>(tree.parent[static_cast<std::size_t>(x)])] >= 0;
    return n;
}
template <class Model, int S, int Known>
inline constexpr auto in_tests = [] {
    constexpr auto const& tree = Model::tree;
    std::array<byte_test, static_cast<std::size_t>(in_test_count(tree, S, Known))> out{};
    std::size_t n = 0;
    for (int x = S; x != tree.lca(S, Known); x = tree.parent[static_cast<std::size_t>(x)]) {
        int const slot = tree.slot[static_cast<std::size_t>(tree.parent[static_cast<std::size_t>(x)])];
        if (slot >= 0) out[n++] = {slot, tree.ordinal[static_cast<std::size_t>(x)]};
    }
    return out;
}();

/// The configuration as the guard of a row from state Source sees it: `active` points at the
/// configuration bytes (bsc::configuration::active; null for a chart without composites, where
/// no test reads a byte).
template <class Model, int Source>
struct configuration_view {
    typename Model::ordinal_type const* active;

    template <class S>
    constexpr bool is_active() const noexcept {
        constexpr int s = Model::template index_of_state<S>::value;
        static_assert(s > 0, "bsc::in<S>: S is not a state of the chart (bsc::error::in_of_state_not_in_chart)");
        if constexpr (exclusive_states(Model::tree, s, Source)) {
            return false;
        } else {
            constexpr auto const& tests = in_tests<Model, s, Source>;
            // clang-format off
            return [&]<std::size_t... I>(std::index_sequence<I...>) {
                return ((active[static_cast<std::size_t>(tests[I].slot)] ==
                         static_cast<typename Model::ordinal_type>(tests[I].ordinal)) && ...);
            }(std::make_index_sequence<tests.size()>{});
            // clang-format on
        }
    }
};

}  // namespace bsc::detail
// end include/bsc/detail/model/configuration_view.hpp
// begin include/bsc/observer.hpp
// Observer hooks: entry, exit and transition notifications for traces and tests. An
// observer implements any subset of the hooks; a machine without one pays nothing.

#include <string_view>


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
// end include/bsc/observer.hpp
// begin include/bsc/statechart.hpp
// bsc::statechart: what a machine takes as its chart.

#include <type_traits>


namespace bsc {

namespace detail {
template <class T>
inline constexpr bool is_chart = false;
template <class Context, class Root, priority Order, class... Rows>
inline constexpr bool is_chart<chart<Context, Root, Order, Rows...>> = true;
}  // namespace detail

/// The type of a chart that bsc::make_chart returned (`decltype(chart)`, const or not), or
/// `bsc::chart_ref<chart>`: what bsc::machine and bsc::table::machine take as their Chart.
/// `bsc::machine<int>` fails at its declaration, naming this concept. (A chart that failed its
/// checks is one too: its machine compiles and does nothing, so that the chart's own errors are
/// the only ones.)
template <class T>
concept statechart = detail::is_chart<std::remove_cv_t<T>> || detail::is_rejected_chart<std::remove_cv_t<T>> ||
    detail::is_chart_ref<std::remove_cv_t<T>>;

}  // namespace bsc
// end include/bsc/statechart.hpp
// begin include/bsc/detail/runtime/driver.hpp
// The driver: what both back ends share, and the public interface of a machine (step, dispatch,
// is<S>, halted, active_states, ...). It is built in layers, each a class template deriving
// from the one below and doing one job (their headers say which):
//
//   machine_data       what a machine holds, and the chart's types and facts
//   explorer_queries   what only the explorer asks (through detail::access)
//   run_control        a run's bracket: reentrancy, guarded calls, failures, the recorded outcome
//   deferral           deferred events, kept and retried
//   done_raising       done<S> events, and the exits when the machine halts
//   settling           run to completion; a cycle's components and raised events
//   driver             the public interface, the construction and the BSC cycle's shell
//
// A back end (bsc::machine, bsc::table::machine) derives from the driver (CRTP) and supplies
// the hooks of detail/runtime/backend.hpp, which the driver checks (machine_backend).

#include <cstddef>
#include <string_view>
#include <type_traits>
#include <utility>

// begin include/bsc/detail/runtime/backend.hpp
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
// end include/bsc/detail/runtime/backend.hpp
// begin include/bsc/detail/runtime/context_data.hpp
// The machine's view of a context's data model: it latches input channels, commits output
// channels and updates timers, wherever they are in the context (detail/members.hpp walks it:
// members, aggregates, std::arrays, types described by bsc::fields, at any depth; transient
// members too, since their channels and timers still run). Members that hold none cost
// nothing, and a context with none is not visited at all.

#include <type_traits>

// begin include/bsc/detail/members.hpp
// The member layer: the one description of what a context holds. Every part of bsc that walks a
// machine's data goes through it: the machine itself (channels' latch and commit, timers'
// update), retentive state, the explorer's codec, the waveform and the network's values.
//
// One rule says what a type is (member_kind): a machine, a channel, a timer, a scalar (bool,
// integer, enum, float, std::chrono::duration), a std::array (walked element by element), a
// record (an aggregate, or a type bsc::fields<T> describes: walked member by member, at any
// depth), something opaque (a string, a handle: a leaf bsc does not look into), or something
// unwalkable: a type that may hold a channel, timer or machine where bsc cannot reach it (inside
// std::optional, std::variant, a container, a union, behind a pointer; an aggregate with a base
// class or a C array). An unwalkable member is a compile error that names its owner and itself,
// never a silent skip. One trait, bsc::transient<T>, says what is not part of the state.
//
// One walk (walk) visits values, one fold (fold_type) computes over types; consumers supply
// visitors and never classify a type themselves.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>
#include <utility>

// begin include/bsc/detail/fields.hpp
// Field access for plain aggregates, without macros or reflection: the number of fields is
// the largest N for which T{any, ..., any} (N times) compiles (any converts to a value or, for a
// reference member, to an lvalue), and structured bindings give
// references to them (detail/field_bindings.hpp). Used to find the channels and timers of a
// context, at any depth of nested aggregates and std::arrays. Supports aggregates of up to
// max_fields (128) fields without base classes or C arrays (use std::array instead).

#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

// begin include/bsc/detail/field_bindings.hpp
// Generated by `python3 scripts/field_bindings.py`; do not edit.
// f(fields...) for the fields of an aggregate with at most 128 fields, each passed as
// an lvalue: no tuple in between, so that a visit of the fields is member accesses.
//
// One specialization per field count, side by side: as one chain of `if constexpr` branches,
// each branch nested in the one before, GCC and Clang took five times as long to read this
// header (0.10 s of GCC's time for every translation unit that includes bsc), most of it in the
// chain's nesting (docs/performance.md, rule "A header is read by every user").

#include <cstddef>


namespace bsc::detail {

inline constexpr std::size_t max_fields = 128;

// field_binder<N>::apply(t, f): f(fields...) for an aggregate t of N fields. (Above max_fields,
// nothing: bsc::error::too_many_fields has said so where the count was taken.)
template <std::size_t N>
struct field_binder {
    template <class T, class F>
    static constexpr void apply(T&, F&) {}
};
template <>
struct field_binder<0> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T&, F& f) { return f(); }
};
template <>
struct field_binder<1> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0] = t;
        return f(f0);
    }
};
template <>
struct field_binder<2> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1] = t;
        return f(f0, f1);
    }
};
template <>
struct field_binder<3> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2] = t;
        return f(f0, f1, f2);
    }
};
template <>
struct field_binder<4> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3] = t;
        return f(f0, f1, f2, f3);
    }
};
template <>
struct field_binder<5> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4] = t;
        return f(f0, f1, f2, f3, f4);
    }
};
template <>
struct field_binder<6> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5] = t;
        return f(f0, f1, f2, f3, f4, f5);
    }
};
template <>
struct field_binder<7> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6] = t;
        return f(f0, f1, f2, f3, f4, f5, f6);
    }
};
template <>
struct field_binder<8> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7);
    }
};
template <>
struct field_binder<9> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8);
    }
};
template <>
struct field_binder<10> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9);
    }
};
template <>
struct field_binder<11> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10);
    }
};
template <>
struct field_binder<12> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11);
    }
};
template <>
struct field_binder<13> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12);
    }
};
template <>
struct field_binder<14> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13);
    }
};
template <>
struct field_binder<15> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14);
    }
};
template <>
struct field_binder<16> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15);
    }
};
template <>
struct field_binder<17> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16);
    }
};
template <>
struct field_binder<18> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17);
    }
};
template <>
struct field_binder<19> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18);
    }
};
template <>
struct field_binder<20> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19);
    }
};
template <>
struct field_binder<21> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20);
    }
};
template <>
struct field_binder<22> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21);
    }
};
template <>
struct field_binder<23> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22);
    }
};
template <>
struct field_binder<24> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23);
    }
};
template <>
struct field_binder<25> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24);
    }
};
template <>
struct field_binder<26> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25);
    }
};
template <>
struct field_binder<27> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26);
    }
};
template <>
struct field_binder<28> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27);
    }
};
template <>
struct field_binder<29> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28);
    }
};
template <>
struct field_binder<30> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29);
    }
};
template <>
struct field_binder<31> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30);
    }
};
template <>
struct field_binder<32> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31);
    }
};
template <>
struct field_binder<33> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32);
    }
};
template <>
struct field_binder<34> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33);
    }
};
template <>
struct field_binder<35> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34);
    }
};
template <>
struct field_binder<36> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35);
    }
};
template <>
struct field_binder<37> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36);
    }
};
template <>
struct field_binder<38> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37);
    }
};
template <>
struct field_binder<39> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38);
    }
};
template <>
struct field_binder<40> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39);
    }
};
template <>
struct field_binder<41> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40);
    }
};
template <>
struct field_binder<42> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41);
    }
};
template <>
struct field_binder<43> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42);
    }
};
template <>
struct field_binder<44> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43);
    }
};
template <>
struct field_binder<45> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44);
    }
};
template <>
struct field_binder<46> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45);
    }
};
template <>
struct field_binder<47> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46);
    }
};
template <>
struct field_binder<48> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47);
    }
};
template <>
struct field_binder<49> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48);
    }
};
template <>
struct field_binder<50> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49);
    }
};
template <>
struct field_binder<51> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50);
    }
};
template <>
struct field_binder<52> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51);
    }
};
template <>
struct field_binder<53> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52);
    }
};
template <>
struct field_binder<54> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53);
    }
};
template <>
struct field_binder<55> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54);
    }
};
template <>
struct field_binder<56> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55);
    }
};
template <>
struct field_binder<57> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56);
    }
};
template <>
struct field_binder<58> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57);
    }
};
template <>
struct field_binder<59> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58);
    }
};
template <>
struct field_binder<60> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59);
    }
};
template <>
struct field_binder<61> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60);
    }
};
template <>
struct field_binder<62> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61);
    }
};
template <>
struct field_binder<63> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62);
    }
};
template <>
struct field_binder<64> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63);
    }
};
template <>
struct field_binder<65> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64);
    }
};
template <>
struct field_binder<66> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65);
    }
};
template <>
struct field_binder<67> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66);
    }
};
template <>
struct field_binder<68> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67);
    }
};
template <>
struct field_binder<69> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68);
    }
};
template <>
struct field_binder<70> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69);
    }
};
template <>
struct field_binder<71> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70);
    }
};
template <>
struct field_binder<72> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71);
    }
};
template <>
struct field_binder<73> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72);
    }
};
template <>
struct field_binder<74> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73);
    }
};
template <>
struct field_binder<75> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74);
    }
};
template <>
struct field_binder<76> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75);
    }
};
template <>
struct field_binder<77> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76);
    }
};
template <>
struct field_binder<78> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77);
    }
};
template <>
struct field_binder<79> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78);
    }
};
template <>
struct field_binder<80> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79);
    }
};
template <>
struct field_binder<81> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80);
    }
};
template <>
struct field_binder<82> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81);
    }
};
template <>
struct field_binder<83> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82);
    }
};
template <>
struct field_binder<84> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83);
    }
};
template <>
struct field_binder<85> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84);
    }
};
template <>
struct field_binder<86> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85);
    }
};
template <>
struct field_binder<87> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86);
    }
};
template <>
struct field_binder<88> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87);
    }
};
template <>
struct field_binder<89> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88);
    }
};
template <>
struct field_binder<90> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89);
    }
};
template <>
struct field_binder<91> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90);
    }
};
template <>
struct field_binder<92> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91);
    }
};
template <>
struct field_binder<93> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92);
    }
};
template <>
struct field_binder<94> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93);
    }
};
template <>
struct field_binder<95> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94);
    }
};
template <>
struct field_binder<96> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95);
    }
};
template <>
struct field_binder<97> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96);
    }
};
template <>
struct field_binder<98> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97);
    }
};
template <>
struct field_binder<99> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98);
    }
};
template <>
struct field_binder<100> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99);
    }
};
template <>
struct field_binder<101> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100);
    }
};
template <>
struct field_binder<102> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101);
    }
};
template <>
struct field_binder<103> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102);
    }
};
template <>
struct field_binder<104> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103);
    }
};
template <>
struct field_binder<105> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104);
    }
};
template <>
struct field_binder<106> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105);
    }
};
template <>
struct field_binder<107> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106);
    }
};
template <>
struct field_binder<108> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107);
    }
};
template <>
struct field_binder<109> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108);
    }
};
template <>
struct field_binder<110> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109);
    }
};
template <>
struct field_binder<111> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110);
    }
};
template <>
struct field_binder<112> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111);
    }
};
template <>
struct field_binder<113> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112);
    }
};
template <>
struct field_binder<114> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113);
    }
};
template <>
struct field_binder<115> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114);
    }
};
template <>
struct field_binder<116> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115);
    }
};
template <>
struct field_binder<117> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115, f116] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115, f116);
    }
};
template <>
struct field_binder<118> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115, f116, f117] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115, f116, f117);
    }
};
template <>
struct field_binder<119> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115, f116, f117, f118] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115, f116, f117, f118);
    }
};
template <>
struct field_binder<120> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115, f116, f117, f118, f119] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115, f116, f117, f118, f119);
    }
};
template <>
struct field_binder<121> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115, f116, f117, f118, f119, f120] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115, f116, f117, f118, f119, f120);
    }
};
template <>
struct field_binder<122> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115, f116, f117, f118, f119, f120, f121] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115, f116, f117, f118, f119, f120, f121);
    }
};
template <>
struct field_binder<123> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115, f116, f117, f118, f119, f120, f121, f122] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115, f116, f117, f118, f119, f120, f121, f122);
    }
};
template <>
struct field_binder<124> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115, f116, f117, f118, f119, f120, f121, f122, f123] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115, f116, f117, f118, f119, f120, f121, f122, f123);
    }
};
template <>
struct field_binder<125> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115, f116, f117, f118, f119, f120, f121, f122, f123, f124] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115, f116, f117, f118, f119, f120, f121, f122, f123, f124);
    }
};
template <>
struct field_binder<126> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115, f116, f117, f118, f119, f120, f121, f122, f123, f124, f125] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115, f116, f117, f118, f119, f120, f121, f122, f123, f124, f125);
    }
};
template <>
struct field_binder<127> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115, f116, f117, f118, f119, f120, f121, f122, f123, f124, f125, f126] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115, f116, f117, f118, f119, f120, f121, f122, f123, f124, f125, f126);
    }
};
template <>
struct field_binder<128> {
    template <class T, class F>
    BSC_DETAIL_VISIT_INLINE static constexpr decltype(auto) apply(T& t, F& f) {
        auto& [f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115, f116, f117, f118, f119, f120, f121, f122, f123, f124, f125, f126, f127] = t;
        return f(f0, f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17, f18, f19, f20, f21, f22, f23, f24, f25, f26, f27, f28, f29, f30, f31, f32, f33, f34, f35, f36, f37, f38, f39, f40, f41, f42, f43, f44, f45, f46, f47, f48, f49, f50, f51, f52, f53, f54, f55, f56, f57, f58, f59, f60, f61, f62, f63, f64, f65, f66, f67, f68, f69, f70, f71, f72, f73, f74, f75, f76, f77, f78, f79, f80, f81, f82, f83, f84, f85, f86, f87, f88, f89, f90, f91, f92, f93, f94, f95, f96, f97, f98, f99, f100, f101, f102, f103, f104, f105, f106, f107, f108, f109, f110, f111, f112, f113, f114, f115, f116, f117, f118, f119, f120, f121, f122, f123, f124, f125, f126, f127);
    }
};

}  // namespace bsc::detail
// end include/bsc/detail/field_bindings.hpp

namespace bsc::detail {

// What a probe's conversion returns: the probes are only used in unevaluated contexts, but a
// member's constructor template that takes one (std::optional's) has its body instantiated, and
// an operator without a definition would then be "used but never defined".
template <class T>
inline T* never_read = nullptr;

// Converts to any member type, so that T{any_field{}...} initialises T's members one by one:
// - a type that can be moved, as an xvalue: a member whose constructor template takes anything
//   (std::optional, std::any) then takes the probe itself, an exact match, rather than being
//   left between that constructor and a conversion;
// - a type that cannot be moved (std::atomic), as a prvalue, which initialises it in place;
// - a member that is a reference, as an lvalue.
struct any_field {
    template <class T>
        requires(!std::is_same_v<T, any_field> && std::is_move_constructible_v<T>)
    constexpr operator T&&() const&& { return static_cast<T&&>(*never_read<T>); }
    template <class T>
        requires(!std::is_same_v<T, any_field> && !std::is_move_constructible_v<T>)
    constexpr operator T() &&;  // (nothing instantiates it: such a member has no constructor template to)
    template <class T>
        requires(!std::is_same_v<T, any_field>)
    constexpr operator T&() const& { return *never_read<T>; }
};
// As any_field, but to values only: it cannot initialise a member that is a non-const reference.
struct any_value_field {
    template <class T>
        requires(!std::is_same_v<T, any_value_field> && std::is_move_constructible_v<T>)
    constexpr operator T&&() const&& { return static_cast<T&&>(*never_read<T>); }
    template <class T>
        requires(!std::is_same_v<T, any_value_field> && !std::is_move_constructible_v<T>)
    constexpr operator T() &&;
};

template <class T, class Probe, std::size_t... I>
constexpr bool brace_constructible(std::index_sequence<I...>) {
    return requires { T{(void(I), Probe{})...}; };
}

// The members initialised one by one: exact for an aggregate that is default-constructible (any
// shorter list of initialisers is valid too).
template <class T, class Probe, std::size_t N = 0>
constexpr std::size_t leading_field_count() {
    if constexpr (N > max_fields)
        return N;
    else if constexpr (brace_constructible<T, Probe>(std::make_index_sequence<N + 1>{}))
        return leading_field_count<T, Probe, N + 1>();
    else
        return N;
}

// The largest count in [From, To] that initialises every member: an aggregate with a reference
// member and no default initialiser for it cannot be initialised by a shorter list, so the count
// is searched up to its size (each member takes at least a byte).
template <class T, class Probe, std::size_t From, std::size_t To>
constexpr std::size_t largest_field_count(std::size_t found) {
    if constexpr (From > To)
        return found;
    else
        return largest_field_count<T, Probe, From + 1, To>(
            brace_constructible<T, Probe>(std::make_index_sequence<From>{}) ? From : found);
}

template <class T, class Probe>
constexpr std::size_t field_count_by() {
    constexpr std::size_t leading = leading_field_count<T, Probe>();
    if constexpr (leading > max_fields || std::is_default_constructible_v<T>)
        return leading;
    else
        return largest_field_count<T, Probe, leading + 1, (sizeof(T) < max_fields ? sizeof(T) : max_fields)>(leading);
}

template <class T>
constexpr std::size_t field_count() {
    return field_count_by<T, any_field>();
}

/// Whether an aggregate has a member that is a non-const lvalue reference (a const one binds a
/// value, and shows as a const field): the retentive state refuses both, since what lies behind
/// a reference is not the machine's.
template <class T>
inline constexpr bool has_reference_field = !brace_constructible<T, any_value_field>(
    std::make_index_sequence<field_count<T>()>{});

// f(fields...) for the fields of an aggregate, each an lvalue; f() for a type that is not one
// (after the error that says so). Clang 14 leaves the visit of a context's timers out of line
// unless told, with a call and its spills in every cycle; GCC 12 inlines it where that pays
// (bench/manufacturing_cell_bench.cpp: forced, its cycle took more instructions, not fewer;
// docs/performance.md, rule "Fields visited without a tuple").
template <class T, class F>
BSC_DETAIL_VISIT_INLINE constexpr decltype(auto) apply_to_fields(T& t, F&& f) {
    using type = std::remove_const_t<T>;
    constexpr std::size_t n = field_count<type>();
    if constexpr (!std::is_aggregate_v<type>) {
        detail::report<error::context_not_an_aggregate<type>>();
        return f();
    } else if constexpr (n > max_fields) {
        detail::report<error::too_many_fields<type>>();
        return f();
    } else {
        return field_binder<n>::apply(t, f);
    }
}

// A tuple of references to the fields of an aggregate (for their types and for std::get: a
// visit of every field is for_each_field, which builds no tuple).
template <class T>
constexpr auto tie_fields(T& t) {
    return detail::apply_to_fields(t, [](auto&... field) { return std::tie(field...); });
}

// Calls f(field) for each field of an aggregate, in declaration order.
template <class T, class F>
BSC_DETAIL_VISIT_INLINE  // as apply_to_fields
    constexpr void
    for_each_field(T& t, F&& f) {
    detail::apply_to_fields(t, [&](auto&... field) { (f(field), ...); });
}

}  // namespace bsc::detail
// end include/bsc/detail/fields.hpp
// begin include/bsc/detail/machine_base.hpp
// What every machine derives from, whatever its back end (an empty base: it costs nothing), so
// that the member layer (detail/members.hpp) knows a machine held in a context.

#include <type_traits>

namespace bsc::detail {

struct machine_base {};
template <class T>
inline constexpr bool is_machine = std::is_base_of_v<machine_base, T>;

}  // namespace bsc::detail
// end include/bsc/detail/machine_base.hpp
// begin include/bsc/detail/member_names.hpp
// The names of an aggregate's members as its definition spells them, at compile time, without
// macros: the address of a member of an object that is declared but never defined is a constant
// that may be a template argument, and both supported compilers spell that argument in the
// function's signature (BSC_DETAIL_FUNCTION_SIGNATURE) ending with the member's name (GCC 12:
// "{(& object<T>.T::speed)}", Clang 14: "{&object.speed}"). Used by the opt-in parts that show
// or store a context by name (the VCD recorder, the retentive state's layout fingerprint);
// nothing else pays for it.

#include <array>
#include <cstddef>
#include <string_view>
#include <tuple>
#include <utility>


namespace bsc::detail {

// Holds the address as a class-type template argument: Clang 14 accepts a pointer to a
// subobject there, but not as a template argument of pointer type.
template <class T>
struct member_address {
    T const* address;
};

BSC_DETAIL_DECLARED_ONLY_BEGIN
// Never defined: only its members' addresses are taken, in constant expressions. T is wrapped so
// that a T without linkage (in an anonymous namespace, or local to a function) may be named: the
// wrapper's linkage is the variable's, and Clang refuses an undefined variable of a type without.
template <class T>
struct declared_object {
    T value;
};
template <class T>
extern declared_object<T> const declared_only;

template <auto Address>
constexpr char const* spelled_address() {
    return BSC_DETAIL_FUNCTION_SIGNATURE;
}

// Identifiers may hold letters beyond ASCII, spelled in UTF-8: every byte of those is >= 0x80.
constexpr bool is_identifier_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           static_cast<unsigned char>(c) >= 0x80;
}

// The last identifier of a signature: the member's name, before the closing brackets.
constexpr std::string_view last_identifier(std::string_view s) {
    std::size_t end = s.size();
    while (end > 0 && !is_identifier_char(s[end - 1])) --end;
    std::size_t begin = end;
    while (begin > 0 && is_identifier_char(s[begin - 1])) --begin;
    return s.substr(begin, end - begin);
}

template <class T, std::size_t I>
constexpr std::string_view member_name_of() {
    constexpr auto& member = std::get<I>(tie_fields(declared_only<T>.value));
    using member_type = std::remove_cvref_t<decltype(member)>;
    return last_identifier(spelled_address<member_address<member_type>{&member}>());
}
BSC_DETAIL_DECLARED_ONLY_END

/// The names of T's members, in declaration order. Requirements: T is an aggregate that
/// detail::tie_fields supports.
template <class T>
// clang-format off
inline constexpr auto member_names = []<std::size_t... I>(std::index_sequence<I...>) {
    return std::array<std::string_view, sizeof...(I)>{member_name_of<T, I>()...};
}(std::make_index_sequence<std::tuple_size_v<decltype(tie_fields(std::declval<T&>()))>>{});
// clang-format on

template <class Class, class Member>
Class class_of_member(Member Class::*);

BSC_DETAIL_DECLARED_ONLY_BEGIN
/// The position of the member that the pointer to member `Member` designates among its
/// aggregate's members (their count if none), found by comparing addresses: GCC 12 does not
/// accept the address that `.*` yields as a template argument.
template <auto Member>
constexpr std::size_t member_index() {
    using Class = decltype(class_of_member(Member));
    // clang-format off
    return []<std::size_t... I>(std::index_sequence<I...>) {
        auto const& object = declared_only<Class>.value;
        void const* const target = &(object.*Member);
        auto const fields = tie_fields(object);
        std::size_t found = sizeof...(I);
        ((static_cast<void const*>(&std::get<I>(fields)) == target ? (found = I, 0) : 0), ...);
        return found;
    }(std::make_index_sequence<member_names<Class>.size()>{});
    // clang-format on
}
/// The name of the member that the pointer to member `Member` designates, e.g. "speed" for
/// `&axis::speed`.
template <auto Member>
constexpr std::string_view member_name() {
    using Class = decltype(class_of_member(Member));
    constexpr std::size_t index = member_index<Member>();
    static_assert(index < member_names<Class>.size(), "the pointer designates no member of the aggregate");
    return member_names<Class>[index];
}
BSC_DETAIL_DECLARED_ONLY_END

}  // namespace bsc::detail
// end include/bsc/detail/member_names.hpp
// begin include/bsc/transient.hpp
// bsc::transient<T> and bsc::transient_member<T>: data a context holds that is not part of the
// machine's state (a log, a display buffer, statistics, a handle): not saved by bsc::save, not
// explored, not recorded in waveforms, not sent over the network. Channels and timers inside a
// transient member are still driven by the machine.

namespace bsc {

/// Specialise as true for a member type that is never part of the state.
template <class T>
inline constexpr bool transient = false;

/// One member left out of the state, whatever its type: `bsc::transient_member<int> scans;`.
/// Reads and writes as the T it holds (`++ctx.scans.value`, or through its conversions).
template <class T>
struct transient_member {
    T value{};

    constexpr operator T&() & { return value; }             // NOLINT(google-explicit-constructor)
    constexpr operator T const&() const& { return value; }  // NOLINT(google-explicit-constructor)
    constexpr transient_member& operator=(T const& v) {
        value = v;
        return *this;
    }
    constexpr T* operator->() { return &value; }
    constexpr T const* operator->() const { return &value; }
};

template <class T>
inline constexpr bool transient<transient_member<T>> = true;

}  // namespace bsc
// end include/bsc/transient.hpp

namespace bsc::detail {

template <class T>
inline constexpr bool is_std_array = false;
template <class T, std::size_t N>
inline constexpr bool is_std_array<std::array<T, N>> = true;

template <class T>
inline constexpr bool is_timer = std::is_base_of_v<timer_base, T>;

template <class T>
inline constexpr bool is_chrono_duration = false;
template <class Rep, class Period>
inline constexpr bool is_chrono_duration<std::chrono::duration<Rep, Period>> = true;

// An enum whose every value of the underlying type is a value of the enum: a scoped enum, or one
// declared with `: type` (only those can be list-initialised from an integer).
template <class T>
inline constexpr bool has_fixed_underlying_type = requires {
    T{std::underlying_type_t<T>{}};
};

/// A type that bsc::fields<T> describes.
template <class T>
concept described_by_fields = requires {
    bsc::fields<T>::names;
};

/// A type adapted by BOOST_HANA_DEFINE_STRUCT (its nested accessors), told apart without Boost.
template <class T>
concept adapted_by_hana = requires {
    typename T::hana_accessors_impl;
};

enum class member_kind : std::uint8_t {
    machine,
    channel,
    timer,  // the machine's own
    boolean,
    signed_integer,
    unsigned_integer,
    enumeration,
    floating,
    time,  // scalars
    array,
    record,      // walked into
    opaque,      // a leaf bsc does not look into
    unwalkable,  // may hide state: an error
};

// ---- aggregates bsc cannot walk ----------------------------------------------------------------

// Converts only to a base class of T: T{only_base<T>{}} compiles when T's first element is a base.
template <class T>
struct only_base {
    template <class U>
        requires(std::is_base_of_v<U, T> && !std::is_same_v<U, T>)
    constexpr operator U() const;  // only used in unevaluated contexts
};

template <class T, std::size_t... I>
constexpr bool braced_constructible(std::index_sequence<I...>) {
    return requires { T{{(void(I), any_field{})}...}; };
}
template <class T, std::size_t... I, std::size_t... J>
constexpr bool braced_then_flat_constructible(std::index_sequence<I...>, std::index_sequence<J...>) {
    return requires { T{{(void(I), any_field{})}..., (void(J), any_field{})...}; };
}
// The elements that accept a braced initialiser, one each: a C array takes one, where the flat
// count (field_count) takes one per element of the array.
template <class T, std::size_t N = 0>
constexpr std::size_t braced_element_count() {
    if constexpr (!braced_constructible<T>(std::make_index_sequence<N + 1>{}))
        return N;
    else
        return braced_element_count<T, N + 1>();
}
// Whether an aggregate holds a C array: fewer elements by braced initialisers than by flat ones,
// and the flat ones cannot finish what the braced ones began (a member that refuses a braced
// initialiser, such as a std::atomic or a reference, stops the braced count too, but the flat
// initialisers then initialise it and the rest).
template <class T>
constexpr bool has_c_array() {
    constexpr std::size_t flat = field_count<T>();
    if constexpr (flat > max_fields || braced_constructible<T>(std::make_index_sequence<flat>{})) {
        return false;
    } else {
        constexpr std::size_t braced = braced_element_count<T>();
        return braced < flat && !braced_then_flat_constructible<T>(std::make_index_sequence<braced>{},
                                                                   std::make_index_sequence<flat - braced>{});
    }
}

enum class aggregate_problem : std::uint8_t { none, base_class, c_array, too_many_members };

template <class T>
constexpr aggregate_problem problem_of_aggregate() {
    if constexpr (requires { T{only_base<T>{}}; })
        return aggregate_problem::base_class;
    else if constexpr (field_count<T>() > max_fields)
        return aggregate_problem::too_many_members;
    else if constexpr (has_c_array<T>())
        return aggregate_problem::c_array;
    else
        return aggregate_problem::none;
}

// Whether T is, or may hold, a channel, a timer or a machine, looking Depth levels deep through
// members, elements, pointers and template arguments: what a type bsc cannot look into must not
// hide. Its own classification, not kind_of's, and bounded, so that a type that holds itself
// (a node with a pointer to the next, a tree of std::vector<node>) is asked a finite question.
// Only complete types are asked (a pointer to an incomplete type hides nothing).
inline constexpr int hiding_depth = 4;

template <class T, int Depth>
constexpr bool may_hold_state();

template <int Depth, class T>
struct hides_in_arguments : std::false_type {};
template <int Depth, template <class...> class Template, class... Arguments>
struct hides_in_arguments<Depth, Template<Arguments...>>
    : std::bool_constant<(may_hold_state<Arguments, Depth>() || ...)> {};
template <int Depth, template <class, auto, auto...> class Template, class Element, auto Value, auto... Values>
struct hides_in_arguments<Depth, Template<Element, Value, Values...>>  // a static_vector<T, N>, a std::span<T, N>
    : std::bool_constant<may_hold_state<Element, Depth>()> {};

template <class T, int Depth>
constexpr bool may_hide_state() {
    using pointee = std::remove_cv_t<std::remove_pointer_t<T>>;
    if constexpr (std::is_pointer_v<T>) {  // (a pointer to a machine is a handle on another actor)
        if constexpr (!requires { sizeof(pointee); })
            return false;
        else
            return !is_machine<pointee> && may_hold_state<pointee, Depth>();
    } else if constexpr (std::is_union_v<T>) {
        return true;  // bsc cannot see which member is alive
    } else if constexpr (std::is_array_v<T>) {
        return may_hold_state<std::remove_cv_t<std::remove_all_extents_t<T>>, Depth>();
    } else if constexpr (hides_in_arguments<Depth, T>::value) {
        return true;
    } else if constexpr (requires { typename T::value_type; }) {  // a container of a class's own
        return may_hold_state<std::remove_cv_t<typename T::value_type>, Depth>();
    } else {
        return false;
    }
}

// ---- the rule ------------------------------------------------------------------------------------

/// What T is to bsc (T without const or volatile).
template <class T>
constexpr member_kind kind_of() {
    if constexpr (is_machine<T>)
        return member_kind::machine;
    else if constexpr (is_channel<T>)
        return member_kind::channel;
    else if constexpr (is_timer<T>)
        return member_kind::timer;
    else if constexpr (std::is_same_v<T, bool>)
        return member_kind::boolean;
    else if constexpr (std::is_integral_v<T> && sizeof(T) <= 8)
        return std::is_signed_v<T> ? member_kind::signed_integer : member_kind::unsigned_integer;
    else if constexpr (std::is_enum_v<T>)
        return member_kind::enumeration;
    else if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>)
        return member_kind::floating;
    else if constexpr (is_chrono_duration<T>)
        return member_kind::time;
    else if constexpr (is_std_array<T>)
        return member_kind::array;
    else if constexpr (described_by_fields<T>)
        return member_kind::record;
    else if constexpr (adapted_by_hana<T>)
        return member_kind::unwalkable;  // <bsc/adapt/hana.hpp> is not included
    else if constexpr (std::is_class_v<T> && std::is_aggregate_v<T> && !std::is_union_v<T>)
        return problem_of_aggregate<T>() == aggregate_problem::none ? member_kind::record : member_kind::unwalkable;
    else if constexpr (may_hide_state<T, hiding_depth>())
        return member_kind::unwalkable;
    else
        return member_kind::opaque;
}

template <class T>
constexpr bool is_transient = bsc::transient<T>;

// ---- records -------------------------------------------------------------------------------------

// f(members...) for a record's members, each an lvalue (const for a const record).
template <class T, class F>
BSC_DETAIL_VISIT_INLINE  // as detail::apply_to_fields (detail/fields.hpp)
    constexpr decltype(auto)
    apply_members(T& t, F&& f) {
    using type = std::remove_const_t<T>;
    if constexpr (described_by_fields<type>)
        return bsc::fields<type>::apply(t, static_cast<F&&>(f));
    else
        return field_binder<field_count<type>()>::apply(t, f);
}

struct list_member_types {
    template <class... Members>
    type_list<Members...> operator()(Members&...) const {
        return {};
    }
};
/// The types of a record's members, const where the member is, in order.
template <class T>
using member_types = decltype(apply_members(std::declval<T&>(), list_member_types{}));

template <class T>
// clang-format off
inline constexpr std::size_t member_count = []<class... M>(type_list<M...>) { return sizeof...(M); }(member_types<T>{});
// clang-format on

template <class T, int Depth>
constexpr bool may_hold_state() {
    using U = std::remove_cv_t<T>;
    if constexpr (Depth <= 0 || !requires { sizeof(U); }) {
        return false;
    } else if constexpr (is_machine<U> || is_channel<U> || is_timer<U>) {
        return true;
    } else if constexpr (is_std_array<U>) {
        return may_hold_state<typename U::value_type, Depth - 1>();
    } else if constexpr (described_by_fields<U> ||
                         (std::is_class_v<U> && std::is_aggregate_v<U> && !std::is_union_v<U> &&
                          problem_of_aggregate<U>() == aggregate_problem::none)) {
        // clang-format off
        return []<class... M>(type_list<M...>) {
            return (may_hold_state<M, Depth - 1>() || ...);
        }(member_types<U>{});
        // clang-format on
    } else if constexpr (std::is_class_v<U> && std::is_aggregate_v<U> && !std::is_union_v<U>) {
        // An aggregate bsc cannot walk is reported where it is a member; held by a template (a
        // std::vector of them) it is not taken to hide anything.
        return false;
    } else {
        return may_hide_state<U, Depth - 1>();
    }
}

// ---- the errors ------------------------------------------------------------------------------------

template <class T>
constexpr void report_unwalkable_aggregate() {
    constexpr aggregate_problem p = problem_of_aggregate<T>();
    if constexpr (p == aggregate_problem::base_class)
        detail::report<error::context_type_has_base_class<T>>();
    else if constexpr (p == aggregate_problem::c_array)
        detail::report<error::context_type_has_c_array<T>>();
    else if constexpr (p == aggregate_problem::too_many_members)
        detail::report<error::too_many_fields<T>>();
}

// Reports what makes T unwalkable: an aggregate bsc cannot walk by its own problem; any other
// type (optional, variant, a container, a union, a pointer) as member I of its Owner.
template <class Owner, std::size_t I, class T>
constexpr void report_unwalkable() {
    if constexpr (adapted_by_hana<T> && !described_by_fields<T>)
        detail::report<error::hana_adapter_not_included<T>>();
    else if constexpr (std::is_class_v<T> && std::is_aggregate_v<T> && !std::is_union_v<T> && !described_by_fields<T>)
        report_unwalkable_aggregate<T>();
    else
        detail::report<error::state_out_of_reach<Owner, error::member_number<I>, T>>();
}

// ---- the walk of values ------------------------------------------------------------------------------

// What a visitor of walk() may declare:
//   static constexpr bool all = true;          walk transient members too (the machine's own
//                                              walk: their channels and timers are driven)
//   template <class T> static constexpr bool visits;   the leaves it wants; subtrees holding none
//                                              are not walked (default: every leaf)
//   void leaf(T& value, Name const& name)      each leaf (machine, channel, timer, scalar, opaque)
//   and, for names: static constexpr bool named = true; enter(name), leave() around a record's
//   members, and element_name(name, i) for an array's elements.
struct no_name {};

template <class V>
constexpr bool walks_all() {
    if constexpr (requires { V::all; })
        return V::all;
    else
        return false;
}
template <class V>
constexpr bool wants_names() {
    if constexpr (requires { V::named; })
        return V::named;
    else
        return false;
}
template <class V, class T>
constexpr bool visits_leaf() {
    if constexpr (requires { V::template visits<T>; })
        return V::template visits<T>;
    else
        return true;
}

/// Whether a walk with V would reach any leaf of T (so that a walk of a context with none of the
/// leaves V wants costs nothing, not even a call).
template <class V, class T>
constexpr bool reaches() {
    using U = std::remove_cv_t<T>;
    if constexpr (is_transient<U> && !walks_all<V>()) {
        return false;
    } else {
        constexpr member_kind k = kind_of<U>();
        if constexpr (k == member_kind::unwalkable)
            return false;  // reported where its owner is walked
        else if constexpr (k == member_kind::array)
            return reaches<V, typename U::value_type>();
        else if constexpr (k == member_kind::record)
            // clang-format off
            return []<class... M>(type_list<M...>) { return (reaches<V, M>() || ...); }(member_types<U>{});
        // clang-format on
        else
            return visits_leaf<V, U>();
    }
}

// Reports every unwalkable member of T, at any depth, once per type: each walk and fold calls it
// for its root, so that nothing bsc cannot reach is skipped in silence. Transient members and
// what they hold are the user's word that they need not be walked.
template <class T>
constexpr bool check_reachable();

template <class Owner, std::size_t I, class M>
constexpr bool check_member() {
    using U = std::remove_cv_t<M>;
    if constexpr (!is_transient<U> && kind_of<U>() == member_kind::unwalkable) {
        report_unwalkable<Owner, I, U>();
        return false;
    } else {
        return check_reachable<M>();
    }
}

template <class T>
constexpr bool check_reachable() {
    using U = std::remove_cv_t<T>;
    constexpr member_kind k = kind_of<U>();
    if constexpr (is_transient<U>) {
        return true;
    } else if constexpr (k == member_kind::array) {
        return check_reachable<typename U::value_type>();
    } else if constexpr (k == member_kind::record) {
        // clang-format off
        return []<class... M, std::size_t... I>(type_list<M...>, std::index_sequence<I...>) {
            return ((check_member<U, I, M>() ? 0 : 1) + ... + 0) == 0;
        }(member_types<U>{}, std::make_index_sequence<member_count<U>>{});
        // clang-format on
    } else if constexpr (k == member_kind::unwalkable) {
        report_unwalkable<void, 0, U>();  // the root itself
        return false;
    } else {
        return true;
    }
}
template <class T>
inline constexpr bool reachable = check_reachable<T>();

/// The names of a record's members, in order.
template <class T>
constexpr auto const& names_of() {
    if constexpr (described_by_fields<T>)
        return bsc::fields<T>::names;
    else
        return member_names<T>;
}

template <class V, class T, class Name>
BSC_DETAIL_VISIT_INLINE  // as detail::apply_to_fields (detail/fields.hpp)
    constexpr void
    walk_into(T& value, V& v, Name const& name) {
    using U = std::remove_cv_t<T>;
    using visitor = std::remove_const_t<V>;
    constexpr member_kind k = kind_of<U>();
    if constexpr (!reaches<visitor, U>()) {
        (void)value, (void)v, (void)name;
    } else if constexpr (k == member_kind::array) {
        std::size_t i = 0;
        for (auto& element : value) {
            if constexpr (wants_names<visitor>())
                walk_into(element, v, v.element_name(name, i++));
            else
                walk_into(element, v, name);
        }
    } else if constexpr (k == member_kind::record) {
        if constexpr (wants_names<visitor>()) {
            v.enter(name);
            std::size_t i = 0;
            apply_members(value, [&](auto&... member) { (walk_into(member, v, names_of<U>()[i++]), ...); });
            v.leave();
        } else {
            apply_members(value, [&](auto&... member) { (walk_into(member, v, name), ...); });
        }
    } else {
        v.leaf(value, name);
    }
}

/// Walks `value` with visitor v, depth first, in declaration order: v.leaf(member, name) for
/// each leaf it visits. Every member bsc cannot reach is a compile error.
template <class V, class T, class Name = no_name>
BSC_DETAIL_VISIT_INLINE  // as detail::apply_to_fields (detail/fields.hpp)
    constexpr void
    walk(T& value, V& v, Name const& name = {}) {
    static_assert(reachable<T> || true);  // instantiates the check (its errors are the report)
    walk_into(value, v, name);
}

// ---- the fold over types -------------------------------------------------------------------------------

// What a folder of fold_type declares: `using result = ...;` and
//   template <class T> result leaf() const          a leaf (T may be const)
//   template <class T> result array(result element) const
//   template <class T, class... M> result record(std::array<result, n> const& members) const
// Transient types are leaves too (folders that skip them test is_transient).
template <class F, class T>
constexpr typename F::result fold_type(F const& f) {
    using U = std::remove_cv_t<T>;
    constexpr member_kind k = kind_of<U>();
    if constexpr (is_transient<U>) {
        return f.template leaf<T>();
    } else if constexpr (k == member_kind::array) {
        return f.template array<U>(fold_type<F, typename U::value_type>(f));
    } else if constexpr (k == member_kind::record) {
        // clang-format off
        return []<class... M>(F const& folder, type_list<M...>) {
            return folder.template record<U>(
                std::array<typename F::result, sizeof...(M)>{fold_type<F, M>(folder)...});
        }(f, member_types<U>{});
        // clang-format on
    } else {
        return f.template leaf<T>();  // (an unwalkable T is reported by check_reachable)
    }
}

// A fold that adds up what each leaf takes (bytes, bits): a transient leaf nothing, an array its
// elements', a record its members'. Derived supplies share<T, K>() for a leaf of type T (const
// where the member is) and kind K.
template <class Derived>
struct summing_fold {
    using result = std::size_t;
    template <class T>
    constexpr std::size_t leaf() const {
        using U = std::remove_cv_t<T>;
        if constexpr (is_transient<U>)
            return 0;
        else
            return static_cast<Derived const&>(*this).template share<T, kind_of<U>()>();
    }
    template <class T>
    constexpr std::size_t array(std::size_t element) const {
        return std::tuple_size_v<T> * element;
    }
    template <class T, std::size_t N>
    constexpr std::size_t record(std::array<std::size_t, N> const& members) const {
        std::size_t total = 0;
        for (std::size_t m : members) total += m;
        return total;
    }
};

/// fold_type from the root of a walk: every member bsc cannot reach is a compile error.
template <class F, class T>
constexpr typename F::result fold(F const& f) {
    static_assert(reachable<T> || true);
    return fold_type<F, T>(f);
}

}  // namespace bsc::detail
// end include/bsc/detail/members.hpp

namespace bsc::detail {

// Calls act(point) for each channel (Channels) or each timer of a context, transient members'
// included.
template <bool Channels, class Act>
struct point_visitor {
    static constexpr bool all = true;
    template <class T>
    static constexpr bool visits = Channels ? is_channel<T> : is_timer<T>;
    Act act;
    template <class Point>
    constexpr void leaf(Point& point, no_name) const {
        act(point);
    }
};

struct latch_act {
    template <class Channel>
    constexpr void operator()(Channel& c) const {
        access::latch(c);
    }
};
struct commit_act {
    template <class Channel>
    constexpr void operator()(Channel& c) const {
        access::commit(c);
    }
};
struct update_act {
    duration now;
    template <class Timer>
    constexpr void operator()(Timer& t) const {
        access::update(t, now);
    }
};
using latch_visitor = point_visitor<true, latch_act>;
using update_visitor = point_visitor<false, update_act>;

template <class Ctx>
inline constexpr bool has_channels = reaches<latch_visitor, Ctx>();
template <class Ctx>
inline constexpr bool has_timers = reaches<update_visitor, Ctx>();

template <class Ctx>
constexpr void latch_inputs(Ctx& ctx) {
    latch_visitor const v{};
    walk(ctx, v);
}

template <class Ctx>
constexpr void commit_outputs(Ctx& ctx) {
    point_visitor<true, commit_act> const v{};
    walk(ctx, v);
}

template <class Ctx>
constexpr void update_timers(Ctx& ctx, duration now) {
    update_visitor const v{{now}};
    walk(ctx, v);
}

}  // namespace bsc::detail
// end include/bsc/detail/runtime/context_data.hpp
// begin include/bsc/detail/runtime/notify.hpp
// The calls a machine makes to its observer, by state and row number: each hook is called
// only if the observer has it, and a machine without observer generates nothing.

#include <type_traits>

// begin include/bsc/detail/guard_label.hpp
// The label of a guard, as the exports draw it and the logger writes it: its name (bsc::named),
// a composition of named guards with their operators, or "guard"; bsc::in<S> is "In(S)". Also
// the pieces the labels of actions share (detail/export/model.hpp): has_name, expression,
// parenthesized.

#include <string>
#include <string_view>
#include <type_traits>


namespace bsc::detail {

/// A guard or action that has a name (bsc::named, or any callable with a `name` member).
template <class T>
concept has_name = requires(T const& t) {
    std::string_view{t.name};
};

template <class T>
inline constexpr bool is_not_guard = false;
template <class G>
inline constexpr bool is_not_guard<not_guard<G>> = true;
template <class T>
inline constexpr bool is_and_guard = false;
template <class L, class R>
inline constexpr bool is_and_guard<and_guard<L, R>> = true;
template <class T>
inline constexpr bool is_or_guard = false;
template <class L, class R>
inline constexpr bool is_or_guard<or_guard<L, R>> = true;
template <class T>
inline constexpr bool is_guard_fn = false;
template <class F>
inline constexpr bool is_guard_fn<guard_fn<F>> = true;
template <class T>
inline constexpr bool is_in_guard = false;
template <class S>
inline constexpr bool is_in_guard<in_guard<S>> = true;

// How a label writes bsc::in<S>: "In(S)" with S's unqualified name. The exports pass their own,
// which names S as their diagrams do (detail/export/model.hpp).
struct in_by_name {
    template <class S>
    std::string operator()(std::type_identity<S>) const {
        return "In(" + std::string(name_of<S>) + ")";
    }
};

/// A label and whether any part of it was named; `precedence` places parentheses:
/// 1 for ||, 2 for &&, 3 for a name or a negation.
struct expression {
    std::string text;
    bool named = false;
    int precedence = 3;
};

inline std::string parenthesized(expression const& e, int context) {
    return e.precedence < context ? "(" + e.text + ")" : e.text;
}

template <class G, class InText = in_by_name>
expression guard_expression(G const& g, InText const& in_text = {}) {
    if constexpr (has_name<G>) {
        return {std::string(std::string_view{g.name}), true, 3};
    } else if constexpr (is_in_guard<G>) {
        return {in_text(std::type_identity<typename G::state>{}), true, 3};
    } else if constexpr (is_not_guard<G>) {
        auto const inner = guard_expression(g.g, in_text);
        return {"!" + parenthesized(inner, 3), inner.named, 3};
    } else if constexpr (is_and_guard<G> || is_or_guard<G>) {
        int const precedence = is_and_guard<G> ? 2 : 1;
        auto const l = guard_expression(g.l, in_text);
        auto const r = guard_expression(g.r, in_text);
        return {parenthesized(l, precedence) + (is_and_guard<G> ? " && " : " || ") + parenthesized(r, precedence),
                l.named || r.named, precedence};
    } else if constexpr (is_guard_fn<G>) {
        return guard_expression(g.fn, in_text);
    } else {
        return {"guard", false, 3};
    }
}

/// The label of a guard: its name, a composition of named guards ("!released && at_home", an
/// unnamed part shown as "guard"), or "guard" when no part has a name. bsc::in<S> counts as
/// named: "In(S)", or as `in_text(std::type_identity<S>{})` writes it.
template <class G, class InText = in_by_name>
std::string guard_label(G const& g, InText const& in_text = {}) {
    auto const e = guard_expression(g, in_text);
    return e.named ? e.text : "guard";
}

}  // namespace bsc::detail
// end include/bsc/detail/guard_label.hpp

namespace bsc::detail {

template <class Model, class Observer>
struct notify {
    template <int S>
    using tag = state_tag<typename Model::template tag_at<S>>;

    template <int Row>
    using source_tag = state_tag<typename Model::template row_at<Row>::source>;
    template <int Row, class Target = typename Model::template row_at<Row>::target>
    using target_tag = std::conditional_t<std::is_same_v<Target, no_target>, state_tag<internal>, state_tag<Target>>;

    template <int S>
    static constexpr bool observes_entry_of = S > 0 && observes_entry<Observer, tag<S>>;
    template <int S>
    static constexpr bool observes_exit_of = S > 0 && observes_exit<Observer, tag<S>>;
    // The event on_transition receives for row Row taken on E: a timeout row's delay.
    template <int Row, class E>
    using reported_event = std::conditional_t<is_timeout_row<typename Model::template row_at<Row>>, timeout_elapsed, E>;
    template <int Row, class E>
    static constexpr bool observes_row =
        observes_transition<Observer, source_tag<Row>, target_tag<Row>, reported_event<Row, E>> ||
        observes_rows<Observer> || (Model::rows.guarded[Row] && observes_guards<Observer>) ||
        (Model::rows.defers[Row] && observes_deferrals<Observer, source_tag<Row>, E>);

    // After state S's entry actions.
    template <int S>
    static constexpr void entered(Observer& o) {
        if constexpr (observes_entry_of<S>) o.on_entry(tag<S>{});
    }
    // After state S's exit actions.
    template <int S>
    static constexpr void exited(Observer& o) {
        if constexpr (observes_exit_of<S>) o.on_exit(tag<S>{});
    }
    // Before the action of transition Row (the row object `row`), taken on event e; a timeout
    // row reports timeout_elapsed with its delay instead (reported_event).
    template <int Row, class RowObject, class E>
    static constexpr void transition(Observer& o, RowObject const& row, E const& e) {
        using reported = reported_event<Row, E>;
        if constexpr (Model::rows.guarded[Row] && observes_guards<Observer>) o.on_guard(guard_label(row.guard));
        if constexpr (Model::rows.defers[Row] && observes_deferrals<Observer, source_tag<Row>, E>)
            o.on_defer(source_tag<Row>{}, e);
        if constexpr (observes_transition<Observer, source_tag<Row>, target_tag<Row>, reported>) {
            if constexpr (std::is_same_v<reported, timeout_elapsed>)
                o.on_transition(source_tag<Row>{}, target_tag<Row>{}, timeout_elapsed{row.trigger_value.delay});
            else
                o.on_transition(source_tag<Row>{}, target_tag<Row>{}, e);
        }
        if constexpr (observes_rows<Observer>) o.on_row(Row);
    }

    // A dispatch of e begins; a cycle at time now begins; that cycle ends.
    template <class E>
    static constexpr void dispatching(Observer& o, E const& e) {
        if constexpr (observes_dispatch<Observer, E>) o.on_dispatch(e);
    }
    static constexpr void cycle_begins(Observer& o, duration now) {
        if constexpr (observes_cycles<Observer>) o.on_cycle(now);
    }
    static constexpr void cycle_ends(Observer& o) {
        if constexpr (observes_cycle_ends<Observer>) o.on_cycle_end();
    }
};

}  // namespace bsc::detail
// end include/bsc/detail/runtime/notify.hpp
// begin include/bsc/detail/runtime/settling.hpp
// Run to completion: a dispatched event's microstep, then eventless transitions, raised events and
// deferred events until none remains, within the policy's limits (outcome::livelock past them);
// in a BSC cycle, the components' turns and the raised events without eventless settling. A
// layer of the driver (detail/runtime/driver.hpp).

#include <cstddef>
#include <utility>

// begin include/bsc/detail/runtime/done_raising.hpp
// Completion (SCXML's done.state events; the rule is detail/model/completion.hpp): done<S> raised
// when a final state is entered, and for a parallel state once all its regions are final, at the
// moment SCXML raises it; and the exit of every state when the machine halts. Called by the back
// ends as they enter states. A layer of the driver (detail/runtime/driver.hpp).

#include <cstddef>
#include <utility>

// begin include/bsc/detail/runtime/deferral.hpp
// Deferred events (`/ bsc::defer`): what the back ends report while a microstep selects and
// fires (a deferring row, another transition), the event kept when only deferring rows took it,
// and the retries, in the order the events came, after a transition changes the configuration.
// A layer of the driver (detail/runtime/driver.hpp).

#include <type_traits>

// begin include/bsc/detail/runtime/run_control.hpp
// A run's bracket and its failures: the mark of a run under way (the refusal of a reentrant
// call), the guarded call of a guard or action, what a failure becomes (bsc::action_failed on
// the queue, or kept for the caller), and the end of a run (the outcome recorded, a kept failure
// rethrown or reported). A layer of the driver (detail/runtime/driver.hpp).

#include <exception>
#include <utility>

// begin include/bsc/detail/assume.hpp
// Tells the optimiser a fact the code keeps but cannot show it (a machine's status byte has no
// failure bit set between runs; its queue is empty between runs), so that it drops the tests
// the fact settles. The fact must hold: where it does not, the behaviour is undefined. GCC
// follows what it is told through later tests; Clang drops it where paths join (driver.hpp says
// what it does there instead). A build without NDEBUG tests the fact instead, and stops the
// program where it does not hold. (The compilers' spellings: detail/config.hpp.)

#include <cassert>


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
// end include/bsc/detail/assume.hpp
// begin include/bsc/detail/runtime/explorer_queries.hpp
// What only the explorer (bsc::verify, through detail::access) asks of a machine: its
// configuration with the bytes that can no longer matter reset, whether a timeout's age still
// matters, and the delays of the timeout rows. A layer of the driver (detail/runtime/driver.hpp).

#include <array>
#include <cstddef>

// begin include/bsc/detail/runtime/timeouts.hpp
// Timeouts (`after(delay)` rows): a state's timeouts count from its entry, a timeout is due once
// its delay has elapsed at the time of the last cycle, a due timeout that leaves its state active
// counts again from then, and of a state's timeouts due at once the first to come due fires. The
// back ends say when (a state entered, a timeout row tried or fired); the rule is here, once.
// Slots are numbered as detail/model/layout.hpp numbers them. A layer of the driver
// (detail/runtime/driver.hpp).

#include <cstddef>

// begin include/bsc/detail/runtime/machine_data.hpp
// What a machine holds, and where: the chart (or nothing, for a chart every machine shares), the
// queue, the clock, the timeouts' entry times, the failures, the observer, the context, the
// configuration bytes, the deferred events and the run's status; the types and facts of the
// chart the rest of the driver reads; and the layout helpers that make a member take no room
// where the chart does not need it. The bottom layer of the driver (detail/runtime/driver.hpp).

#include <array>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <type_traits>
#include <utility>

// begin include/bsc/detail/model/completion.hpp
// Completion (SCXML 3.7.1): which states raise bsc::done<S>, and the flags a machine keeps
// while it enters a parallel state. Computed only for a chart that can take a done event (it
// names one, or takes bsc::any_event); for every other chart all of this is empty, and the
// back ends generate nothing for it.

#include <array>
#include <cstddef>


namespace bsc::detail {

template <class E>
inline constexpr bool is_done_event = false;
template <class S>
inline constexpr bool is_done_event<done<S>> = true;
template <>
inline constexpr bool is_done_event<any_event> = true;  // it takes done events too

template <class Model>
struct completion {
    static constexpr int N = Model::N;
    static constexpr auto const& tree = Model::tree;

    // Whether a row of the chart can take a done event.
    // clang-format off
    static constexpr bool takes_any = []<class... Es>(type_list<Es...>) {
        return any_true({is_done_event<Es>..., false});
    }(typename Model::events{});
    // clang-format on

    // trigger[s]: the trigger of bsc::done<S> for a composite or parallel state S other than
    // the root, or -1 (no row takes it, or it is never raised).
    static constexpr std::array<int, static_cast<std::size_t>(N)> trigger = [] {
        std::array<int, static_cast<std::size_t>(N)> out{};
        for (int& t : out) t = -1;
        if constexpr (takes_any)
            // clang-format off
            [&]<class... Tags>(type_list<Tags...>) {
                std::size_t s = 0;
                [[maybe_unused]] int const set[] = {  // (in order, as a list: max_fold)
                    (out[s] = s > 1 && (tree.kinds[s] == kind::composite || tree.kinds[s] == kind::parallel)
                                  ? Model::template trigger_of<done<Tags>>::value
                                  : -1,
                     ++s, 0)...};
            }(typename Model::tags{});
        // clang-format on
        return out;
    }();

    // Whether the machine ever raises a done event: then it needs a queue.
    static constexpr bool raises = [] {
        for (int t : trigger)
            if (t >= 0) return true;
        return false;
    }();

    // The parallel states whose done event is taken, numbered: while one is being entered, a
    // final state entered in one of its regions must not look at the regions not yet entered
    // (their bytes are the history of an earlier visit).
    static constexpr int parallel_count = [] {
        int n = 0;
        for (int s = 0; s < N; ++s)
            n += tree.kinds[static_cast<std::size_t>(s)] == kind::parallel && trigger[static_cast<std::size_t>(s)] >= 0;
        return n;
    }();
    static constexpr auto parallel_number = [] {
        std::array<int, static_cast<std::size_t>(N)> out{};
        int n = 0;
        for (int s = 0; s < N; ++s)
            out[static_cast<std::size_t>(s)] = tree.kinds[static_cast<std::size_t>(s)] == kind::parallel &&
                                                       trigger[static_cast<std::size_t>(s)] >= 0
                                                   ? n++
                                                   : -1;
        return out;
    }();
};

// What a machine keeps for completion: one flag per parallel state whose done event is taken,
// set while the state's regions are being entered. Nothing for other charts.
template <int Parallels>
struct entering_flags {
    std::array<bool, static_cast<std::size_t>(Parallels)> flag{};
};
template <>
struct entering_flags<0> {};

}  // namespace bsc::detail
// end include/bsc/detail/model/completion.hpp
// begin include/bsc/detail/runtime/event_queue.hpp
// The bounded internal event queue: a ring buffer of the chart's event types. No heap;
// a push onto a full queue is refused and remembered, never written out of bounds.

#include <array>
#include <cstddef>
#include <type_traits>
#include <variant>


namespace bsc::detail {

// What every bounded queue keeps: its slots (Slots, first, where a machine's members of large
// alignment go), where the oldest event is, how many there are, and whether a raise found the
// queue full.
template <std::size_t Capacity, class Slots>
class ring {
public:
    constexpr bool empty() const { return size_ == 0; }
    constexpr std::size_t size() const { return size_; }
    static constexpr std::size_t capacity() { return Capacity; }
    constexpr bool overflowed() const { return overflowed_; }
    constexpr void clear_overflow() { overflowed_ = false; }
    constexpr void clear() { head_ = size_ = 0; }

    // Between runs a machine's queue is empty, rewound and without overflow: every run ends so
    // (detail/runtime/settling.hpp: settled, abandon; run_control.hpp: end_run_by_exception). Said to the optimiser at
    // the start of a dispatch, so that it places the events a dispatch raises at known slots
    // and drops the tests of a queue it sees nothing raised into: a raise then costs about a
    // store, its processing a load (docs/performance.md,
    // rule "Tell the optimiser what a run guarantees"). A hidden friend, not a member: the
    // queue is the raise argument of every action, which should not be handed a promise it
    // can break.
    friend constexpr void assume_idle(ring const& q) { detail::assume(q.size_ == 0 && q.head_ == 0 && !q.overflowed_); }
    // Puts the oldest event back at the first slot; only for an empty queue (at the end of a
    // run), where it costs one store and no test.
    friend constexpr void rewind_empty(ring& q) { q.head_ = 0; }

protected:
    // True, and the overflow marked, if the queue is full: the raise then stores nothing.
    constexpr bool refuse_when_full() {
        if (size_ == Capacity) {
            overflowed_ = true;
            return true;
        }
        return false;
    }
    // The slot after the newest event; added() counts the event once it is stored there.
    constexpr std::size_t back() const { return (head_ + size_) % Capacity; }
    constexpr void added() { ++size_; }
    // The slot of the oldest event; drop_front() takes it out once it is read. (A queue whose
    // slots hold nothing only counts: removed().)
    constexpr std::size_t front() const { return head_; }
    constexpr void drop_front() {
        head_ = (head_ + 1) % Capacity;
        removed();
    }
    constexpr void removed() { --size_; }

    [[no_unique_address]] Slots items_{};

private:
    std::size_t head_ = 0;
    std::size_t size_ = 0;
    bool overflowed_ = false;
};

// The position among Events of the event an event E is queued as: E itself, or its nearest
// family (detail/model/event_families.hpp): the rows that take it see no more of it than that. -1: none.
template <class E, class... Es>
constexpr int queued_index(type_list<Es...>) {
    return trigger_in<E, type_list<Es...>>::value;  // its own position first, as a chart's trigger
}

// Raises e into a queue of Events: push(f) with the event e is queued as, or, for an event the
// chart does not name, the error that says so (and false).
template <class Events, class E, class Push>
constexpr bool raise_into(E const& e, Push&& push) {
    constexpr int as = queued_index<E>(Events{});
    if constexpr (as < 0) {
        detail::report<error::raised_event_not_in_chart<E>>();
        return false;
    } else {
        return push(event_as<at<static_cast<std::size_t>(as), Events>>(e));
    }
}

template <std::size_t Capacity, class Events>
class event_queue;

template <std::size_t Capacity, class... Es>
class event_queue<Capacity, type_list<Es...>>
    : public ring<Capacity, std::array<std::variant<std::monostate, Es...>, Capacity>> {
    using ring<Capacity, std::array<std::variant<std::monostate, Es...>, Capacity>>::items_;

public:
    using value_type = std::variant<std::monostate, Es...>;

    /// Raises e: queues it for processing after the current step. False if the queue is full.
    /// An event the chart does not name is queued as its nearest family (detail/model/event_families.hpp):
    /// the rows that take it see no more of it than that.
    template <class E>
    constexpr bool operator()(E const& e) noexcept(std::is_nothrow_copy_constructible_v<E>) {
        return raise_into<type_list<Es...>>(e, [this]<class F>(F const& f) { return this->template push<F>(f); });
    }

    // Removes the oldest event and calls f with it.
    template <class F>
    constexpr void pop(F&& f) {
        value_type item = std::move(items_[this->front()]);
        this->drop_front();
        visit_index<static_cast<int>(sizeof...(Es))>(static_cast<int>(item.index()) - 1,
                                                     [&](auto i) { f(*std::get_if<decltype(i)::value + 1>(&item)); });
    }

    // ---- what the queue holds between runs: for the retentive state and the explorer -------
    // Calls f(item) for each event held, oldest first.
    template <class F>
    constexpr void for_each_held(F&& f) const {
        for (std::size_t i = 0; i < this->size(); ++i) f(items_[(this->front() + i) % Capacity]);
    }
    // Queues an item already held as the queue's variant (a delayed event coming due, an event
    // restored).
    constexpr bool push_item(value_type const& item) {
        if (this->refuse_when_full()) return false;
        items_[this->back()] = item;
        this->added();
        return true;
    }

private:
    template <class E>
    constexpr bool push(E const& e) {
        if (this->refuse_when_full()) return false;
        auto& slot = items_[this->back()];
        // Emplacing spares GCC a false -Wmaybe-uninitialized on a temporary variant; Clang
        // 14 cannot emplace into a variant in a constant expression, so that assigns.
        if (std::is_constant_evaluated())
            slot = value_type{std::in_place_type<E>, e};
        else
            slot.template emplace<E>(e);
        this->added();  // (after the copy, which may throw)
        return true;
    }
};

// The slots of a single_event_queue: the events, or for an empty event none.
template <std::size_t Capacity, class E>
struct single_event_slots {
    std::array<E, Capacity> value{};
};
template <std::size_t Capacity, class E>
    requires std::is_empty_v<E>
struct single_event_slots<Capacity, E> {};

// The queue of a chart that raises one event type only, a trivially copyable one whose default
// construction is a constant expression (queue_for.hpp picks it): the events themselves,
// without a variant's index to store, load and switch on; for an empty event, not even the
// events, only their count (a raise is then an increment, as a hand-written flag would be).
template <std::size_t Capacity, class E>
class single_event_queue : public ring<Capacity, single_event_slots<Capacity, E>> {
    static_assert(Capacity > 0 && std::is_trivially_copyable_v<E>);
    static constexpr bool stores_events = !std::is_empty_v<E>;
    using ring<Capacity, single_event_slots<Capacity, E>>::items_;

public:
    /// Raises e, as event_queue does: E itself, or an event of E's family queued as E.
    template <class R>
    constexpr bool operator()(R const& e) noexcept(std::is_nothrow_copy_constructible_v<R>) {
        return raise_into<type_list<E>>(e, [this](E const& f) { return this->push(f); });
    }

    // Removes the oldest event and calls f with it.
    template <class F>
    constexpr void pop(F&& f) {
        if constexpr (stores_events) {
            E const item = items_.value[this->front()];
            this->drop_front();
            f(item);
        } else {
            this->removed();
            f(E{});
        }
    }

private:
    constexpr bool push(E const& e) {
        if (this->refuse_when_full()) return false;
        if constexpr (stores_events) items_.value[this->back()] = e;
        this->added();
        return true;
    }
};

// A chart whose queue capacity is zero raises nothing: every raise is an overflow.
template <class... Es>
class event_queue<0, type_list<Es...>> {
public:
    using value_type = std::variant<std::monostate, Es...>;
    template <class F>
    constexpr void for_each_held(F&&) const {}
    constexpr bool push_item(value_type const&) {
        overflowed_ = true;
        return false;
    }
    template <class E>
    constexpr bool operator()(E const&) noexcept {
        overflowed_ = true;
        return false;
    }
    constexpr bool empty() const { return true; }
    constexpr std::size_t size() const { return 0; }
    static constexpr std::size_t capacity() { return 0; }
    constexpr bool overflowed() const { return overflowed_; }
    constexpr void clear_overflow() { overflowed_ = false; }
    constexpr void clear() {}
    template <class F>
    constexpr void pop(F&&) {}

private:
    bool overflowed_ = false;
};

// The queue of a chart none of whose actions can raise (detail::raised_by_chart): it is always
// empty, and saying so at compile time spares every dispatch the checks for raised events.
// (Not a template: its name is part of the symbols of every action the machine calls.)
class no_event_queue {
public:
    template <class E>
    constexpr bool operator()(E const&) noexcept {  // never called: no action takes the raise argument
        return false;
    }
    static constexpr bool empty() { return true; }
    static constexpr std::size_t size() { return 0; }
    static constexpr std::size_t capacity() { return 0; }
    static constexpr bool overflowed() { return false; }
    constexpr void clear_overflow() {}
    constexpr void clear() {}
    template <class F>
    constexpr void pop(F&&) {}
};

}  // namespace bsc::detail
// end include/bsc/detail/runtime/event_queue.hpp
// begin include/bsc/detail/runtime/failures.hpp
// How a machine catches what its guards and actions throw. Each call of a guard or an action is
// one block: if it throws, the rest of it is skipped and the failure goes to the machine
// (detail::run_control::fail), which raises bsc::action_failed or keeps it for the caller. Built
// without exceptions, these are plain calls.

#include <exception>
#include <type_traits>
#include <utility>

namespace bsc::detail {

// A machine's record of a failure, kept as a pointer so that a machine stays a literal type
// (std::exception_ptr is not one) and usable in constant expressions, where nothing can
// throw. It is allocated only when something has thrown.
class failure_slot {
public:
    constexpr failure_slot() = default;
    constexpr failure_slot(failure_slot const& other) {
        if (!std::is_constant_evaluated() && other.error_ != nullptr) error_ = copy(*other.error_);
    }
    constexpr failure_slot& operator=(failure_slot const& other) {
        if (this != &other) {
            reset();
            if (!std::is_constant_evaluated() && other.error_ != nullptr) error_ = copy(*other.error_);
        }
        return *this;
    }
    constexpr ~failure_slot() { reset(); }

    constexpr explicit operator bool() const { return error_ != nullptr; }
    // Keeps the first failure; later ones of the same run are dropped (the first caused them).
    void keep(std::exception_ptr error) {
        if (error_ == nullptr) error_ = copy(std::move(error));
    }
    std::exception_ptr get() const { return error_ != nullptr ? *error_ : nullptr; }
    std::exception_ptr take() {
        std::exception_ptr error = get();
        reset();
        return error;
    }
    constexpr void reset() {
        if (!std::is_constant_evaluated() && error_ != nullptr) destroy(error_);
        error_ = nullptr;
    }

private:
    static std::exception_ptr* copy(std::exception_ptr error) { return new std::exception_ptr(std::move(error)); }
    static void destroy(std::exception_ptr* error) { delete error; }

    std::exception_ptr* error_ = nullptr;
};

// Where the table engine's thunks report a failure: the machine and its fail().
struct failure_sink {
    void* machine = nullptr;
    void (*report)(void* machine, std::exception_ptr error) = nullptr;
};

// Runs a block; a failure goes to on_failure(std::exception_ptr).
template <class Block, class OnFailure>
constexpr void run_block(Block&& block, OnFailure&& on_failure) {
#if defined(__cpp_exceptions)
    try {
        block();
    } catch (...) {
        on_failure(std::current_exception());
    }
#else
    (void)on_failure;
    block();
#endif
}

}  // namespace bsc::detail
// end include/bsc/detail/runtime/failures.hpp

namespace bsc::detail {

// Whether a row's guard or action can throw, called as a machine calls it: a transition's
// guard with (context, event), or (context, event, configuration) if it tests the configuration
// (bsc::in<S>), and its action with (context, event, queue), an entry or exit action with
// (context, queue).
template <class Context, class Queue, class Row>
struct row_nothrow {  // an entry or exit row
    static constexpr bool value = nothrow_callable_with<decltype(Row::action), Context&, Queue&>;
};
template <class G, class Context, class E, bool = tests_configuration<G>>
inline constexpr bool guard_call_nothrow = nothrow_callable_with<G, Context const&, E const&>;
template <class G, class Context, class E>
inline constexpr bool guard_call_nothrow<G, Context, E, true> =
    nothrow_callable_with<G, Context const&, E const&, any_configuration const&>;
template <class Context, class Queue, class S, class Trigger, class G, class A, class T>
struct row_nothrow<Context, Queue, transition_row<S, Trigger, G, A, T>> {
    using event = row_event_t<transition_row<S, Trigger, G, A, T>>;
    static constexpr bool value = guard_call_nothrow<G, Context, event> &&
                                  nothrow_callable_with<A, Context&, event const&, Queue&>;
};

// Whether any guard or action of the chart can throw. If none can (each is noexcept, or the
// code is built without exceptions), a machine keeps no record of failures and never checks
// for one: containing failures costs nothing where nothing can fail.
template <class Model, class Queue>
constexpr bool chart_may_throw() {
#if defined(__cpp_exceptions)
    // clang-format off
    return []<class... Rows>(type_list<Rows...>) {
        return !all_true({row_nothrow<typename Model::chart_context, Queue, Rows>::value...});
    }(typename Model::row_types{});
    // clang-format on
#else
    return false;
#endif
}

// Whether every machine of a chart can share one constant instance of it instead of storing a
// copy: a chart that holds no data at all (each row is empty: its trigger, guard and action
// carry no value, no delay, no captures, and can be made again from nothing), or a
// bsc::chart_ref, which names the constexpr variable that holds the chart. A machine of such a
// chart calls the rows of shared_chart, whose values (delays, captures) are then constants the
// compiler folds into the code.
template <class Chart, class Rows = typename Chart::row_types>
inline constexpr bool is_shared_chart = false;
template <class Chart, class... Rows>
inline constexpr bool is_shared_chart<Chart, type_list<Rows...>> =
    is_chart_ref<Chart> || (all_true({(std::is_empty_v<Rows> && std::is_default_constructible_v<Rows>)...}) &&
                            std::is_default_constructible_v<Chart>);
template <class Chart>
inline constexpr Chart shared_chart{};

// The entry times of a chart without timeouts: none, and unlike std::array<duration, 0>, no
// byte. (No index is ever valid; operator[] exists for code that loops over zero slots.)
struct no_timeout_slots {
    static constexpr std::size_t size() { return 0; }
    constexpr duration* begin() { return nullptr; }
    constexpr duration* end() { return nullptr; }
    constexpr duration const* begin() const { return nullptr; }
    constexpr duration const* end() const { return nullptr; }
    constexpr duration& operator[](std::size_t) const { return unused; }

private:
    static inline duration unused{};
};
template <std::size_t Slots>
using timeout_slots = std::conditional_t<Slots == 0, no_timeout_slots, std::array<duration, Slots>>;

// A member handed out by reference (the context, the observer): no space when T is empty, and
// otherwise T whole. A [[no_unique_address]] T itself could lend its tail padding to the next
// members, and bytes copied over the reference (std::memcpy of a trivially copyable object)
// would then overwrite them.
template <class T, bool Empty = std::is_empty_v<T>>
struct whole {
    T value;
};
template <class T>
struct whole<T, true> {
    [[no_unique_address]] T value;
};

// The capacity of the deferred events of a machine: Policy::deferred_capacity for a chart that
// defers, and for any other no member read (a policy written before it existed still works).
template <class Policy, bool Defers>
inline constexpr std::size_t deferred_capacity_of = 0;
template <class Policy>
inline constexpr std::size_t deferred_capacity_of<Policy, true> = Policy::deferred_capacity;

// What a machine of a chart that defers keeps besides its deferred events: whether the
// microstep under way selected a deferring row, or fired another transition; whether a
// transition changed the configuration since the last round of retries; and how many deferred
// events the current round still retries.
struct deferral_state {
    bool requested = false;
    bool other_fired = false;
    bool changed = false;
    std::size_t retry = 0;
};
struct no_deferral {};

// The record of failures of a machine none of whose guards and actions can throw.
struct no_failure_slot {
    constexpr explicit operator bool() const { return false; }
    constexpr void reset() {}
    static std::exception_ptr get() { return nullptr; }
};

// The clock and its started flag of a machine that keeps no clock (machine_data::keeps_clock): two
// types, so that both members take no room.
struct no_clock {};
struct no_clock_start {};

template <class Backend, class Chart, class Policy, class Observer, class Queue>
class machine_data : public machine_base {
protected:
    using model = chart_model<std::remove_cv_t<Chart>>;
    using layout = chart_layout<model>;
    static constexpr auto const& tree = model::tree;
    static constexpr auto const& rows = model::rows;
    static constexpr int root = layout::root;
    static constexpr auto state_count = static_cast<std::size_t>(model::N);
    // Whether the machine has an observer. Without one no hook is called, and the back ends do
    // not even instantiate the calls.
    static constexpr bool observed = !std::is_same_v<Observer, no_observer>;

public:
    using chart_type = std::remove_cv_t<Chart>;
    using context_type = typename chart_type::context_type;
    using configuration_type = configuration<static_cast<std::size_t>(tree.slots), typename model::ordinal_type>;
    using event_types = typename model::events;
    using policy_type = Policy;
    using observer_type = Observer;
    /// How many raised events the internal queue holds: Policy::queue_capacity; 0 where no
    /// action of the chart can raise and it takes no done event or bsc::action_failed; 1 where
    /// only done events are queued, one at a time (detail/runtime/queue_for.hpp).
    static constexpr std::size_t queue_capacity = Queue::capacity();

protected:
    constexpr machine_data(Chart const& chart, context_type context, Observer observer)
        : chart_(stored_chart(chart)), observer_{std::move(observer)}, context_{std::move(context)} {}

    // The chart: the machine's copy, or, for a shared chart (is_shared_chart), the one every machine shares.
    constexpr chart_type const& chart() const {
        if constexpr (is_shared_chart<chart_type>)
            return shared_chart<chart_type>;
        else
            return chart_;
    }


    // Whether the chart sends delayed events (bsc::raise_after): its queue keeps them.
    static constexpr bool delays_events = requires(Queue & q) { q.release_due(duration{}); };
    // Whether the machine keeps the time of its last cycle. Timeouts count from it (their entry
    // times are the clock's), and timers and delayed events run on it, so that a caller's time
    // that goes backwards does not reach them; without any of these, only now() and the report
    // of a clock that went backwards read it, and a policy may leave it out (keep_clock).
    static constexpr bool keeps_clock = Policy::keep_clock || layout::timeout_slots > 0 || has_timers<context_type> ||
                                        delays_events;

    // The time of the last cycle: the clock, or zero for a machine that keeps none.
    constexpr duration cycle_time() const {
        if constexpr (keeps_clock)
            return clock_;
        else
            return duration{};
    }
    // Whether a cycle has run (the clock is the caller's time); false without a clock.
    constexpr bool clock_started() const {
        if constexpr (keeps_clock)
            return clock_started_;
        else
            return false;
    }
    // Sets the clock as if a cycle had run at `now` (started = false: as if none had). A machine
    // without a clock has nothing to set.
    constexpr void set_clock([[maybe_unused]] duration now, [[maybe_unused]] bool started) {
        if constexpr (keeps_clock) {
            clock_ = now;
            clock_started_ = started;
        }
    }

    // Whether the chart defers events (`/ bsc::defer`): then the machine keeps them.
    static constexpr bool defers = model::has_deferral;
    using completion = detail::completion<model>;
    // Whether a guard or action of the chart can throw (detail::chart_may_throw).
    static constexpr bool may_throw = chart_may_throw<model, Queue>();

    // Row Row of the chart. (Read from the base that holds it, named directly: row_at would
    // be one more function to instantiate per row.)
    template <int Row>
    constexpr auto const& row() const {
        using slot = row_slot<static_cast<std::size_t>(Row), typename model::template row_at<Row>>;
        return static_cast<slot const&>(chart().rows).row;
    }

    // Whether state s is active, read from the bytes; outermost first, so one pass suffices.
    constexpr std::array<bool, state_count> active_flags() const {
        std::array<bool, state_count> active{};
        active[0] = true;
        if constexpr (tree.slots > 0)
            for (std::size_t s = 1; s < state_count; ++s) {
                auto const p = static_cast<std::size_t>(tree.parent[s]);
                active[s] = active[p] && (tree.slot[p] < 0 ||
                                          config_.active[static_cast<std::size_t>(tree.slot[p])] == tree.ordinal[s]);
            }
        else
            for (std::size_t s = 1; s < state_count; ++s) active[s] = true;
        return active;
    }

    // True once a final child of the root is active (the driver's halted()).
    constexpr bool halted() const {
        if constexpr (layout::can_halt)
            return layout::final_root_children[config_.active[static_cast<std::size_t>(tree.slot[root])]];
        else
            return false;
    }

    // The back end this driver is the base of.
    constexpr Backend& backend() { return static_cast<Backend&>(*this); }
    constexpr Backend const& backend() const { return static_cast<Backend const&>(*this); }

    friend struct access;

protected:
    struct no_chart {};
    using stored_chart_type = std::conditional_t<is_shared_chart<chart_type>, no_chart, chart_type>;
    static constexpr stored_chart_type stored_chart(chart_type const& chart) {
        if constexpr (is_shared_chart<chart_type>)
            return (void)chart, no_chart{};
        else
            return chart;
    }
    // The members whose alignment is known to be large first, the context next to the bytes, so
    // that a small machine has no padding inside.
    [[no_unique_address]] stored_chart_type chart_;
    [[no_unique_address]] Queue queue_{};
    [[no_unique_address]] std::conditional_t<keeps_clock, duration, no_clock> clock_{};
    [[no_unique_address]] timeout_slots<static_cast<std::size_t>(layout::timeout_slots)> armed_{};  // entry times
    // The first failure of the current run that no transition took.
    [[no_unique_address]] std::conditional_t<may_throw, failure_slot, no_failure_slot> failure_;
    // The failure of the last run, for last_failure(), under a policy that does not rethrow.
    [[no_unique_address]] std::conditional_t<Policy::rethrow_failures || !may_throw, no_failure_slot, failure_slot>
        reported_;
    [[no_unique_address]] whole<Observer> observer_;
    [[no_unique_address]] whole<context_type> context_;
    configuration_type config_{};
    [[no_unique_address]] entering_flags<completion::parallel_count> entering_;
    // The events deferred (`/ bsc::defer`), oldest first, and the state of their retries.
    [[no_unique_address]] std::conditional_t<
        defers, event_queue<deferred_capacity_of<Policy, defers>, typename model::events>, no_deferral>
        deferred_;
    [[no_unique_address]] std::conditional_t<defers, deferral_state, no_deferral> deferral_;
    // The outcome of the last run (low bits), the mark of a run under way (running_bit) and
    // whether the run under way has kept a failure (failed_bit: failure_ holds it). An
    // enumeration and not a std::uint8_t: a store through an unsigned char may alias any object,
    // so the compiler would reload the context after every mark.
    enum class run_status : std::uint8_t {};
    static constexpr std::uint8_t running_bit = 0x80;
    static constexpr std::uint8_t failed_bit = 0x40;
    static constexpr std::uint8_t bits(run_status s) { return static_cast<std::uint8_t>(s); }
    run_status status_ = static_cast<run_status>(outcome::ignored);
    // A cycle has run: clock_ is the caller's time.
    [[no_unique_address]] std::conditional_t<keeps_clock, bool, no_clock_start> clock_started_{};
};

}  // namespace bsc::detail
// end include/bsc/detail/runtime/machine_data.hpp

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
// end include/bsc/detail/runtime/timeouts.hpp

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
// end include/bsc/detail/runtime/explorer_queries.hpp

namespace bsc::detail {

template <class Backend, class Chart, class Policy, class Observer, class Queue>
class run_control : public explorer_queries<Backend, Chart, Policy, Observer, Queue> {
    using base = explorer_queries<Backend, Chart, Policy, Observer, Queue>;

protected:
    using base::base;
    using typename base::model;
    using typename base::completion;
    using typename base::run_status;
    using base::may_throw;
    using base::running_bit;
    using base::failed_bit;
    using base::bits;
    using base::status_;
    using base::queue_;
    using base::failure_;
    using base::reported_;
    using base::entering_;

    // back end that says so (Backend::marks_running_lazily), from the first guard or transition
    // it is about to run (the back end calls mark_running() there): only guards, actions and
    // the observer can call the machine back, and a dispatch that runs none of them (an
    // ignored event) then never writes the mark.
    constexpr bool running() const {
        if constexpr (Policy::refuse_reentry)
            return (bits(status_) & running_bit) != 0;
        else
            return false;  // the caller's promise: never called back
    }
    constexpr void mark_running() {
        if constexpr (Policy::refuse_reentry) status_ = static_cast<run_status>(bits(status_) | running_bit);
    }
    // The outcome of the last run as kept (outcome::ignored if the policy keeps none).
    constexpr outcome kept_outcome() const { return static_cast<outcome>(bits(status_) & ~(running_bit | failed_bit)); }

    // Evaluates guard(args...) (true if it holds) or calls action(args...): what either throws
    // goes to fail(), and a guard that throws does not hold (SCXML: a condition that raises an
    // error is false). The callable and its arguments come separately, not as a lambda around
    // the call, and the try blocks are written out, not handed a handler as the table engine's
    // run_block is: two functions less to instantiate for every guard and action of the chart
    // (three: the arguments are forwarded with a cast, not with std::forward).
    template <class Guard, class... Args>
    constexpr bool test(Guard const& guard, Args&&... args) {
#if defined(__cpp_exceptions)
        try {
            return static_cast<bool>(guard(static_cast<Args&&>(args)...));
        } catch (...) {
            fail(std::current_exception());
            return false;
        }
#else
        return static_cast<bool>(guard(static_cast<Args&&>(args)...));
#endif
    }
    template <class Action, class... Args>
    constexpr void run(Action const& action, Args&&... args) {
#if defined(__cpp_exceptions)
        try {
            action(static_cast<Args&&>(args)...);
        } catch (...) {
            fail(std::current_exception());
        }
#else
        action(static_cast<Args&&>(args)...);
#endif
    }
    // The same, for code that knows the machine only by address (the table engine's thunks).
    failure_sink sink() {
        return {this, [](void* machine, std::exception_ptr error) {
                    static_cast<run_control*>(machine)->fail(std::move(error));
                }};
    }

    // Whether the chart takes bsc::action_failed: then failures go on the internal queue.
    static constexpr bool takes_failures = model::template trigger_of<action_failed>::value >= 0;

    // A guard or action threw: raise bsc::action_failed if the chart takes it (and the queue
    // has room), else keep it for the caller. (Where nothing can throw, nothing gets here: a
    // noexcept function that throws has already ended the program.)
    // (noexcept: what could throw here is recording a failure, an allocation; the program then
    // ends, as it would if a destructor threw while unwinding.)
    void fail(std::exception_ptr error) noexcept {
        if constexpr (may_throw) {
            if constexpr (takes_failures)
                if (queue_(action_failed{error})) return;
            keep_failure(std::move(error));
        } else {
            (void)error;
            std::terminate();
        }
    }
    void keep_failure(std::exception_ptr error) noexcept {
        if constexpr (may_throw) {
            failure_.keep(std::move(error));
            status_ = static_cast<run_status>(bits(status_) | failed_bit);
        } else {
            (void)error;
        }
    }

    // The end of a run, the machine consistent and its outputs committed: records the outcome
    // (which ends the run), and then rethrows a failure no transition took, or reports it as
    // outcome::failed.
    constexpr outcome end_run(outcome result) {
        // (A test of the status byte, not of failure_: where every guard and action of the run
        // is inlined and cannot throw, the compiler sees that nothing set the bit, and the test
        // is gone; see start_without_failure.)
        if constexpr (may_throw)
            if ((bits(status_) & failed_bit) != 0) [[unlikely]]
                return failed_run(result);
        return record(result);  // where nothing can throw nothing can have failed: no test
    }
    outcome failed_run(outcome result) {
        // (Cleared here too: a policy that keeps no outcome has record() write nothing.)
        status_ = static_cast<run_status>(bits(status_) & ~failed_bit);
        if constexpr (Policy::rethrow_failures) {
            record(result);
            std::rethrow_exception(failure_.take());
        } else {
            report_failure(failure_.take());
            return record(outcome::failed);
        }
    }
    // (noexcept, as fail(): keeping a failure allocates, and running out of memory there ends
    // the program rather than leave the machine marked running for good.)
    void report_failure(std::exception_ptr error) noexcept {
        reported_.reset();
        reported_.keep(std::move(error));
    }

    // A dispatch starts with failed_bit clear: every end of a run clears it (record,
    // end_run_by_exception) and only a run sets it, inside the running mark, which a dispatch
    // has just found clear. Said to the compiler, so that where every guard and action of the
    // run is inlined and cannot throw it sees that nothing set the bit, and end_run's test is
    // gone. GCC takes it as a range it may assume (it follows a range through the bit tests);
    // Clang, which drops an assumption at the first join of paths, and any compiler not known
    // to follow one (BSC_DETAIL_ASSUMPTION_SURVIVES_JOINS, detail/config.hpp), as a store of the
    // cleared byte, which merges with the running mark or the recorded outcome. (Only where
    // the running mark is kept: a policy without it never reads the byte at the start.) A
    // machine assigned to from inside its own run loses its running mark mid-run and breaks
    // this, as it breaks run to completion: docs/semantics.md, "Reentrancy", says not to.
    constexpr void start_without_failure() {
        if constexpr (may_throw && Policy::refuse_reentry) {
#if BSC_DETAIL_ASSUMPTION_SURVIVES_JOINS
            detail::assume(bits(status_) < failed_bit);
#else
            status_ = static_cast<run_status>(bits(status_) & ~failed_bit);
#endif
        }
    }

    // A run starts with the queue idle (event_queue.hpp, assume_idle): said to the optimiser.
    // It holds unless the machine is called back from inside its own run under a policy that
    // does not refuse it, or copied, assigned to or destroyed there (docs/semantics.md,
    // "Reentrancy"); builds without NDEBUG check it instead.
    constexpr void assume_idle_queue() const {
        if constexpr (requires { assume_idle(queue_); }) assume_idle(queue_);
    }

    // The outcome of a dispatch that ran no guard, action or observer: recorded, and returned.
    constexpr outcome record(outcome result) {
        if constexpr (Policy::keep_last_outcome || Policy::refuse_reentry) status_ = static_cast<run_status>(result);
        return result;
    }

    // Runs the body of a dispatch, a cycle or the construction, whose caller records the
    // outcome it returns (record() ends the run). If the body ends by an exception instead (a
    // rethrown failure, a throwing observer), the run ends here and the last outcome stays.
    // (A try block and not an object whose destructor ends the run: the object would have to
    // live on the stack of every dispatch.)
    template <class Body>
    BSC_DETAIL_ALWAYS_INLINE constexpr outcome run_to_end(Body&& body) {
#if defined(__cpp_exceptions)
        try {
            return body();
        } catch (...) {
            end_run_by_exception();
            throw;
        }
#else
        return body();
#endif
    }
    constexpr void end_run_by_exception() {
        // A failure the run kept goes with it: the exception that ended the run is what the
        // caller sees.
        if constexpr (may_throw) failure_.reset();
        queue_.clear();  // and what it had raised: nothing leaks into the next run
        queue_.clear_overflow();
        status_ = static_cast<run_status>(bits(status_) & ~(running_bit | failed_bit));
        if constexpr (completion::parallel_count > 0) entering_ = {};  // the run is over, whatever it was entering
    }

    friend struct access;
};

}  // namespace bsc::detail
// end include/bsc/detail/runtime/run_control.hpp

namespace bsc::detail {

template <class Backend, class Chart, class Policy, class Observer, class Queue>
class deferral : public run_control<Backend, Chart, Policy, Observer, Queue> {
    using base = run_control<Backend, Chart, Policy, Observer, Queue>;

protected:
    using base::base;
    using typename base::model;
    using base::defers;
    using base::deferral_;
    using base::deferred_;
    using base::backend;
    using base::keep_failure;

    // A deferring row was selected: its event is kept at the end of the microstep, unless
    // another transition fired in it.
    constexpr void deferral_selected() {
        if constexpr (defers) deferral_.requested = true;
    }
    // A transition that does not defer fired; `changes`: it has a target.
    constexpr void transition_fired(bool changes) {
        if constexpr (defers) {
            deferral_.other_fired = true;
            if (changes) deferral_.changed = true;
        } else {
            (void)changes;
        }
    }

    // Fires the transitions an event (not the eventless pseudo-event) enables where the chart
    // defers, and keeps the event if only deferring rows took it. (Elsewhere the callers go
    // straight to the back end's fire, without a function between to instantiate per event.)
    template <int Trigger, class E>
    constexpr bool fire_or_defer(E const& e) {
        deferral_.requested = false;
        deferral_.other_fired = false;
        bool const fired = backend().template fire<Trigger>(e);
        if (deferral_.requested && !deferral_.other_fired) (void)deferred_(e);
        return fired;
    }

    // Processes one deferred event again, if a round of retries is under way, or if a
    // transition has changed the configuration since the last round (which starts a round over
    // every event kept, in the order they came). True if it processed one.
    constexpr bool retry_deferred() {
        if constexpr (defers) {
            if (deferral_.retry == 0 && deferral_.changed) {
                deferral_.changed = false;
                deferral_.retry = deferred_.size();
            }
            if (deferral_.retry == 0) return false;
            --deferral_.retry;
            deferred_.pop([&](auto const& ev) { fire_queued(ev); });
            return true;
        } else {
            return false;
        }
    }

    // Fires the transitions an event taken from the queue or the deferred events enables,
    // without settling; a failure that no transition takes is kept for the caller.
    template <class E>
    constexpr void fire_queued(E const& e) {
        constexpr int trigger = model::template trigger_of<E>::value;
        bool fired = false;
        if constexpr (defers)
            fired = fire_or_defer<trigger>(e);
        else
            fired = backend().template fire<trigger>(e);
        if constexpr (std::is_same_v<E, action_failed>)
            if (!fired) keep_failure(e.error);  // raised, but no transition takes it here
    }
};

}  // namespace bsc::detail
// end include/bsc/detail/runtime/deferral.hpp

namespace bsc::detail {

template <class Backend, class Chart, class Policy, class Observer, class Queue>
class done_raising : public deferral<Backend, Chart, Policy, Observer, Queue> {
    using base = deferral<Backend, Chart, Policy, Observer, Queue>;

protected:
    using base::base;
    using typename base::model;
    using typename base::layout;
    using typename base::completion;
    using base::tree;
    using base::root;
    using base::state_count;
    using base::config_;
    using base::queue_;
    using base::entering_;
    using base::backend;
    using base::halted;

    // After the entry actions of final state f: raises done for its parent, and for the
    // parallel state above the parent if every region of it is now in a final state (SCXML's
    // enterStates). A final child of the root raises nothing: the machine halts.
    constexpr void entered_final(int f) {
        if constexpr (completion::raises) {
            int const p = tree.parent[static_cast<std::size_t>(f)];
            if (p == root) return;
            raise_done(p);
            int const g = tree.parent[static_cast<std::size_t>(p)];
            if (tree.kinds[static_cast<std::size_t>(g)] == kind::parallel && !entering(g) && in_final(g)) raise_done(g);
        } else {
            (void)f;
        }
    }

    // The back end is about to enter the regions of parallel state g. Until it has entered them
    // all (regions_entered), a final state entered in a region does not look at the regions
    // after its own, which are not entered yet.
    constexpr void regions_entering(int g) {
        if constexpr (completion::parallel_count > 0) {
            int const n = completion::parallel_number[static_cast<std::size_t>(g)];
            if (n >= 0) entering_.flag[static_cast<std::size_t>(n)] = true;
        } else {
            (void)g;
        }
    }
    // The back end has entered every region of parallel state g: done for g is raised if they are
    // all final and the last was entered through a final state of its own (a composite region),
    // where SCXML raises it, after the last final state entered.
    constexpr void regions_entered(int g) {
        if constexpr (completion::parallel_count > 0) {
            int const n = completion::parallel_number[static_cast<std::size_t>(g)];
            if (n >= 0) {
                entering_.flag[static_cast<std::size_t>(n)] = false;
                if (tree.kinds[static_cast<std::size_t>(last_child(g))] == kind::composite && in_final(g))
                    raise_done(g);
            }
        } else {
            (void)g;
        }
    }

    // Runs the exit actions of every active state, innermost first, when the machine halts
    // (SCXML's exitInterpreter).
    constexpr void halt_if_final() {
        if constexpr (layout::can_halt)
            if (halted()) {
                backend().exit_all();
                queue_.clear();
            }
    }

private:
    constexpr bool entering(int g) const {
        if constexpr (completion::parallel_count > 0) {
            int const n = completion::parallel_number[static_cast<std::size_t>(g)];
            return n >= 0 && entering_.flag[static_cast<std::size_t>(n)];
        } else {
            return (void)g, false;
        }
    }
    static constexpr int last_child(int s) {
        int last = tree.first_child[static_cast<std::size_t>(s)];
        while (tree.next_sibling[static_cast<std::size_t>(last)] >= 0)
            last = tree.next_sibling[static_cast<std::size_t>(last)];
        return last;
    }
    // SCXML's isInFinalState: a composite whose active child is final, a parallel state all of
    // whose regions are.
    constexpr bool in_final(int s) const {
        auto const i = static_cast<std::size_t>(s);
        if (tree.kinds[i] == kind::composite) {
            auto const ordinal = config_.active[static_cast<std::size_t>(tree.slot[i])];
            for (int c = tree.first_child[i]; c >= 0; c = tree.next_sibling[static_cast<std::size_t>(c)])
                if (tree.ordinal[static_cast<std::size_t>(c)] == ordinal)
                    return tree.kinds[static_cast<std::size_t>(c)] == kind::final_state;
            return false;
        }
        if (tree.kinds[i] == kind::parallel) {
            for (int c = tree.first_child[i]; c >= 0; c = tree.next_sibling[static_cast<std::size_t>(c)])
                if (!in_final(c)) return false;
            return true;
        }
        return false;
    }
    // Queues done<S> for state s, if a row takes it.
    constexpr void raise_done(int s) {
        // clang-format off
        [&]<std::size_t... S>(std::index_sequence<S...>) {
            if constexpr (state_count <= max_fold)
                (void)((s == static_cast<int>(S) ? (raise_done_of<S>(), true) : false) || ...);
            else  // (a list: detail::max_fold)
                [[maybe_unused]] bool const raised[] = {(s == static_cast<int>(S) ? (raise_done_of<S>(), true) : false)...};
        }(std::make_index_sequence<state_count>{});
        // clang-format on
    }
    template <std::size_t S>
    constexpr void raise_done_of() {
        if constexpr (completion::trigger[S] >= 0)
            (void)queue_(done<typename model::template tag_at<static_cast<int>(S)>>{});
    }
};

}  // namespace bsc::detail
// end include/bsc/detail/runtime/done_raising.hpp

namespace bsc::detail {

template <class Backend, class Chart, class Policy, class Observer, class Queue>
class settling : public done_raising<Backend, Chart, Policy, Observer, Queue> {
    using base = done_raising<Backend, Chart, Policy, Observer, Queue>;

protected:
    using base::base;
    using typename base::model;
    using typename base::layout;
    using base::observed;
    using base::defers;
    using base::queue_;
    using base::deferral_;
    using base::deferred_;
    using base::context_;
    using base::observer_;
    using base::backend;
    using base::running;
    using base::mark_running;
    using base::start_without_failure;
    using base::assume_idle_queue;
    using base::record;
    using base::end_run;
    using base::end_run_by_exception;
    using base::fire_or_defer;
    using base::fire_queued;
    using base::retry_deferred;
    using base::halt_if_final;
    using base::halted;

    template <int Trigger, class E>
    constexpr outcome process(E const& e) {
        if (running()) return outcome::reentrant;
        start_without_failure();
        if (halted()) return record(outcome::halted);
        assume_idle_queue();
        if (!backend_hooks::marks_running_lazily<Backend> || observed) mark_running();
        // (As run_to_end, written out: a lambda holding the whole dispatch might not be inlined,
        // and a function for the body would be one more to instantiate per event type.)
        outcome settled = outcome::ignored;
#if defined(__cpp_exceptions)
        try {
#endif
            if constexpr (observed) notify<model, Observer>::dispatching(observer_.value, e);
            latch_inputs(context_.value);
            bool fired = false;
            if constexpr (defers)
                fired = this->template fire_or_defer<Trigger>(e);
            else
                fired = backend().template fire_dispatched<Trigger>(e);
            settled = finish(fired);
            commit_outputs(context_.value);
#if defined(__cpp_exceptions)
        } catch (...) {
            end_run_by_exception();
            throw;
        }
#endif
        return end_run(settled);
    }

    // The components' turns in a cycle: a component takes its turn if it was active when the
    // cycle began and still is (an earlier component may have left it); one entered during
    // the cycle waits for the next. Returns the number of transitions fired.
    constexpr int run_components() { return run_components(std::make_index_sequence<layout::components.size()>{}); }
    // (A function of its own and not a lambda: the flags and the count are then its locals, in
    // registers, not captures that every component's stores might overwrite, reloaded after each.)
    template <std::size_t... I>
    constexpr int run_components(std::index_sequence<I...>) {
        constexpr auto const& components = layout::components;
        bool const active_at_start[] = {backend().template is_active<components[I]>()...};
        int fired = 0;
        ((fired += active_at_start[I] && backend().template is_active<components[I]>() &&
                   backend().template component_step<components[I]>()),
         ...);
        return fired;
    }

    // Settles the machine after a microstep: eventless transitions until none is enabled,
    // then the raised events one by one, each followed by its eventless transitions. Under a
    // scan policy eventless transitions are left to step(), and only raised events are processed.
    constexpr outcome finish(bool consumed) {
        if constexpr (!Policy::settle_eventless) return drain_queue(consumed);
        // The common case, kept inline: nothing raised, and no eventless transition to try.
        if constexpr (!layout::has_trigger(eventless_id) && !defers)
            if (queue_.empty() && !queue_.overflowed() && !(layout::can_halt && halted()))
                return consumed ? outcome::consumed : outcome::ignored;
        return settle(consumed);
    }

    constexpr outcome settle(bool consumed) {
        std::size_t internal_events = 0;
        for (;;) {
            if constexpr (layout::has_trigger(eventless_id)) {
                // Up to max_eventless_steps transitions settle; one more means the chart cycles.
                for (std::size_t steps = 0; !halted() && backend().template fire<eventless_id>(eventless{});)
                    if (++steps > Policy::max_eventless_steps) return abandon();
            }
            if (halted()) break;
            if (queue_.empty()) {
                // Then the deferred events, one at a time, each followed by its eventless
                // transitions and what it raises.
                if constexpr (defers) {
                    if (deferral_.retry > 0 || deferral_.changed) {
                        if (++internal_events > Policy::max_internal_events) return abandon();
                        if (retry_deferred()) continue;
                    }
                }
                break;
            }
            if (++internal_events > Policy::max_internal_events) return abandon();
            queue_.pop([&](auto const& ev) { this->fire_queued(ev); });
        }
        return settled(consumed);
    }

    // The raised events of a cycle, each one microstep and no eventless settling, so that no
    // component fires twice in a cycle.
    constexpr outcome drain_queue(bool consumed) {
        std::size_t n = 0;
        for (; !queue_.empty() && !halted();) {
            if (++n > Policy::max_internal_events) return abandon();
            queue_.pop([&](auto const& ev) { this->fire_queued(ev); });
        }
        if constexpr (defers) {
            // The deferred events a transition of this cycle released, each one microstep.
            while (!halted() && (deferral_.retry > 0 || deferral_.changed)) {
                if (++n > Policy::max_internal_events) return abandon();
                if (!retry_deferred()) break;
                for (; !queue_.empty() && !halted();) {
                    if (++n > Policy::max_internal_events) return abandon();
                    queue_.pop([&](auto const& ev) { this->fire_queued(ev); });
                }
            }
        }
        return settled(consumed);
    }

    // The end of every run that settles. The queue is empty here, but for a machine that has
    // halted (halt_if_final drops what it holds): it is rewound to its first slot, for
    // assume_idle_queue.
    constexpr outcome settled(bool consumed) {
        halt_if_final();
        if constexpr (requires { rewind_empty(queue_); }) rewind_empty(queue_);
        if constexpr (defers) {
            if (deferred_.overflowed()) {
                deferred_.clear_overflow();
                queue_.clear_overflow();
                return outcome::queue_overflow;
            }
        }
        if (queue_.overflowed()) {
            queue_.clear_overflow();
            return outcome::queue_overflow;
        }
        return consumed ? outcome::consumed : outcome::ignored;
    }

    constexpr outcome abandon() {
        queue_.clear();
        queue_.clear_overflow();
        if constexpr (defers) deferral_.retry = 0;  // the deferred events stay, for a later change
        return outcome::livelock;
    }
};

}  // namespace bsc::detail
// end include/bsc/detail/runtime/settling.hpp
// begin include/bsc/event_set.hpp
// bsc::event_set<Chart>: the events of a chart, named and numbered at compile time, so that a
// program can dispatch an event it received as text (an operator panel, a command line) or as a
// number (a field bus, a network message):
//
//   m.dispatch_by_name("ON_P");                      // outcome::unknown_event if no event is so named
//   m.dispatch_by_number(3, decode);                 // decode(std::type_identity<E>{}) builds E
//   bsc::event_set<decltype(chart)>::names           // {"ON_P", "OFF_P", ...}
//
// An event's name is its static member `name` when it has one (`static constexpr
// std::string_view name = "ON_P";`), otherwise its type's unqualified name (bsc::name_of). Its
// number is its position among the chart's events: the trigger events of the rows, in the order
// in which they first appear, without those the environment cannot send (detail::reserved_event:
// bsc::done<S> and bsc::action_failed, which only the machine raises, and bsc::any_event, a tag).
// So "done.state.S" and "*" name no event here, and dispatch_by_name answers
// outcome::unknown_event for them. Two events of a chart with the same name are an error
// (bsc::error::duplicate_event_name).

#include <array>
#include <cassert>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>


namespace bsc {

namespace detail {

// The first pair of events of Events with the same name, as positions (-1, -1 if none).
template <class... Events>
constexpr std::pair<int, int> duplicate_event_name() {
    constexpr std::array<std::string_view, sizeof...(Events)> names{event_name<Events>...};
    for (std::size_t i = 0; i < names.size(); ++i)
        for (std::size_t j = i + 1; j < names.size(); ++j)
            if (names[i] == names[j]) return {static_cast<int>(i), static_cast<int>(j)};
    return {-1, -1};
}

// The events a chart may take that the environment cannot send: bsc::done<S>, raised by the
// machine when S completes, bsc::action_failed, raised when one of its guards or actions throws,
// and bsc::any_event, the tag that a row on every event receives instead of the event. A dispatch
// of one from outside would fake what only the machine knows (bsc::error::event_not_dispatchable).
template <class E>
inline constexpr bool reserved_event = false;
template <class S>
inline constexpr bool reserved_event<done<S>> = true;
template <>
inline constexpr bool reserved_event<action_failed> = true;
template <>
inline constexpr bool reserved_event<any_event> = true;

// The events that can be sent by name or number: the chart's, without the reserved ones.
template <class Events>
struct sendable_events;
template <class... Events>
struct sendable_events<type_list<Events...>> {
    using type = concat_t<std::conditional_t<reserved_event<Events>, type_list<>, type_list<Events>>...>;
};

template <class Events>
struct event_set_of;
template <class... Events>
struct event_set_of<type_list<Events...>> {
    static constexpr std::size_t size = sizeof...(Events);
    static constexpr std::array<std::string_view, size> names{event_name<Events>...};

    // Calls f(std::type_identity<E>{}) for the event numbered `number` (< size).
    template <class F>
    static constexpr decltype(auto) visit(std::size_t number, F&& f) {
        assert(number < size);
        return visit_from<0>(number, f);
    }

private:
    template <std::size_t I, class F>
    static constexpr decltype(auto) visit_from(std::size_t number, F& f) {
        if constexpr (I + 1 < size) {
            if (number != I) return visit_from<I + 1>(number, f);
        }
        return f(std::type_identity<at<I, type_list<Events...>>>{});
    }
};

// Reports the first two events of the list with the same name; true either way, so that the
// static_assert that calls it adds no error of its own.
template <class... Events>
constexpr bool check_event_names(type_list<Events...>) {
    constexpr auto duplicate = duplicate_event_name<Events...>();
    if constexpr (duplicate.first >= 0)
        report<error::duplicate_event_name<at<static_cast<std::size_t>(duplicate.first), type_list<Events...>>,
                                           at<static_cast<std::size_t>(duplicate.second), type_list<Events...>>>>();
    return true;
}

}  // namespace detail

/// The events of Chart, named and numbered at compile time (see the top of this header).
/// Requirements: no two events of the chart have the same event_name.
template <class Chart>
struct event_set {
private:
    using model = detail::chart_model<std::remove_cv_t<Chart>>;
    using sendable = typename detail::sendable_events<typename model::events>::type;
    using base = detail::event_set_of<sendable>;
    static_assert(detail::check_event_names(sendable{}));

public:
    /// The events the environment may send, as a type list in number order: the chart's trigger
    /// events without bsc::done<S>, bsc::action_failed and bsc::any_event.
    using events = sendable;
    /// How many they are.
    static constexpr std::size_t size = base::size;
    /// Their names, by number.
    static constexpr std::array<std::string_view, size> names = base::names;

    /// The number of event E (bsc::error::not_an_event_of_the_chart if E is none of `events`).
    template <class E>
    static constexpr std::size_t number_of = [] {
        constexpr int n = detail::position_in<E, sendable>::value;
        if constexpr (n < 0) detail::report<error::not_an_event_of_the_chart<E>>();
        return static_cast<std::size_t>(n < 0 ? 0 : n);
    }();

    /// The number of the event called `name` (exactly, case included), or nothing.
    static constexpr std::optional<std::size_t> find(std::string_view name) {
        for (std::size_t i = 0; i < size; ++i)
            if (names[i] == name) return i;
        return std::nullopt;
    }

    /// Why `name` names no event: "no event of this chart is named 'X'; its events are A, B, C".
    static std::string unknown(std::string_view name) {
        std::string text = "no event of this chart is named '";
        text.append(name).append(size == 0 ? "'; it has no events" : "'; its events are ");
        for (std::size_t i = 0; i < size; ++i) text.append(i == 0 ? "" : ", ").append(names[i]);
        return text;
    }

    /// Calls f(std::type_identity<E>{}) for the event numbered `number`.
    /// Requirements: number < size.
    template <class F>
    static constexpr decltype(auto) visit(std::size_t number, F&& f) {
        return base::visit(number, f);
    }
};

}  // namespace bsc
// end include/bsc/event_set.hpp

namespace bsc::detail {

// The observer type a machine's deduction guide takes from its constructor's arguments
// (chart[, context[, observer]]): both back ends deduce through this one rule.
template <class... Arguments>
struct observer_argument {
    using type = no_observer;
};
template <class Context, class Observer>
struct observer_argument<Context, Observer> {
    using type = Observer;
};
template <class... Arguments>
using observer_argument_t = typename observer_argument<Arguments...>::type;

// The decoder of dispatch_by_name when none is given: builds no event (each is default-constructed).
struct no_decoder {};

template <class Backend, class Chart, class Policy, class Observer, class Queue>
class driver : public settling<Backend, Chart, Policy, Observer, Queue> {
    using base = settling<Backend, Chart, Policy, Observer, Queue>;

protected:
    using typename base::model;
    using typename base::layout;
    using base::tree;
    using base::root;
    using base::state_count;
    using base::observed;
    using base::keeps_clock;
    using base::delays_events;
    using base::may_throw;
    using base::config_;
    using base::queue_;
    using base::armed_;
    using base::context_;
    using base::observer_;
    using base::reported_;
    using base::clock_;
    using base::clock_started_;
    using base::backend;
    using base::active_flags;
    using base::cycle_time;
    using base::running;
    using base::mark_running;
    using base::kept_outcome;
    using base::record;
    using base::end_run;
    using base::run_to_end;
    using base::assume_idle_queue;
    using base::process;
    using base::finish;
    using base::drain_queue;
    using base::run_components;

public:
    using typename base::chart_type;
    using typename base::context_type;
    using typename base::configuration_type;
    using typename base::event_types;
    using typename base::policy_type;
    using typename base::observer_type;
    using base::queue_capacity;

    /// One BSC execution cycle at time `now` (the BSC paper's execution cycle): timers are
    /// updated, input channels latched; then each component (the root and every region of a
    /// parallel state), in document order, fires at most one eventless or timeout transition,
    /// its actions' writes visible at once to the components after it; events raised meanwhile
    /// are processed; output channels are committed. Components entered during the cycle first
    /// run in the next one. Time never runs backwards for the machine: an earlier `now` is
    /// reported and ignored.
    constexpr step_report step(duration now) {
        step_report report;
        if (running()) {
            report.status = outcome::reentrant;
            return report;
        }
        if (halted()) {
            report.status = record(outcome::halted);
            return report;
        }
        assume_idle_queue();
        mark_running();
        report.status = end_run(run_to_end([&] { return cycle(now, report); }));
        return report;
    }

private:
    // The cycle of step(now), which has marked the machine running; returns its outcome.
    // Out of line, so that step stays small enough to be inlined where it is called: GCC 12,
    // inlining the cycle into step instead, returns the report from a call, assembled in
    // memory by narrow stores and read back by wider loads, which stall (docs/performance.md,
    // rule "The cycle out of line").
    BSC_DETAIL_NOINLINE constexpr outcome cycle(duration now, step_report& report) {
        if constexpr (keeps_clock) {
            if (!clock_started_) {
                // The clock starts at the first cycle, wherever the caller's time starts; what was
                // armed before it (at construction, by a dispatch) counts from this cycle too.
                clock_started_ = true;
                clock_ = now;
                for (auto& armed : armed_) armed = now;
                if constexpr (delays_events) queue_.start_clock(now);
            } else if (now < clock_) {
                report.clock_went_backwards = true;  // the cycle runs at the clock's time
            } else {
                clock_ = now;
                if constexpr (delays_events) queue_.set_clock(now);
            }
            now = clock_;
        }
        notify<model, Observer>::cycle_begins(observer_.value, now);
        update_timers(context_.value, now);
        latch_inputs(context_.value);
        if constexpr (layout::has_trigger(any_condition)) report.transitions = run_components();
        // The delayed events due now, as raised events (bsc::raise_after).
        if constexpr (delays_events) queue_.release_due(now);
        outcome const drained = drain_queue(report.transitions > 0);
        commit_outputs(context_.value);
        notify<model, Observer>::cycle_ends(observer_.value);
        return drained;
    }

public:
    /// The time of the last cycle (the machine's clock; zero before the first cycle). A machine
    /// keeps a clock when its chart has timeouts, timers or delayed events, or when its policy
    /// says keep_clock (bsc::default_policy does; bsc::lean_policy does not).
    constexpr duration now() const {
        if constexpr (!keeps_clock) detail::report<error::clock_not_kept<Policy>>();
        return cycle_time();
    }

    /// Processes e to completion: the transitions it enables, then eventless transitions and
    /// raised events until none remain. Fails to compile if no transition handles E, or if E
    /// is an event the environment cannot send (bsc::done<S>, bsc::action_failed,
    /// bsc::any_event: bsc::error::event_not_dispatchable).
    template <class E>
    constexpr outcome dispatch(E const& e) {
        constexpr int trigger = model::template trigger_of<E>::value;
        if constexpr (reserved_event<E>) {
            detail::report<error::event_not_dispatchable<E>>();
            return outcome::ignored;
        } else if constexpr (trigger == -2) {
            detail::report<error::event_in_two_families<E>>();
            return outcome::ignored;
        } else if constexpr (trigger < 0) {
            detail::report<error::unhandled_event<E>>();
            return outcome::ignored;
        } else {
            return this->template process<trigger>(e);
        }
    }

    /// As dispatch(e), but an event type that no transition handles is accepted and ignored.
    template <class E>
    constexpr outcome dispatch(E const& e, allow_unhandled_t) {
        constexpr int trigger = model::template trigger_of<E>::value;
        if constexpr (reserved_event<E>) {
            detail::report<error::event_not_dispatchable<E>>();
            return outcome::ignored;
        } else if constexpr (trigger == -2) {
            detail::report<error::event_in_two_families<E>>();
            return outcome::ignored;
        } else if constexpr (trigger < 0) {
            if (running()) return outcome::ignored;  // inside a run: nothing to record
            if (!halted()) notify<model, Observer>::dispatching(observer_.value, e);
            return record(outcome::ignored);
        } else {
            return this->template process<trigger>(e);
        }
    }

    /// Dispatches the event of the chart called `name` (bsc::event_set: its static member
    /// `name`, or its type's name), built by `decode(std::type_identity<E>{})` when the decoder
    /// accepts that call and default-constructed otherwise. outcome::unknown_event, and nothing
    /// processed, if no event of the chart the environment may send is so named (so for
    /// "done.state.S" and "*": bsc::event_set leaves them out); outcome::reentrant, as dispatch,
    /// from inside one of the machine's own guards or actions.
    template <class Decode = no_decoder>
    constexpr outcome dispatch_by_name(std::string_view name, Decode&& decode = {}) {
        // An unknown name is a number past the last event: dispatch_by_number refuses both alike.
        return dispatch_by_number(event_set<Chart>::find(name).value_or(event_set<Chart>::size), decode);
    }

    /// As dispatch_by_name, for the event numbered `number` (bsc::event_set<Chart>::number_of).
    template <class Decode = no_decoder>
    constexpr outcome dispatch_by_number(std::size_t number, Decode&& decode = {}) {
        if (running()) return outcome::reentrant;
        if (number >= event_set<Chart>::size) return record(outcome::unknown_event);
        if constexpr (event_set<Chart>::size > 0)
            return event_set<Chart>::visit(number, [&]<class E>(std::type_identity<E> event) {
                if constexpr (std::is_invocable_r_v<E, Decode&, std::type_identity<E>>) {
                    return dispatch(static_cast<E>(decode(event)));
                } else if constexpr (std::is_default_constructible_v<E>) {
                    return dispatch(E{});
                } else {
                    detail::report<error::event_not_constructible<E>>();
                    return outcome::ignored;
                }
            });
        else
            return (void)decode, record(outcome::unknown_event);  // not reached: no number is below 0
    }

    /// True if state S is active.
    template <class S>
    constexpr bool is() const {
        constexpr int s = model::template index_of_state<S>::value;
        if constexpr (s < 0) {
            detail::report<error::queried_state_not_in_chart<S>>();
            return false;
        } else {
            return backend().template is_active<s>();
        }
    }

    /// True once a final child of the root is active: the machine processes nothing more.
    using base::halted;

    /// The names of the active states, outermost first, in document order.
    constexpr auto active_states() const {
        bsc::state_names<state_count> names;
        auto const active = active_flags();
        for (std::size_t s = 1; s < state_count; ++s)
            if (active[s]) names.push_back(state_names_of<model>[s]);
        return names;
    }

    /// The outcome of the last dispatch (or of construction).
    constexpr outcome last_outcome() const {
        if constexpr (!Policy::keep_last_outcome) detail::report<error::last_outcome_not_kept<Policy>>();
        return kept_outcome();
    }

    /// The exception of the last dispatch, cycle or construction whose outcome was
    /// outcome::failed (a policy whose rethrow_failures is false); null otherwise.
    std::exception_ptr last_failure() const {
        if constexpr (!Policy::keep_last_outcome) detail::report<error::last_outcome_not_kept<Policy>>();
        if constexpr (!Policy::rethrow_failures && may_throw)
            if (kept_outcome() == outcome::failed) return reported_.get();
        return nullptr;
    }

    /// The context as the environment sees it: const. Inputs are set through it (input::set is
    /// const: the plant's wire), outputs and variables read; only the chart's actions write
    /// outputs and variables (docs/api.md, "Data").
    constexpr context_type const& context() const { return context_.value; }
    constexpr configuration_type const& active_configuration() const { return config_; }
    constexpr Observer& observer() { return observer_.value; }
    constexpr Observer const& observer() const { return observer_.value; }

protected:
    // Checks the back end's side of the contract (detail/runtime/backend.hpp) where Backend is
    // complete: a back end without a hook fails here, naming machine_backend and the hook.
    constexpr driver(Chart const& chart, context_type context, Observer observer)
        : base(chart, std::move(context), std::move(observer)) {
        static_assert(machine_backend<Backend>, "a bsc back end supplies every hook of detail/runtime/backend.hpp");
    }


    // Enters the initial configuration (entry actions run) and settles eventless transitions.
    // Called by the back end's constructor, once the back end exists.
    constexpr void start() {
        mark_running();
        end_run(run_to_end([&] {
            if constexpr (tree.slots > 0) config_.active = layout::initial_bytes;
            latch_inputs(context_.value);
            backend().enter_initial();
            outcome const settled = finish(false);
            commit_outputs(context_.value);
            return settled;
        }));
    }

private:
    using driver_type = driver;  // what detail::access reaches a machine's data through
    friend struct access;
};

}  // namespace bsc::detail
// end include/bsc/detail/runtime/driver.hpp
// begin include/bsc/detail/runtime/queue_for.hpp
// The internal event queue a machine of a chart needs: none if no action of the chart can raise
// an event (detail::raised_by_chart) and the chart takes neither bsc::action_failed nor a done
// event; otherwise one that holds only the events that can be raised (detail::queued_events).

#include <type_traits>

// begin include/bsc/detail/runtime/delayed_events.hpp
// Delayed events to self (SCXML's <send delay> to the machine): bsc::raise_after(delay, e, id)
// schedules e, bsc::cancel_delayed(id) cancels what was scheduled under id. The internal queue
// of a chart that sends them (detail/runtime/queue_for.hpp) is a delaying_queue: the ring of raised
// events plus a fixed number of slots, each an event with the time it comes due. step(now)
// moves the events due into the ring, earliest first; a pending event does not belong to the
// state that sent it, so leaving that state does not cancel it.
//
// An event whose due time would lie past duration::max() (a delay near duration::max() from a
// clock already far from zero) never comes due: no step(now) can reach that time. It is not
// kept: schedule() accepts it (no overflow) and it takes no slot, so it is neither saved,
// restored nor explored, and there is nothing for its id to cancel. The same holds where the
// due time moves: when the clock starts (start_clock: what was sent before the first cycle
// counts from it) and when a saved machine resumes at a later time (bsc::resume_at,
// detail/state_bytes.hpp).

#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>


namespace bsc::detail {

template <std::size_t Capacity, std::size_t Slots, class Events>
class delaying_queue;

template <std::size_t Capacity, std::size_t Slots, class... Es>
class delaying_queue<Capacity, Slots, type_list<Es...>> : public event_queue<Capacity, type_list<Es...>> {
    using base = event_queue<Capacity, type_list<Es...>>;

public:
    using typename base::value_type;

    /// Schedules e to come due `delay` after the machine's clock (the time of its last cycle).
    /// False, and an overflow reported at the end of the run, if every slot is taken. An event
    /// due past duration::max() never comes due: it is not kept, and true is returned.
    template <class E>
    constexpr bool schedule(duration delay, E const& e, int id) noexcept(std::is_nothrow_copy_constructible_v<E>) {
        constexpr int as = queued_index<E>(type_list<Es...>{});
        if constexpr (as < 0) {
            detail::report<error::raised_event_not_in_chart<E>>();
            return false;
        } else {
            using F = at<static_cast<std::size_t>(as), type_list<Es...>>;
            if (shifted_past_max(clock_, delay)) return true;  // never due
            for (auto& s : slots_)
                if (!s.pending) {
                    s.pending = true;
                    s.due = clock_ + delay;
                    s.sent = sent_++;
                    s.id = id;
                    s.event = value_type{std::in_place_type<F>, event_as<F>(e)};
                    return true;
                }
            delayed_overflow_ = true;
            return false;
        }
    }

    /// Cancels every pending event scheduled under `id` (0, no id: none; bsc::cancel_delayed
    /// refuses it).
    constexpr void cancel(int id) noexcept {
        if (id == 0) return;
        for (auto& s : slots_)
            if (s.pending && s.id == id) s.pending = false;
    }

    // ---- for the machine -----------------------------------------------------------------------
    constexpr void set_clock(duration now) { clock_ = now; }
    // The machine's clock started at `now` (its first cycle): what was scheduled before counts
    // from there, as the timeouts armed before it do (until then a due time is the delay, the
    // clock being zero). An event then due past duration::max() never comes due: dropped.
    constexpr void start_clock(duration now) {
        for (auto& s : slots_)
            if (s.pending) {
                if (shifted_past_max(s.due, now))
                    s.pending = false;
                else
                    s.due = shifted(s.due, now);
            }
        clock_ = now;
    }
    // Moves the events due at `now` into the queue of raised events, earliest first, and among
    // those due at once in the order they were sent.
    constexpr void release_due(duration now) {
        for (;;) {
            slot* next = nullptr;
            for (auto& s : slots_)
                if (s.pending && s.due <= now &&
                    (next == nullptr || s.due < next->due || (s.due == next->due && s.sent < next->sent)))
                    next = &s;
            if (next == nullptr) return;
            next->pending = false;
            (void)this->push_item(next->event);
        }
    }
    // ---- what the queue holds between runs: for the retentive state and the explorer -------
    // The time of the machine's last cycle, as the queue knows it.
    constexpr duration clock() const { return clock_; }
    // The number of pending events.
    constexpr std::size_t scheduled() const {
        std::size_t n = 0;
        for (auto const& s : slots_) n += s.pending ? 1 : 0;
        return n;
    }
    // Calls f(due, id, item) for each pending event, in the order they were sent.
    template <class F>
    constexpr void for_each_scheduled(F&& f) const {
        std::uint32_t after = 0;
        bool first = true;
        for (;;) {
            slot const* next = nullptr;
            for (auto const& s : slots_)
                if (s.pending && (first || s.sent > after) && (next == nullptr || s.sent < next->sent)) next = &s;
            if (next == nullptr) return;
            f(next->due, next->id, next->event);
            after = next->sent;
            first = false;
        }
    }
    // Forgets every pending event and the count of events sent.
    constexpr void clear_scheduled() {
        for (auto& s : slots_) s.pending = false;
        sent_ = 0;
    }
    // Keeps an event due at `due`, as the last one sent. False if every slot is taken.
    constexpr bool put_scheduled(duration due, int id, value_type const& item) {
        for (auto& s : slots_)
            if (!s.pending) {
                s = slot{true, due, sent_++, id, item};
                return true;
            }
        return false;
    }
    static constexpr std::size_t slot_count() { return Slots; }

    constexpr bool overflowed() const { return base::overflowed() || delayed_overflow_; }
    constexpr void clear_overflow() {
        base::clear_overflow();
        delayed_overflow_ = false;
    }

private:
    struct slot {
        bool pending = false;
        duration due{};
        std::uint32_t sent = 0;  // (not "order": in a template, `s.order <` would name bsc::order)
        int id = 0;
        value_type event{};
    };
    std::array<slot, Slots> slots_{};
    duration clock_{};
    std::uint32_t sent_ = 0;
    bool delayed_overflow_ = false;
};

}  // namespace bsc::detail
// end include/bsc/detail/runtime/delayed_events.hpp

namespace bsc::detail {
// What the actions of the chart raise (detail::raised_by, one pass over the rows): type_list<>
// if none can raise (the machine then has no queue for them), raises_anything if one may raise
// whatever it likes, else the events the bsc::raise actions name.
// (A class, not an alias template: GCC 12 rejects the lambda in an alias template.)
template <class Model>
struct raised_by_chart {
    // clang-format off
    using type = typename decltype([]<class... Rows>(type_list<Rows...>) {
        using context = typename Model::chart_context;
        // (Entry and exit rows see no event; raised_by ignores it for them.)
        return std::type_identity<join_raised<decltype(raised_by<context, row_event_t<Rows>, raise_stand_in>(
            static_cast<decltype(Rows::action) const*>(nullptr)))...>>{};
    }(typename Model::row_types{}))::type;
    // clang-format on
};

// Whether an action of the chart sends or cancels delayed events (bsc::raise_after): then its
// queue keeps slots for them.
template <class Model>
constexpr bool chart_sends_delayed() {
    // clang-format off
    return []<class... Rows>(type_list<Rows...>) {
        return any_true({sends_delayed<std::remove_cv_t<decltype(Rows::action)>>..., false});
    }(typename Model::row_types{});
    // clang-format on
}

// The events the queue holds: those the actions raise, where each action says which
// (bsc::raise), and the done events and bsc::action_failed the chart takes (the machine raises
// those), in the chart's order; all the chart's events if an action may raise anything or
// raises an event the chart does not name (the queue then stores it as its family). Fewer
// events, fewer alternatives for the code that runs queued events to instantiate.
template <class Model, class Raised>
struct queued_events {
    using type = typename Model::events;
};
template <class Model, class... Raised>
struct queued_events<Model, type_list<Raised...>> {
    template <class E>
    static constexpr bool kept =
        is_done_event<E> || BSC_DETAIL_IS_SAME(E, action_failed) || position_in<E, type_list<Raised...>>::value >= 0;
    using type = std::conditional_t<(... && (position_in<Raised, typename Model::events>::value >= 0)),
                                    // clang-format off
                                    decltype([]<class... Es>(type_list<Es...>) {
                                        return concat_t<std::conditional_t<kept<Es>, type_list<Es>, type_list<>>...>{};
                                    }(typename Model::events{})),
                                    // clang-format on
                                    typename Model::events>;
};

// Whether E{} is a constant expression: a single_event_queue default-constructs its slots, and
// an empty event at each pop, where an event_queue constructs nothing but the events raised. An
// event whose default constructor is not constexpr would then keep a machine out of constant
// expressions, or run code of its own where none ran before.
template <class E>
concept constant_default = requires {
    typename std::bool_constant<(static_cast<void>(E{}), true)>;
};

// The queue of the events Events: a single_event_queue for one trivially copyable event type
// whose default construction is a constant, an event_queue otherwise.
template <std::size_t Capacity, class Events>
struct queue_of {
    using type = event_queue<Capacity, Events>;
};
template <std::size_t Capacity, class E>
    requires(Capacity > 0 && std::is_trivially_copyable_v<E> && constant_default<E>)
struct queue_of<Capacity, type_list<E>> {
    using type = single_event_queue<Capacity, E>;
};

// Whether a machine of the chart never holds more than one queued event: the queue holds done
// events only (no action raises, the chart takes no bsc::action_failed), no state is parallel
// (a microstep then enters at most one final state, and raises at most one done event), and no
// row is eventless, a timeout or deferring (an eventless transition is taken before the queued
// events, and could raise one more; a cycle's or a deferred event's microsteps alike). Every
// microstep is then followed by the one that takes what it raised, and a queue of one slot
// holds what a queue of the policy's capacity would: a completion costs a store and a load, not
// a ring's arithmetic (docs/performance.md, rule "A completion waits in one slot").
template <class Model, class Raised>
constexpr bool one_completion_at_a_time() {
    using layout = chart_layout<Model>;
    return std::is_same_v<Raised, type_list<>> && Model::template trigger_of<action_failed>::value < 0 &&
           !layout::has_parallel && !layout::has_trigger(any_condition) && !Model::has_deferral;
}

// The queue of raised events, worked out only for a chart that has one.
template <bool Needed, class Model, class Policy, class Raised>
struct raise_queue {
    using type = no_event_queue;
};
template <class Model, class Policy, class Raised>
struct raise_queue<true, Model, Policy, Raised> {
    static constexpr std::size_t capacity = Policy::queue_capacity > 0 && one_completion_at_a_time<Model, Raised>()
                                                ? 1
                                                : Policy::queue_capacity;
    using type = typename queue_of<capacity, typename queued_events<Model, Raised>::type>::type;
};

template <class Policy, bool Sends>
inline constexpr std::size_t delayed_capacity_of = 0;
template <class Policy>
inline constexpr std::size_t delayed_capacity_of<Policy, true> = Policy::delayed_capacity;

// The queue of a machine of the chart (either back end): with slots for delayed events if an
// action sends them; a bounded queue of the events the chart raises if an action can raise, or
// the chart takes bsc::action_failed or a bsc::done event (which the machine raises); otherwise
// none, and no test for raised events after a microstep.
template <class Chart, class Policy, class Model = chart_model<std::remove_cv_t<Chart>>,
          bool Delays = chart_sends_delayed<Model>(), class Raised = typename raised_by_chart<Model>::type>
using queue_for = std::conditional_t<
    Delays, delaying_queue<Policy::queue_capacity, delayed_capacity_of<Policy, Delays>, typename Model::events>,
    typename raise_queue<!std::is_same_v<Raised, type_list<>> ||
                             Model::template trigger_of<action_failed>::value >= 0 || completion<Model>::raises,
                         Model, Policy, Raised>::type>;
}  // namespace bsc::detail
// end include/bsc/detail/runtime/queue_for.hpp
// begin include/bsc/detail/runtime/rejected.hpp
// A machine declared on a chart that failed its checks (detail::rejected_chart): the chart's
// errors are already reported where the chart is declared, so the machine accepts whatever
// the program does with it and does nothing, instead of burying the chart's errors under
// errors of its own. Both back ends specialise their machine on it.

#include <cstddef>
#include <exception>
#include <type_traits>


namespace bsc::detail {

// Declared on `decltype(chart)` or on `bsc::chart_ref<chart>` (whose chart_type is the chart's
// type), alike: either way the chart's own errors are the only ones.
template <class Chart>
concept rejected = is_rejected_chart<std::remove_cv_t<Chart>> ||
    (is_chart_ref<std::remove_cv_t<Chart>>&& is_rejected_chart<typename std::remove_cv_t<Chart>::chart_type>);

template <class Chart>
class inert_machine {
public:
    using chart_type = std::remove_cv_t<Chart>;
    using context_type = typename chart_type::context_type;
    static constexpr std::size_t queue_capacity = 0;

    template <class... Arguments>
    constexpr explicit inert_machine(Arguments const&...) {}

    template <class... Arguments>
    constexpr outcome dispatch(Arguments const&...) {
        return outcome::ignored;
    }
    template <class... Arguments>
    constexpr outcome dispatch_by_name(Arguments const&...) {
        return outcome::ignored;
    }
    template <class... Arguments>
    constexpr outcome dispatch_by_number(Arguments const&...) {
        return outcome::ignored;
    }
    template <class... Arguments>
    constexpr auto step(Arguments const&...) {
        return 0;
    }
    template <class... States>
    constexpr bool is() const {
        return false;
    }
    constexpr bool halted() const { return false; }
    constexpr outcome last_outcome() const { return outcome::ignored; }
    std::exception_ptr last_failure() const { return nullptr; }
    constexpr duration now() const { return duration::zero(); }
    constexpr context_type const& context() const { return context_; }  // const, as a machine's

private:
    friend struct access;
    context_type context_{};
};

}  // namespace bsc::detail
// end include/bsc/detail/runtime/rejected.hpp
// begin include/bsc/detail/runtime/selection.hpp
// The transitions one microstep selects in parallel regions, and SCXML's conflict resolution
// over them (removeConflictingTransitions): both back ends select into this buffer and keep
// what resolve_conflicts keeps.

#include <array>
#include <cstddef>
#include <cstdint>

namespace bsc::detail {

// Selected transitions, in selection order, each once. What a number stands for (a chart
// row, a position in a trigger's transitions) is the back end's business.
template <std::size_t Capacity>
struct selection {
    std::array<std::uint16_t, Capacity> rows{};
    std::size_t size = 0;

    constexpr void add(std::size_t row) {
        for (std::size_t i = 0; i < size; ++i)
            if (rows[i] == row) return;
        rows[size++] = static_cast<std::uint16_t>(row);
    }
};

// Walking the selection in order, a transition whose exit set meets that of one kept earlier
// (conflict(later, earlier)) replaces it if it preempts it (its source lies below the
// earlier one's: preempts(later, earlier)), and is dropped otherwise.
template <std::size_t Capacity, class Conflict, class Preempts>
constexpr selection<Capacity> resolve_conflicts(selection<Capacity> const& selected, Conflict conflict,
                                                Preempts preempts) {
    selection<Capacity> kept;
    for (std::size_t i = 0; i < selected.size; ++i) {
        std::size_t const later = selected.rows[i];
        bool dropped = false;
        selection<Capacity> survivors;
        for (std::size_t j = 0; j < kept.size && !dropped; ++j) {
            std::size_t const earlier = kept.rows[j];
            if (!conflict(later, earlier))
                survivors.add(earlier);
            else if (!preempts(later, earlier))
                dropped = true;
        }
        if (!dropped) {
            survivors.add(later);
            kept = survivors;
        }
    }
    return kept;
}

}  // namespace bsc::detail
// end include/bsc/detail/runtime/selection.hpp


namespace bsc {

/// A running instance of a chart: its context, its active configuration and its internal
/// event queue. Construction enters the initial configuration; dispatch(e) processes one
/// event to completion; step(now) runs one BSC execution cycle. No heap, no virtual calls,
/// no RTTI, no exceptions; usable in constant expressions.
///
/// Requirements: `Chart` is a bsc::statechart (the type of a chart from bsc::make_chart, or
/// bsc::chart_ref); `Policy` is a bsc::machine_policy (bsc::default_policy, or a class derived from
/// it); `Observer` implements any subset of the hooks in observer.hpp.
template <statechart Chart, machine_policy Policy = default_policy, class Observer = no_observer>
class machine : public detail::driver<machine<Chart, Policy, Observer>, Chart, Policy, Observer,
                                      detail::queue_for<Chart, Policy>> {
    using base = detail::driver<machine, Chart, Policy, Observer, detail::queue_for<Chart, Policy>>;
    friend base;
    // The driver's layers that call the hooks (detail/runtime/backend.hpp), and backend_hooks,
    // through which the driver checks them.
    friend detail::backend_hooks;
    template <class, class, class, class, class>
    friend class detail::settling;
    template <class, class, class, class, class>
    friend class detail::deferral;
    template <class, class, class, class, class>
    friend class detail::done_raising;
    // A dispatch marks the machine running only where a guard or a transition is about to run
    // (guard_holds, fire_from), or, in a chart with parallel states, at each microstep: an
    // ignored event in a chart without parallel states writes nothing. (What a run takes after
    // its dispatched event, raised, deferred and eventless, is marked before its walk: fire().)
    static constexpr bool marks_running_lazily = true;
    using typename base::model;
    using plan = detail::plan<model>;
    static constexpr auto const& tree = model::tree;
    static constexpr auto const& rows = model::rows;
    static constexpr int root = plan::root;
    using base::context_;
    using base::config_;
    using base::queue_;
    using base::observer_;
    using notify = detail::notify<model, Observer>;
    using base::observed;

public:
    using typename base::context_type;
    /// Enters the initial configuration (entry actions run) and settles eventless transitions.
    /// (The chart parameter's type_identity leaves deduction to the guides below.)
    constexpr explicit machine(std::type_identity_t<Chart> const& chart, context_type context = {},
                               Observer observer = {})
        : base(chart, std::move(context), std::move(observer)) {
        this->start();
    }

private:
    // ---- the configuration -----------------------------------------------------------------
    template <int S>
    constexpr int active_child() const {
        if constexpr (tree.slot[S] >= 0) {
            return config_.active[static_cast<std::size_t>(tree.slot[S])];
        } else {
            return 0;  // the top has one child
        }
    }
    template <int S>
    constexpr void set_active_child(int ordinal) {
        if constexpr (tree.slot[S] >= 0)
            config_.active[static_cast<std::size_t>(tree.slot[S])] = static_cast<typename model::ordinal_type>(ordinal);
    }
    template <int S>
    constexpr bool is_active() const {
        if constexpr (S <= root) {
            return true;
        } else {
            constexpr int p = tree.parent[S];
            if constexpr (tree.slot[p] >= 0)
                return active_child<p>() == tree.ordinal[S] && is_active<p>();
            else
                return is_active<p>();
        }
    }

    // The event e as row Row sees it: its own event type, a family of it, or bsc::any_event.
    // (Where E is the row's own event, e is passed as it is: most rows of most charts, and no
    // conversion to instantiate.)
    template <int Row, class E>
    static constexpr bool sees_itself = BSC_DETAIL_IS_SAME(E,
                                                           detail::row_event_t<typename model::template row_at<Row>>);
    template <int Row, class E>
    static constexpr decltype(auto) seen_by(E const& e) {
        return detail::event_as<detail::row_event_t<typename model::template row_at<Row>>>(e);
    }

    constexpr void enter_initial() { enter_default<root>(); }
    // When the machine halts: every active state's exit actions, innermost first.
    constexpr void exit_all() { exit_below<0>(); }

    // ---- entry and exit ----------------------------------------------------------------
    // Whether entering (exiting) state s does anything: entry (exit) actions, the observer's
    // hook, and on entry a final state's record or the arming of its timeouts. Most states of
    // most charts do nothing, and are then not called at all: each call instantiates a function
    // per state and per path, which is most of what a chart costs to compile.
    static constexpr bool acts_on_entry(int s) {
        return observed || plan::count_rows(detail::row_kind::entry, s) > 0 ||
               tree.kinds[static_cast<std::size_t>(s)] == detail::kind::final_state ||
               plan::timeout_slot_count[static_cast<std::size_t>(s)] > 0;
    }
    static constexpr bool acts_on_exit(int s) { return observed || plan::count_rows(detail::row_kind::exit, s) > 0; }
    // Whether exiting the path from x up to, not including, d does anything.
    static constexpr bool acts_on_exit_up(int x, int d) {
        for (; x != d; x = tree.parent[static_cast<std::size_t>(x)])
            if (acts_on_exit(x)) return true;
        return false;
    }

    // The entry (or exit) actions of state S, in declaration order.
    template <detail::row_kind K, int S>
    constexpr void run_state_actions() {
        constexpr auto const& actions = plan::template rows_of<K, S>;
        // clang-format off
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            (this->run(this->template row<actions[I]>().action, context_.value, queue_), ...);
        }(std::make_index_sequence<actions.size()>{});
        // clang-format on
    }

    template <int S>
    constexpr void run_entry() {
        if constexpr (plan::count_rows(detail::row_kind::entry, S) > 0) run_state_actions<detail::row_kind::entry, S>();
        if constexpr (tree.kinds[S] == detail::kind::final_state) this->entered_final(S);
        if constexpr (plan::timeout_slot_count[S] > 0)
            this->arm_timeouts(plan::timeout_slot[S], plan::timeout_slot_count[S]);
        if constexpr (observed) notify::template entered<S>(observer_.value);
    }

    template <int S>
    constexpr void run_exit() {
        if constexpr (plan::count_rows(detail::row_kind::exit, S) > 0) run_state_actions<detail::row_kind::exit, S>();
        if constexpr (observed) notify::template exited<S>(observer_.value);
    }

    template <int S, class F>
    static constexpr void for_each_child(F&& f) {
        constexpr auto const& children = plan::template children<S>;
        // clang-format off
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            // (In order, as a list: a composite may have more children than a fold takes,
            // detail::max_fold.)
            [[maybe_unused]] int const visited[] = {((void)f(detail::int_c<children[I]>{}), 0)..., 0};
        }(std::make_index_sequence<children.size()>{});
        // clang-format on
    }

    // Calls f(child) for the active child of composite S if it is one of the children the
    // trigger makes relevant; returns false (without calling f) otherwise.
    template <int Trigger, int S, class F>
    BSC_DETAIL_WALK_INLINE constexpr bool with_relevant_active_child(F&& f) const {
        constexpr auto const& children = plan::template relevant_children<Trigger, S>;
        int const active = active_child<S>();
        // Where every child is relevant, the last needs no test: the byte always names a child.
        // The compiler then builds a jump table without a range check, and where the children
        // all do the same (a reaction every state of a flat chart has) finds nothing to test.
        // (Not below four children: GCC then turns three tests into a lookup of the next byte,
        // which an unconditional last arm prevents.)
        constexpr std::size_t n = children.size();
        constexpr bool every_child = n >= 4 && static_cast<int>(n) == tree.child_count[S];
        // clang-format off
        return [&]<std::size_t... I>(std::index_sequence<I...>) BSC_DETAIL_WALK_INLINE {
            if constexpr (n <= detail::max_fold) {
                return ((active == tree.ordinal[children[I]] || (every_child && I + 1 == n) ? (f(detail::int_c<children[I]>{}), true)
                                                                                              : false) ||
                        ...);
            } else {  // more children than a fold takes: a list of tests, one of which holds
                bool found = false;
                [[maybe_unused]] bool const tested[] = {
                    (active == tree.ordinal[children[I]] ? (f(detail::int_c<children[I]>{}), found = true) : false)...};
                return found;
            }
        }(std::make_index_sequence<n>{});
        // clang-format on
    }

    template <int S, class F>
    constexpr void with_active_child(F&& f) const {
        constexpr auto const& children = plan::template children<S>;
        detail::visit_index<static_cast<int>(children.size())>(
            active_child<S>(), [&](auto i) { f(detail::int_c<children[decltype(i)::value]>{}); });
    }

    // Enters S and its default (or history) completion.
    template <int S>
    constexpr void enter_default() {
        if constexpr (acts_on_entry(S)) run_entry<S>();
        if constexpr (has_content(S)) enter_content<S>();
    }

    // Whether entering S goes on below it (a basic or final state has nothing more to enter);
    // whether entering S by default does anything at all.
    static constexpr bool has_content(int s) {
        return tree.kinds[static_cast<std::size_t>(s)] == detail::kind::composite ||
               tree.kinds[static_cast<std::size_t>(s)] == detail::kind::parallel;
    }
    static constexpr bool acts_on_default_entry(int s) { return acts_on_entry(s) || has_content(s); }

    template <int S>
    constexpr void enter_content() {
        constexpr auto k = tree.kinds[S];
        if constexpr (k == detail::kind::composite) {
            constexpr auto h = tree.hist[S];
            if constexpr (h == detail::history::none) {
                // The initial transition: its actions, then its target, a child or deeper.
                constexpr int init = tree.initial[S];
                run_state_actions<detail::row_kind::initial, S>();
                if constexpr (tree.kinds[init] == detail::kind::history) {
                    enter_history<init>();
                } else if constexpr (tree.more_initial[S][0] >= 0) {
                    enter_toward_all<S, -1 - S>();  // initial<A, B>: one state in each region
                } else if constexpr (tree.initial_target[S] == init) {
                    set_active_child<S>(tree.ordinal[init]);
                    if constexpr (acts_on_default_entry(init)) enter_default<init>();
                } else {
                    enter_toward<S, tree.initial_target[S]>();
                }
            } else if constexpr (h == detail::history::shallow) {
                with_active_child<S>([&](auto c) { enter_default<decltype(c)::value>(); });
            } else {
                with_active_child<S>([&](auto c) { enter_restore<decltype(c)::value>(); });
            }
        } else if constexpr (k == detail::kind::parallel) {
            this->regions_entering(S);
            for_each_child<S>([&](auto c) { enter_default<decltype(c)::value>(); });
            this->regions_entered(S);
        }
    }

    // Enters history state H of composite P: P's remembered child (shallow) or remembered
    // sub-configuration (deep), or, if P has never been active, H's default transition.
    template <int H>
    constexpr void enter_history() {
        constexpr int p = tree.parent[H];
        if (plan::template never_active_byte<p>(active_child<p>())) {
            run_state_actions<detail::row_kind::initial, H>();
            constexpr int c = tree.initial[H];
            if constexpr (tree.initial_target[H] == c) {
                set_active_child<p>(tree.ordinal[c]);
                enter_default<c>();
            } else {
                enter_toward<p, tree.initial_target[H]>();
            }
        } else if constexpr (tree.hist[H] == detail::history::shallow) {
            with_active_child<p>([&](auto c) { enter_default<decltype(c)::value>(); });
        } else {
            with_active_child<p>([&](auto c) { enter_restore<decltype(c)::value>(); });
        }
    }

    // Deep history: re-enters S and the sub-configuration its bytes remember.
    template <int S>
    constexpr void enter_restore() {
        if constexpr (acts_on_entry(S)) run_entry<S>();
        constexpr auto k = tree.kinds[S];
        if constexpr (k == detail::kind::composite)
            with_active_child<S>([&](auto c) { enter_restore<decltype(c)::value>(); });
        else if constexpr (k == detail::kind::parallel) {
            this->regions_entering(S);
            for_each_child<S>([&](auto c) { enter_restore<decltype(c)::value>(); });
            this->regions_entered(S);
        }
    }

    // Enters, below the active state D, the path to Target (and parallel siblings on the way).
    template <int D, int Target>
    constexpr void enter_toward() {
        constexpr int c = tree.child_toward(D, Target);
        if constexpr (tree.kinds[D] == detail::kind::parallel) {
            // (A parallel D is never a transition's domain: it has just been entered.)
            this->regions_entering(D);
            for_each_child<D>([&](auto k) {
                if constexpr (decltype(k)::value == c)
                    enter_path_node<c, Target>();
                else
                    enter_default<decltype(k)::value>();
            });
            this->regions_entered(D);
        } else if constexpr (tree.kinds[c] == detail::kind::history) {
            enter_history<c>();  // D, its composite, has been entered: now its history
        } else {
            set_active_child<D>(tree.ordinal[c]);
            if constexpr (c != Target || acts_on_default_entry(c)) enter_path_node<c, Target>();
        }
    }
    template <int C, int Target>
    constexpr void enter_path_node() {
        if constexpr (acts_on_entry(C)) run_entry<C>();
        if constexpr (C == Target) {
            if constexpr (has_content(C)) enter_content<C>();
        } else {
            enter_toward<C, Target>();
        }
    }

    // Exits the active descendants of S, innermost first, in reverse document order.
    template <int S>
    constexpr void exit_below() {
        constexpr auto k = tree.kinds[S];
        if constexpr (k == detail::kind::composite || k == detail::kind::top) {
            with_active_child<S>([&](auto c) { exit_subtree<decltype(c)::value>(); });
        } else if constexpr (k == detail::kind::parallel) {
            constexpr auto const& children = plan::template children<S>;
            // clang-format off
            [&]<std::size_t... I>(std::index_sequence<I...>) {
                (exit_subtree<children[children.size() - 1 - I]>(), ...);
            }(std::make_index_sequence<children.size()>{});
            // clang-format on
        }
    }
    // Exits the active descendants of S, then S.
    template <int S>
    constexpr void exit_subtree() {
        if constexpr (has_content(S)) exit_below<S>();
        if constexpr (acts_on_exit(S)) run_exit<S>();
    }

    // Exits the known path from basic state X up to, not including, D.
    template <int X, int D>
    constexpr void exit_up() {
        if constexpr (X != D) {
            if constexpr (acts_on_exit(X)) run_exit<X>();
            if constexpr (acts_on_exit_up(tree.parent[X], D)) exit_up<tree.parent[X], D>();
        }
    }

    // ---- transitions -------------------------------------------------------------------
    // Whether the guard of row Row holds. (Called for guarded rows only: an unguarded row holds,
    // and a call would instantiate a function for nothing.)
    // A guard with bsc::in<S> is called with a view of the configuration bytes, whose tests are
    // resolved at compile time (detail/model/configuration_view.hpp: only the bytes between S
    // and its lowest common ancestor with the row's source, active while the guard is evaluated;
    // one compare for a child of another region); every other guard as g(context, event), as before.
    template <int Row, class E>
    constexpr bool guard_holds(E const& e) {
        static_assert(rows.guarded[Row]);
        if constexpr (!plan::has_parallel) this->mark_running();
        if constexpr (detail::tests_configuration<std::remove_cvref_t<decltype(this->template row<Row>().guard)>>)
            return guard_holds_in<Row>(e);
        else if constexpr (sees_itself<Row, E>)
            return this->test(this->template row<Row>().guard, std::as_const(context_.value), e);
        else
            return this->test(this->template row<Row>().guard, std::as_const(context_.value), seen_by<Row>(e));
    }
    template <int Row, class E>
    constexpr bool guard_holds_in(E const& e) {
        detail::configuration_view<model, rows.source[Row]> const active{configuration_bytes()};
        if constexpr (sees_itself<Row, E>)
            return this->test(this->template row<Row>().guard, std::as_const(context_.value), e, active);
        else
            return this->test(this->template row<Row>().guard, std::as_const(context_.value), seen_by<Row>(e), active);
    }
    constexpr typename model::ordinal_type const* configuration_bytes() const {
        if constexpr (tree.slots > 0)
            return config_.active.data();
        else
            return nullptr;  // no composite: no test reads a byte
    }

    template <int Row, class E>
    constexpr void run_action(E const& e) {
        if constexpr (rows.defers[Row]) {  // keeps the event (detail/runtime/deferral.hpp, fire_or_defer)
            if constexpr (observed)
                notify::template transition<Row>(observer_.value, this->template row<Row>(), seen_by<Row>(e));
            this->deferral_selected();
            return;
        } else if constexpr (base::defers) {
            this->transition_fired(rows.domain[Row] >= 0);
        }
        if constexpr (sees_itself<Row, E>) {
            if constexpr (observed) notify::template transition<Row>(observer_.value, this->template row<Row>(), e);
            if constexpr (!std::is_same_v<std::remove_cvref_t<decltype(this->template row<Row>().action)>,
                                          detail::no_action>)
                this->run(this->template row<Row>().action, context_.value, e, queue_);
        } else {
            if constexpr (observed)
                notify::template transition<Row>(observer_.value, this->template row<Row>(), seen_by<Row>(e));
            if constexpr (!std::is_same_v<std::remove_cvref_t<decltype(this->template row<Row>().action)>,
                                          detail::no_action>)
                this->run(this->template row<Row>().action, context_.value, seen_by<Row>(e), queue_);
        }
    }

    template <int Row>
    constexpr void run_entries() {
        constexpr int d = rows.domain[Row];
        if constexpr (d >= 0 && rows.several(Row))
            enter_toward_all<d, Row>();
        else if constexpr (d >= 0)
            enter_toward<d, rows.target[Row]>();
    }

    // ---- several targets: bsc::targets, bsc::initial<A, B> ------------------------------
    // A set of targets, by key: a row's (key >= 0), or the initial states of state s
    // (key -1 - s). Every target set is orthogonal (detail/checks/structure.hpp).
    static constexpr std::array<int, 4> target_set(int key) {
        return key >= 0 ? rows.targets_of(static_cast<std::size_t>(key))
                        : tree.initial_states(static_cast<std::size_t>(-1 - key));
    }
    // A target of the set below state s, -1 if none; whether s is one.
    static constexpr int target_below(int s, int key) {
        for (int t : target_set(key))
            if (t >= 0 && tree.contains(s, t)) return t;
        return -1;
    }
    static constexpr bool is_target(int s, int key) {
        for (int t : target_set(key))
            if (t == s) return true;
        return false;
    }
    // Enters, below the active state D, the paths to every target of the set: at a parallel
    // state, each region toward the targets it holds, the others by default.
    template <int D, int Key>
    constexpr void enter_toward_all() {
        if constexpr (tree.kinds[D] == detail::kind::parallel) {
            this->regions_entering(D);
            for_each_child<D>([&](auto k) {
                if constexpr (target_below(decltype(k)::value, Key) >= 0)
                    enter_path_all<decltype(k)::value, Key>();
                else
                    enter_default<decltype(k)::value>();
            });
            this->regions_entered(D);
        } else {
            constexpr int c = tree.child_toward(D, target_below(D, Key));
            if constexpr (tree.kinds[c] == detail::kind::history) {
                enter_history<c>();
            } else {
                set_active_child<D>(tree.ordinal[c]);
                enter_path_all<c, Key>();
            }
        }
    }
    template <int C, int Key>
    constexpr void enter_path_all() {
        if constexpr (acts_on_entry(C)) run_entry<C>();
        if constexpr (is_target(C, Key)) {
            if constexpr (has_content(C)) enter_content<C>();
        } else {
            enter_toward_all<C, Key>();
        }
    }

    // Fires a transition selected at basic state Leaf (or at a composite where the walk ends),
    // which no parallel state contains: the exit path is known, so exits, action and entries
    // are straight-line code.
    template <int Leaf, int Row, class E>
    constexpr void fire_from(E const& e) {
        if constexpr (!plan::has_parallel) this->mark_running();  // else select_and_fire has marked
        constexpr int d = rows.domain[Row];
        if constexpr (d >= 0 && acts_on_exit_up(Leaf, d)) exit_up<Leaf, d>();
        run_action<Row>(e);
        run_entries<Row>();
    }

    // The transitions selected in parallel regions, fired together after selection.
    struct no_selection {};  // for charts without parallel states
    using selection = detail::selection<static_cast<std::size_t>(plan::max_active_leaves())>;

    // A region-local trigger's selection: per component, 0 or 1 + the row's index in its
    // component_rows.
    struct component_selection {
        std::array<std::uint8_t, plan::components.size()> chosen{};
    };

    // Transitions of such a trigger fire where they are selected, as outside parallel states,
    // when no observer could see the order of exits and entries change.
    template <int Trigger>
    static constexpr bool fires_at_selection = plan::template fires_at_selection<Trigger> && !observed;

    template <int Trigger>
    using selection_for =
        std::conditional_t<!plan::has_parallel || fires_at_selection<Trigger>, no_selection,
                           std::conditional_t<plan::template region_local<Trigger>, component_selection, selection>>;

    template <int Leaf, int Trigger, int Row, class E, class Sel>
    BSC_DETAIL_WALK_INLINE constexpr bool try_row(E const& e, Sel& sel) {
        if constexpr (rows.guarded[Row])
            if (!guard_holds<Row>(e)) return false;
        if constexpr (!tree.under_parallel(Leaf) || fires_at_selection<Trigger>)
            fire_from<Leaf, Row>(e);
        else if constexpr (plan::template region_local<Trigger>)
            sel.chosen[static_cast<std::size_t>(plan::component_of[Leaf])] = static_cast<std::uint8_t>(
                plan::template component_code<Trigger, Row>);
        else
            sel.add(plan::template position_of<Trigger>(Row));
        return true;
    }

    // The candidates of basic state Leaf on the trigger, in order, until one is taken. (Leaf may
    // be a composite where the walk ends: walk_ends_at.)
    template <int Leaf, int Trigger, class E, class Sel>
    BSC_DETAIL_WALK_INLINE constexpr bool try_leaf(E const& e, Sel& sel) {
        constexpr auto const& candidates = plan::template candidates<Leaf, Trigger>;
        // clang-format off
        return [&]<std::size_t... I>(std::index_sequence<I...>) BSC_DETAIL_WALK_INLINE {
            return (try_row<Leaf, Trigger, candidates[I]>(e, sel) || ...);
        }(std::make_index_sequence<candidates.size()>{});
        // clang-format on
    }

    // Whether the states strictly below composite s can be left without a word: none is
    // parallel and none acts on exit.
    static constexpr bool quiet_below(int s) {
        for (int x = s + 1; tree.contains(s, x); ++x)
            if (tree.kinds[static_cast<std::size_t>(x)] == detail::kind::parallel || acts_on_exit(x)) return false;
        return true;
    }
    // Whether the walk for the trigger ends at composite s, as at a basic state: no state below
    // s takes the trigger by a row of its own, and leaving them does nothing, so which of them
    // is active does not matter (s's candidates are every basic state's below it, and firing
    // from s exits what acts). A dispatch then reads none of the bytes below s.
    template <int Trigger>
    static constexpr bool walk_ends_at(int s) {
        return tree.kinds[static_cast<std::size_t>(s)] == detail::kind::composite && !tree.under_parallel(s) &&
               plan::template no_source_below<Trigger>(s) && quiet_below(s);
    }

    // Walks the active configuration below S, visiting only states relevant to the trigger.
    // (A single candidate, or a single relevant child, the common cases, is reached without
    // the helper that expands several: a function less to instantiate for each.)
    template <int S, int Trigger, class E, class Sel>
    BSC_DETAIL_WALK_INLINE constexpr bool select(E const& e, Sel& sel) {
        constexpr auto k = tree.kinds[S];
        if constexpr (!plan::template relevant<Trigger>(S)) {
            return false;
        } else if constexpr (k == detail::kind::basic || k == detail::kind::final_state || walk_ends_at<Trigger>(S)) {
            constexpr auto const& candidates = plan::template candidates<S, Trigger>;
            if constexpr (candidates.size() == 1)
                return try_row<S, Trigger, candidates[0]>(e, sel);
            else
                return try_leaf<S, Trigger>(e, sel);
        } else if constexpr (k == detail::kind::parallel) {
            bool any = false;
            for_each_child<S>([&](auto c) { any = select<decltype(c)::value, Trigger>(e, sel) || any; });
            return any;
        } else if constexpr (constexpr auto const& children = plan::template relevant_children<Trigger, S>;
                             children.size() == 1) {
            if (active_child<S>() != tree.ordinal[children[0]]) return false;
            return select<children[0], Trigger>(e, sel);
        } else {
            bool any = false;
            with_relevant_active_child<Trigger, S>(
                [&](auto c) BSC_DETAIL_WALK_INLINE { any = select<decltype(c)::value, Trigger>(e, sel); });
            return any;
        }
    }

    template <int Trigger, class F>
    static constexpr void with_transition(int position, F&& f) {
        constexpr auto const& on_trigger = plan::template transitions<Trigger>;
        detail::visit_index<static_cast<int>(on_trigger.size())>(
            position, [&](auto i) { f(detail::int_c<on_trigger[decltype(i)::value]>{}); });
    }

    // SCXML: keep what conflict resolution keeps; then exit all, run the actions in order,
    // enter all.
    template <int Trigger, class E>
    constexpr void fire_selected(E const& e, selection const& sel) {
        constexpr auto const& on_trigger = plan::template transitions<Trigger>;
        selection const kept = detail::resolve_conflicts(
            sel,
            [](std::size_t later, std::size_t earlier) {
                return plan::conflict(on_trigger[later], on_trigger[earlier]);
            },
            [](std::size_t later, std::size_t earlier) {
                return plan::preempts(on_trigger[later], on_trigger[earlier]);
            });
        for (std::size_t i = kept.size; i-- > 0;)
            with_transition<Trigger>(kept.rows[i], [&](auto r) {
                constexpr int d = rows.domain[decltype(r)::value];
                if constexpr (d >= 0) exit_below<d>();
            });
        for (std::size_t i = 0; i < kept.size; ++i)
            with_transition<Trigger>(kept.rows[i], [&](auto r) { run_action<decltype(r)::value>(e); });
        for (std::size_t i = 0; i < kept.size; ++i)
            with_transition<Trigger>(kept.rows[i], [&](auto r) { run_entries<decltype(r)::value>(); });
    }

    // Calls f(row) for the row chosen in component C, if any.
    template <int Trigger, int C, class F>
    static constexpr void with_chosen(std::uint8_t code, F&& f) {
        constexpr auto const& chosen_from = plan::template component_rows<Trigger, C>;
        // clang-format off
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            (void)((code == I + 1 ? (f(detail::int_c<chosen_from[I]>{}), true) : false) || ...);
        }(std::make_index_sequence<chosen_from.size()>{});
        // clang-format on
    }

    // A region-local trigger's transitions: none conflicts with another, so all fire; the
    // components are disjoint and visited in document order, which is the order SCXML fires
    // them in.
    template <int Trigger, class E>
    constexpr void fire_components(E const& e, component_selection const& sel) {
        constexpr auto const& selecting = plan::template selecting_components<Trigger>;
        constexpr std::size_t n = selecting.size();
        // clang-format off
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            (with_chosen<Trigger, selecting[n - 1 - I]>(sel.chosen[static_cast<std::size_t>(selecting[n - 1 - I])], [&](auto r) {
                 constexpr int d = rows.domain[decltype(r)::value];
                 if constexpr (d >= 0)
                     exit_below<d>();
             }),
             ...);
            (with_chosen<Trigger, selecting[I]>(sel.chosen[static_cast<std::size_t>(selecting[I])],
                                            [&](auto r) { run_action<decltype(r)::value>(e); }),
             ...);
            (with_chosen<Trigger, selecting[I]>(sel.chosen[static_cast<std::size_t>(selecting[I])],
                                            [&](auto r) { run_entries<decltype(r)::value>(); }),
             ...);
        }(std::make_index_sequence<n>{});
        // clang-format on
    }

    // Selects and fires the transitions Trigger enables, without settling; true if a transition
    // fired. Flattened: the walk of the relevant states, the guards, exits, actions and entries
    // become one straight-line nest of switches for the trigger, whatever the compiler's
    // inlining budget for the function that dispatches (a dispatch of a parallel chart otherwise
    // ended up as calls of the walk's lambdas, which cost more than the walk).
    // (Marked running once, before the walk, where no parallel state marks each microstep: what
    // fire() takes, a raised, deferred or eventless event, comes within a run, where running
    // user code is likely; the walk's own marks (guard_holds, fire_from) then write what is
    // there. Marked only in each transition instead, the walk of a trigger that every state
    // takes alike, as fsm-benchmark's Large takes the event its exits raise, kept a switch on
    // the state for the mark alone: docs/performance.md, rule "Marked before a walk within a run".)
    template <int Trigger, class E>
    BSC_DETAIL_FLATTEN constexpr bool fire(E const& e) {
        if constexpr (!plan::has_parallel) this->mark_running();
        return select_and_fire<Trigger>(e);
    }
    // fire() for a dispatched event, marked only where a guard or transition runs: an ignored
    // event writes nothing.
    template <int Trigger, class E>
    BSC_DETAIL_FLATTEN constexpr bool fire_marking_lazily(E const& e) {
        return select_and_fire<Trigger>(e);
    }
    // fire() for a dispatched event. Where the dispatch has nothing to do after it but record
    // its outcome (no parallel states, nothing raised, no eventless transition or deferral to
    // settle, and a policy that records), it is flattened in line: the dispatch then records
    // the outcome where the transition ends and calls nothing (the call cost a frame, and a
    // mark of the running machine that the record overwrites). Elsewhere fire() is called: a
    // dispatch that records nothing ends in a jump to it, and one that settles, or a firing in
    // several regions, grows more in line than the call costs (docs/performance.md,
    // rule "Dispatched event fired in line where nothing follows").
    static constexpr bool dispatch_fires_in_line =
        !plan::has_parallel && (Policy::refuse_reentry || Policy::keep_last_outcome) &&
        std::is_same_v<detail::queue_for<Chart, Policy>, detail::no_event_queue> &&
        !plan::has_trigger(detail::eventless_id) && !base::defers;
    template <int Trigger, class E>
    BSC_DETAIL_WALK_INLINE constexpr bool fire_dispatched(E const& e) {
        if constexpr (dispatch_fires_in_line)
            return fire_in_line<Trigger>(e);
        else
            return fire_marking_lazily<Trigger>(e);
    }
    // (Flattened before it is put in line: GCC does not flatten what an always-inline function
    // brings into a flattened one, hence select_and_fire itself, not fire().)
    template <int Trigger, class E>
    BSC_DETAIL_FLATTEN BSC_DETAIL_ALWAYS_INLINE constexpr bool fire_in_line(E const& e) {
        return select_and_fire<Trigger>(e);
    }
    template <int Trigger, class E>
    constexpr bool select_and_fire(E const& e) {
        if constexpr (!plan::has_trigger(Trigger)) {
            return false;
        } else {
            // With parallel regions, several transitions may fire in one microstep: one mark
            // before them all costs less than one each.
            if constexpr (plan::has_parallel) this->mark_running();
            using sel_type = selection_for<Trigger>;
            sel_type sel;
            // From the root: the top above it has no byte and no transitions.
            bool const any = select<root, Trigger>(e, sel);
            if constexpr (std::is_same_v<sel_type, component_selection>) {
                if (any) fire_components<Trigger>(e, sel);
            } else if constexpr (std::is_same_v<sel_type, selection>) {
                if (sel.size > 0) fire_selected<Trigger>(e, sel);
            }
            return any;
        }
    }

    // ---- the BSC cycle -----------------------------------------------------------------
    template <int Row>
    constexpr bool condition_holds() {
        if constexpr (rows.trigger[Row] <= detail::timeout_trigger_id(0)) {
            if (!this->timeout_due(plan::row_timeout_slot[Row], this->template row<Row>().trigger_value.delay))
                return false;
        }
        if constexpr (rows.guarded[Row])
            return guard_holds<Row>(eventless{});
        else
            return true;
    }

    // Condition-driven row Row, whose condition holds, fires; a timeout that competes with
    // others of its state by due time (layout.hpp, competes_by_due_time) goes through
    // fire_first_due, every other row straight to fire_condition.
    template <int Row>
    constexpr void fire_candidate() {
        if constexpr (plan::competes_by_due_time(Row))
            fire_first_due<Row>();
        else
            fire_condition<Row>();
    }

    // Timeout row Row, due, fires; but if a timeout row of its source declared after it is due
    // too, came due first (plan.hpp, later_timeouts; detail::came_due_first) and its guard
    // holds, that one fires instead: of a state's timeouts due at once, the first to come due.
    template <int Row>
    constexpr void fire_first_due() {
        constexpr auto const& later = plan::template later_timeouts<Row>;
        if constexpr (later.size() == 0) {
            fire_condition<Row>();
        } else {
            std::size_t first = 0;  // 0: Row itself, k: later[k - 1]
            int slot = plan::row_timeout_slot[Row];
            duration delay = this->template row<Row>().trigger_value.delay;
            // clang-format off
            [&]<std::size_t... K>(std::index_sequence<K...>) {
                (
                    [&] {
                        constexpr int u = later[K];
                        constexpr int u_slot = plan::row_timeout_slot[u];
                        duration const u_delay = this->template row<u>().trigger_value.delay;
                        if (!this->timeout_due(u_slot, u_delay) || !this->came_due_before(u_slot, u_delay, slot, delay)) return;
                        if constexpr (rows.guarded[u])
                            if (!guard_holds<u>(eventless{})) return;
                        first = K + 1;
                        slot = u_slot;
                        delay = u_delay;
                    }(),
                    ...);
                if (first == 0)
                    fire_condition<Row>();
                else
                    (void)((first == K + 1 ? (fire_condition<later[K]>(), true) : false) || ...);
            }(std::make_index_sequence<later.size()>{});
            // clang-format on
        }
    }

    template <int Row>
    constexpr void fire_condition() {
        constexpr int d = rows.domain[Row];
        if constexpr (d >= 0) exit_below<d>();
        run_action<Row>(eventless{});
        run_entries<Row>();
        // A timeout that leaves its state active counts again from now (layout.hpp, rearms).
        if constexpr (plan::rearms(Row)) this->rearm_timeout(plan::row_timeout_slot[Row]);
    }

    template <int Frontier, int Component>
    constexpr bool try_component_candidates() {
        constexpr auto const& candidates = plan::template component_candidates<Frontier, Component>;
        // clang-format off
        return [&]<std::size_t... I>(std::index_sequence<I...>) {
            return ((condition_holds<candidates[I]>() && (fire_candidate<candidates[I]>(), true)) || ...);
        }(std::make_index_sequence<candidates.size()>{});
        // clang-format on
    }

    // Walks a component from S down to its active frontier and fires its first enabled
    // condition-driven transition, if any.
    template <int Component>
    constexpr bool component_step() {
        return component_walk<Component, Component>();
    }
    template <int S, int Component>
    constexpr bool component_walk() {
        constexpr auto k = tree.kinds[S];
        if constexpr (!plan::template relevant<detail::any_condition>(S)) {
            return false;
        } else if constexpr (k == detail::kind::composite) {
            // An irrelevant child has no condition-driven transition on it or above it.
            bool fired = false;
            with_relevant_active_child<detail::any_condition, S>(
                [&](auto c) { fired = component_walk<decltype(c)::value, Component>(); });
            return fired;
        } else {
            return try_component_candidates<S, Component>();
        }
    }
};

// Charts are declared `constexpr`, so `machine{chart, ...}` and `machine<decltype(chart)>` name
// the same type.
// A machine of a chart that failed its checks does nothing (detail/runtime/rejected.hpp).
template <statechart Chart, machine_policy Policy, class Observer>
    requires detail::rejected<Chart>
class machine<Chart, Policy, Observer> : public detail::inert_machine<Chart> {
public:
    using detail::inert_machine<Chart>::inert_machine;
};

template <class C, class... A>
machine(C const&, A...) -> machine<C const, default_policy, detail::observer_argument_t<A...>>;

}  // namespace bsc
// end include/bsc/machine.hpp
// begin include/bsc/system.hpp
// Systems of actors (the COMDES-II paper [COMDES]; the modules of the ECA paper [ECA]; see
// docs/references.md): several machines — controllers and plant models — wired by typed signals
// from output channels to input channels, stepped in a declared order with the time given from
// outside. The wiring is one list, the system's actor diagram, and it is checked where the
// system type is instantiated: a link goes from an output to an input of the same value type
// (or says how to convert with bsc::convert), one link at most drives an input, every linked
// actor is stepped once per step, and every input of a stepped actor is driven by a link or
// declared bsc::from_outside. Each defect is one compile error (bsc::error, docs/checks.md).

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>


namespace bsc {

/// What the consumer of a link reads while the link's publisher is silent, when the two actors
/// run on different nodes (<bsc/net/node.hpp>). In one process a link is never stale, and the
/// policy changes nothing.
///
/// `hold_last` (the default): the last value received stays, as a latched level would.
struct hold_last {};

/// `fail_safe<V>`: the consumer reads `V` until the publisher is heard again, e.g. a motor
/// command that reads "stop" when its controller is lost. V is a structural value of the link's
/// type (a number, an enumerator, an aggregate of those).
template <auto V>
struct fail_safe {
    static constexpr auto value = V;
};

/// `lossless`: the link is never stale; the consumer waits for every value, however long its
/// publisher is silent, and the publisher waits for the consumer. For the couplings of a
/// simulated plant (a brick handed from one machine to the next), where a missed value is a
/// lost object, not a late one.
struct lossless {};

/// `convert<F>`: the consumer of the link reads `F(value)` for the source's value: a conversion
/// made explicit where the types of the two channels differ (a link without it requires the
/// same value type on both ends). F is a constexpr callable: a captureless lambda, a function
/// pointer. What a fail_safe<V> link reads while stale is V itself, already of the target's type.
template <auto F>
struct convert {
    static constexpr auto function = F;
};

namespace detail {

template <class T>
struct is_staleness_policy : std::false_type {};
template <>
struct is_staleness_policy<hold_last> : std::true_type {};
template <>
struct is_staleness_policy<lossless> : std::true_type {};
template <auto V>
struct is_staleness_policy<fail_safe<V>> : std::true_type {};

template <class T>
struct is_conversion : std::false_type {};
template <auto F>
struct is_conversion<convert<F>> : std::true_type {};

// The identity, for a link without bsc::convert.
struct no_conversion {};

// The first of Ts for which Is holds, or Default.
template <template <class> class Is, class Default, class... Ts>
struct first_such {
    using type = Default;
};
template <template <class> class Is, class Default, class T, class... Ts>
struct first_such<Is, Default, T, Ts...>
    : std::conditional_t<Is<T>::value, std::type_identity<T>, first_such<Is, Default, Ts...>> {};

// Two pointers to members (or any two template arguments) that designate the same member.
template <auto A, auto B>
constexpr bool same_member_pointer() {
    if constexpr (std::is_same_v<decltype(A), decltype(B)>)
        return A == B;
    else
        return false;
}

}  // namespace detail

/// A signal: the published value of output channel `FromChannel` of actor `FromActor` is
/// written into input channel `ToChannel` of actor `ToActor` just before `ToActor` steps.
/// Actors are members of the system's aggregate; channels are members of their contexts.
/// `Options`, in any order and each at most once: what the consumer reads when the two run on
/// different nodes and the publisher falls silent (hold_last, the default, fail_safe<V> or
/// lossless), and `convert<F>` for channels of different value types.
template <auto FromActor, auto FromChannel, auto ToActor, auto ToChannel, class... Options>
struct link {
    static constexpr auto from_actor = FromActor;
    static constexpr auto from_channel = FromChannel;
    static constexpr auto to_actor = ToActor;
    static constexpr auto to_channel = ToChannel;
    using when_stale = typename detail::first_such<detail::is_staleness_policy, hold_last, Options...>::type;
    /// bsc::convert<F>, or detail::no_conversion.
    using conversion = typename detail::first_such<detail::is_conversion, detail::no_conversion, Options...>::type;
    using options = detail::type_list<Options...>;

    /// What the consumer reads for the source's value `v`: v, or F(v) with bsc::convert<F>.
    template <class V>
    static constexpr auto converted(V const& v) {
        if constexpr (std::is_same_v<conversion, detail::no_conversion>)
            return v;
        else
            return conversion::function(v);
    }

    template <class Actors>
    static constexpr void transfer(Actors& actors) {
        auto const& source = (actors.*FromActor).context().*FromChannel;
        // The target's input is set through its machine's const context, as the environment sets it.
        ((actors.*ToActor).context().*ToChannel).set(converted(source.get()));
    }
    template <auto Actor>
    static constexpr bool targets() {
        return detail::same_member_pointer<Actor, ToActor>();
    }
};

/// An input that no link drives and that the environment sets between steps (an operator's
/// switch, a sensor outside the system): input channel `Channel` of actor `Actor`, declared
/// among a system's links. Every input (bsc::input) of a stepped actor is driven by a link or
/// so declared.
template <auto Actor, auto Channel>
struct from_outside {
    static constexpr auto actor = Actor;
    static constexpr auto channel = Channel;
};

/// The order in which a system steps its actors, as pointers to the aggregate's members.
template <auto... Actors>
struct order {};

/// What one system step did.
struct system_report {
    int transitions = 0;  ///< condition-driven transitions fired by all actors
    bool queue_overflow = false;
    bool livelock = false;
    bool halted = false;  ///< some actor is halted (a final child of its root is active)
};

namespace detail {

template <class T>
inline constexpr bool is_link = false;
template <auto FromActor, auto FromChannel, auto ToActor, auto ToChannel, class... Options>
inline constexpr bool is_link<link<FromActor, FromChannel, ToActor, ToChannel, Options...>> = true;
template <class T>
inline constexpr bool is_from_outside = false;
template <auto Actor, auto Channel>
inline constexpr bool is_from_outside<from_outside<Actor, Channel>> = true;

template <class List>
struct tuple_of_list;
template <class... Ts>
struct tuple_of_list<type_list<Ts...>> {
    using type = std::tuple<Ts...>;
};
// The entries of a system for which Is holds, in their order, as a std::tuple.
template <template <class> class Is, class... Entries>
using entries_such = typename tuple_of_list<
    concat_t<type_list<>, std::conditional_t<Is<Entries>::value, type_list<Entries>, type_list<>>...>>::type;
template <class T>
struct link_entry : std::bool_constant<is_link<T>> {};
template <class T>
struct from_outside_entry : std::bool_constant<is_from_outside<T>> {};

// An actor of Actors that has a context (a machine), and the member Channel of that context.
template <class Actors, auto Actor>
concept actor_with_context = requires(Actors const& actors) {
    (actors.*Actor).context();
};
template <class Actors, auto Actor>
using context_of_actor = std::remove_cvref_t<decltype((std::declval<Actors const&>().*Actor).context())>;
template <class Actors, auto Actor, auto Channel>
concept actor_has_member = actor_with_context<Actors, Actor> &&
    requires(context_of_actor<Actors, Actor> const& context) {
    context.*Channel;
};
template <class Actors, auto Actor, auto Channel>
using member_of_actor = std::remove_cvref_t<decltype(std::declval<context_of_actor<Actors, Actor> const&>().*Channel)>;

// Whether Channel is a member of Actor's context that the actor publishes (an output, an
// inout), or that is written from outside it (an input, an inout).
template <class Actors, auto Actor, auto Channel>
constexpr bool publishes() {
    if constexpr (actor_has_member<Actors, Actor, Channel>) {
        using M = member_of_actor<Actors, Actor, Channel>;
        return is_output_channel<M> || is_inout_channel<M>;
    } else {
        return false;
    }
}
template <class Actors, auto Actor, auto Channel>
constexpr bool written_from_outside() {
    if constexpr (actor_has_member<Actors, Actor, Channel>) {
        using M = member_of_actor<Actors, Actor, Channel>;
        return is_input_channel<M> || is_inout_channel<M>;
    } else {
        return false;
    }
}

template <class Conversion, class From, class To>
concept conversion_applies = requires(From const& value) {
    Conversion::function(value);
}
&&std::is_convertible_v<decltype(Conversion::function(std::declval<From const&>())), To>;

// What an option of bsc::link is: 1 a staleness policy, 2 a conversion, 0 neither.
template <class Option>
constexpr int option_kind() {
    return is_staleness_policy<Option>::value ? 1 : is_conversion<Option>::value ? 2 : 0;
}

// Each option of a link is known, and none is a second of its kind.
template <class Options>
struct link_options_rules;
template <class... Options>
struct link_options_rules<type_list<Options...>> {
    static constexpr std::array<int, sizeof...(Options) + 1> kinds{option_kind<Options>()..., -1};
    template <std::size_t I>
    static constexpr bool repeated() {
        for (std::size_t j = 0; j < I; ++j)
            if (kinds[j] == kinds[I]) return true;
        return false;
    }
    template <std::size_t I, class Option>
    static constexpr bool check_one() {
        if constexpr (option_kind<Option>() == 0 || repeated<I>())
            return report<error::invalid_link_option<Option>>();
        else
            return true;
    }
    static constexpr bool check() {
        // clang-format off
        return []<std::size_t... I>(std::index_sequence<I...>) {
            return ((check_one<I, Options>() ? 0 : 1) + ... + 0) == 0;
        }(std::index_sequence_for<Options...>{});
        // clang-format on
    }
};

BSC_DETAIL_DECLARED_ONLY_BEGIN
BSC_DETAIL_DECLARED_ONLY_END

// The name of member I of Context, as a template argument.
template <class Context, std::size_t I>
constexpr auto member_name_argument() {
    constexpr std::string_view name = names_of<Context>()[I];
    fixed_string<name.size() + 1> text{};
    for (std::size_t k = 0; k < name.size(); ++k) text.chars[k] = name[k];
    return text;
}

// The checks of a system's wiring, each defect reported once (detail::report) as the error that
// names it; check() is true when there is none. A check that would only repeat an earlier
// finding in other words is not run: the inputs left undriven are looked for once every link
// and bsc::from_outside entry is right.
template <class Actors, class Order, class... Entries>
struct system_rules;

template <class Actors, auto... Steps, class... Entries>
struct system_rules<Actors, order<Steps...>, Entries...> {
    using links = entries_such<link_entry, Entries...>;
    using declared_outside = entries_such<from_outside_entry, Entries...>;

    template <std::size_t I>
    static constexpr auto step_at = std::get<I>(std::tuple{Steps...});

    template <auto Actor>
    static constexpr bool in_order() {
        return (same_member_pointer<Actor, Steps>() || ...);
    }
    // Whether the order names its I-th actor for the first time there.
    template <std::size_t I>
    static constexpr bool first_in_order() {
        // clang-format off
        return []<std::size_t... J>(std::index_sequence<J...>) {
            return !(same_member_pointer<step_at<J>, step_at<I>>() || ...);
        }(std::make_index_sequence<I>{});
        // clang-format on
    }
    // Whether a link drives Channel of Actor.
    template <auto Actor, auto Channel>
    static constexpr bool linked() {
        // clang-format off
        return []<class... L>(std::tuple<L...>*) {
            return ((same_member_pointer<L::to_actor, Actor>() && same_member_pointer<L::to_channel, Channel>()) || ...);
        }(static_cast<links*>(nullptr));
        // clang-format on
    }

    template <std::size_t I>
    static constexpr bool check_step() {
        if constexpr (!first_in_order<I>())
            return report<error::actor_twice_in_order<step_at<I>>>();
        else
            return true;
    }

    template <class L>
    static constexpr bool check_link() {
        if constexpr (!link_options_rules<typename L::options>::check()) {
            return false;
        } else {
            constexpr bool from_in = in_order<L::from_actor>();
            constexpr bool to_in = in_order<L::to_actor>();
            if constexpr (!from_in) report<error::actor_not_in_order<L::from_actor>>();
            if constexpr (!to_in) report<error::actor_not_in_order<L::to_actor>>();
            if constexpr (!from_in || !to_in) {
                return false;
            } else {
                constexpr bool source = publishes<Actors, L::from_actor, L::from_channel>();
                constexpr bool target = written_from_outside<Actors, L::to_actor, L::to_channel>();
                if constexpr (!source) report<error::link_source_not_an_output<L::from_actor, L::from_channel>>();
                if constexpr (!target) report<error::link_target_not_an_input<L::to_actor, L::to_channel>>();
                if constexpr (!source || !target) {
                    return false;
                } else {
                    using from = channel_value<member_of_actor<Actors, L::from_actor, L::from_channel>>;
                    using to = channel_value<member_of_actor<Actors, L::to_actor, L::to_channel>>;
                    using conversion = typename L::conversion;
                    if constexpr (std::is_same_v<conversion, no_conversion> && !std::is_same_v<from, to>)
                        return report<error::link_value_types_differ<L::from_channel, L::to_channel, from, to>>();
                    else if constexpr (!std::is_same_v<conversion, no_conversion> &&
                                       !conversion_applies<conversion, from, to>)
                        return report<error::link_conversion_not_applicable<conversion, from, to>>();
                    else
                        return true;
                }
            }
        }
    }

    // Link I drives an input that an earlier link drives already.
    template <std::size_t I>
    static constexpr bool check_driven_once() {
        using L = std::tuple_element_t<I, links>;
        // clang-format off
        constexpr bool earlier = []<std::size_t... J>(std::index_sequence<J...>) {
            return ((same_member_pointer<std::tuple_element_t<J, links>::to_actor, L::to_actor>() &&
                     same_member_pointer<std::tuple_element_t<J, links>::to_channel, L::to_channel>()) ||
                    ...);
        }(std::make_index_sequence<I>{});
        // clang-format on
        if constexpr (earlier)
            return report<error::input_driven_twice<L::to_actor, L::to_channel>>();
        else
            return true;
    }

    template <class F>
    static constexpr bool check_from_outside() {
        if constexpr (!in_order<F::actor>())
            return report<error::actor_not_in_order<F::actor>>();
        else if constexpr (!written_from_outside<Actors, F::actor, F::channel>())
            return report<error::from_outside_not_an_input<F::actor, F::channel>>();
        else if constexpr (linked<F::actor, F::channel>())
            return report<error::input_linked_and_from_outside<F::actor, F::channel>>();
        else
            return true;
    }

    template <class Entry>
    static constexpr bool check_entry() {
        if constexpr (is_link<Entry>)
            return check_link<Entry>();
        else if constexpr (is_from_outside<Entry>)
            return check_from_outside<Entry>();
        else
            return report<error::not_a_link<Entry>>();
    }

    // The members of Actor's context that a link or a from_outside entry drives (one more
    // than the members, for a channel found nowhere).
    template <auto Actor, class Context>
    static constexpr auto driven_members() {
        std::array<bool, member_count<Context> + 1> driven{};
        auto mark = [&]<auto A, auto Channel>() {
            if constexpr (same_member_pointer<A, Actor>()) driven[member_index<Channel>()] = true;
        };
        // clang-format off
        []<class... L>(std::tuple<L...>*, auto& m) {
            (m.template operator()<L::to_actor, L::to_channel>(), ...);
        }(static_cast<links*>(nullptr), mark);
        // clang-format on
        // clang-format off
        []<class... F>(std::tuple<F...>*, auto& m) {
            (m.template operator()<F::actor, F::channel>(), ...);
        }(static_cast<declared_outside*>(nullptr), mark);
        // clang-format on
        return driven;
    }
    template <auto Actor, class Context>
    static constexpr auto driven_of = driven_members<Actor, Context>();

    template <auto Actor, class Context, std::size_t K>
    static constexpr bool check_input_driven() {
        using member = std::tuple_element_t<K, typename tuple_of_list<member_types<Context>>::type>;
        if constexpr (is_input_channel<std::remove_cv_t<member>> && !driven_of<Actor, Context>[K])
            return report<
                error::input_not_driven<Actor, error::member_number<K>, member_name_argument<Context, K>()>>();
        else
            return true;
    }
    template <auto Actor, class Context, std::size_t... K>
    static constexpr bool check_members_driven(std::index_sequence<K...>) {
        return ((check_input_driven<Actor, Context, K>() ? 0 : 1) + ... + 0) == 0;
    }

    // Every bsc::input member of the context of the order's I-th actor is driven. Only an
    // aggregate context is looked into: one described by bsc::fields or Boost.Hana may keep its
    // channels private, where neither a link nor from_outside can name them. Inputs nested in a
    // struct or a std::array of the context are not looked for: no link can name them.
    template <std::size_t I>
    static constexpr bool check_inputs_driven() {
        constexpr auto actor = step_at<I>;
        if constexpr (!first_in_order<I>() || !actor_with_context<Actors, actor>) {
            return true;
        } else {
            using context = context_of_actor<Actors, actor>;
            if constexpr (!std::is_class_v<context> || !std::is_aggregate_v<context> || described_by_fields<context> ||
                          kind_of<context>() != member_kind::record)
                return true;
            else
                return check_members_driven<actor, context>(std::make_index_sequence<member_count<context>>{});
        }
    }

    static constexpr bool check() {
        // clang-format off
        constexpr bool steps = []<std::size_t... I>(std::index_sequence<I...>) {
            return ((check_step<I>() ? 0 : 1) + ... + 0) == 0;
        }(std::index_sequence_for<decltype(Steps)...>{});
        // clang-format on
        constexpr bool entries = ((check_entry<Entries>() ? 0 : 1) + ... + 0) == 0;
        // clang-format off
        constexpr bool once = []<std::size_t... I>(std::index_sequence<I...>) {
            return ((check_driven_once<I>() ? 0 : 1) + ... + 0) == 0;
        }(std::make_index_sequence<std::tuple_size_v<links>>{});
        // clang-format on
        if constexpr (!entries || !once) {
            return false;
        } else {
            // clang-format off
            constexpr bool inputs = []<std::size_t... I>(std::index_sequence<I...>) {
                return ((check_inputs_driven<I>() ? 0 : 1) + ... + 0) == 0;
            }(std::index_sequence_for<decltype(Steps)...>{});
            // clang-format on
            return steps && inputs;
        }
    }
};

}  // namespace detail

template <class Actors, class Order, class... Links>
struct system;

/// A system: the aggregate `Actors` of machines (anything with `context()` and `step(now)`),
/// stepped in `Order`, with `Links` delivering signals and `bsc::from_outside` entries naming the
/// inputs the environment sets. `actors` is a public member, so a system is itself an aggregate
/// that the explorer can encode. No heap. The wiring is checked where the type is instantiated
/// (detail::system_rules): each defect is one compile error, and a system with one does nothing.
template <class Actors, auto... Steps, class... Links>
struct system<Actors, order<Steps...>, Links...> {
    using actors_type = Actors;
    using order_type = order<Steps...>;
    /// The links, in their order (the bsc::from_outside entries left out).
    using links_type = detail::entries_such<detail::link_entry, Links...>;
    /// The bsc::from_outside entries, in their order.
    using from_outside_type = detail::entries_such<detail::from_outside_entry, Links...>;
    /// Whether the wiring passed every check.
    static constexpr bool well_formed = detail::system_rules<Actors, order<Steps...>, Links...>::check();
    static_assert(well_formed || true);  // instantiates the checks here (their errors are the report)

    Actors actors;

    /// One step of every actor, in order: each first receives the signals linked to it (the
    /// outputs its senders published, this step for senders earlier in the order, the last
    /// step for the others), then runs one cycle at `now`.
    constexpr system_report step(duration now) {
        system_report report;
        if constexpr (well_formed)
            (step_one<Steps>(now, report), ...);
        else
            (void)now;
        return report;
    }

private:
    template <auto Actor>
    constexpr void step_one(duration now, system_report& report) {
        // clang-format off
        []<class... L>(std::tuple<L...>*, Actors& all) {
            ((L::template targets<Actor>() ? L::transfer(all) : void()), ...);
        }(static_cast<links_type*>(nullptr), actors);
        // clang-format on
        auto const r = (actors.*Actor).step(now);
        report.transitions += r.transitions;
        report.queue_overflow = report.queue_overflow || r.status == outcome::queue_overflow;
        report.livelock = report.livelock || r.status == outcome::livelock;
        report.halted = report.halted || r.status == outcome::halted || (actors.*Actor).halted();
    }
};

}  // namespace bsc
// end include/bsc/system.hpp
// begin include/bsc/table/machine.hpp
// bsc::table::machine: the table-driven back end. A generic engine (the machine-tool paper
// [MCS] in docs/references.md, section 3.3.2) interprets the two tables of
// bsc/detail/table/tables.hpp: it knows states and transitions only by their numbers, and reaches the
// chart's guards and actions through the tables' function pointers. Its public interface and
// run to completion are the shared driver's (detail/runtime/driver.hpp), so a program changes back end
// by changing one type.
//
// The paper's engine and this one:
//
//   StartStEng(st, qtStates, tm, qtTrans)   the constructor: enter_initial()
//   stEng(event)                            dispatch(e): one microstep per event taken from
//                                           the environment or the queue
//   deActivPath(from, to, inclusive)        deactivate_path(domain)
//   activPath(from, to, hist)               activate_path(domain, target)
//   StopStEng()                             the destructor (the engine owns no resource)
//
// and the five steps of its Figure 9 are those of select_and_fire(). step(now) adds the BSC execution
// cycle of the Basic Statechart paper [BSC] (one condition-driven transition per component)
// with the same tables.

#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

// begin include/bsc/detail/table/tables.hpp
// The operation rules of the table-driven runtime: a chart as the two constant tables of the
// machine-tool paper [MCS] (docs/references.md, section 3.3.1), the topology table (the paper's
// BSTATE, one row per state) and the transition table (BTRANS, one row per transition). The
// chart's guards, actions, entry and exit actions are reached through plain function pointers:
// one small generated function ("thunk") per row, which receives the chart object and the
// context and calls the row's callable. Everything here is computed by the compiler from the
// chart model; bsc::table::machine interprets it.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>
#include <utility>


namespace bsc::table {

/// A state's number: its row in the topology table. Row 0 is the implicit top above the
/// chart's root (the paper's ancestor 0 of MCS); since the top is nobody's child or sibling,
/// 0 (no_state) also means "none" in the first_child, next_sibling, initial and `to` columns.
using state_id = std::uint16_t;
inline constexpr state_id no_state = 0;

/// An event's number: the position of its type in the machine's event_types.
using event_id = std::int16_t;
inline constexpr event_id eventless_id = -1;  ///< a transition without an event
inline constexpr event_id timeout_id = -2;    ///< a timeout transition, taken by a BSC cycle only

/// Eventless and timeout transitions are condition-driven: the ones a BSC cycle considers.
constexpr bool is_condition(event_id event) { return event < 0; }

/// The paper's status column, in the words of the DSL: the kind of state and its history.
enum class state_kind : std::uint8_t {
    top,          ///< the implicit state above the root (row 0)
    basic,        ///< an atomic state
    final_state,  ///< an atomic state that ends its parent (the root: the machine halts)
    composite,    ///< exactly one child active (the paper's hierarchical, or OR, state)
    parallel,     ///< all children active (the paper's concurrent, or AND, state)
    history,      ///< a history pseudo-state of its parent composite: never active
};
enum class history_kind : std::uint8_t { none, shallow, deep };

struct state_status {
    state_kind kind = state_kind::basic;
    history_kind history = history_kind::none;
    friend constexpr bool operator==(state_status, state_status) = default;
};

/// One row of the topology table (the paper's BSTATE, Figure 7, whose descendant, sibling and
/// ancestor columns are first_child, next_sibling and parent here), then the columns the
/// engine would otherwise recompute by walking the tree.
template <class Chart, class Raise>
struct state_row {
    using context_type = typename Chart::context_type;
    /// Runs the state's entry (or exit) actions, in declaration order; each is one block, and
    /// what one throws goes to `failures` before the next runs.
    using state_action = void (*)(Chart const& chart, context_type& context, Raise& raise,
                                  bsc::detail::failure_sink const& failures);

    state_id state = no_state;         ///< this row's number
    state_id first_child = no_state;   ///< first child in document order (BSTATE's descendant)
    state_id next_sibling = no_state;  ///< next sibling in document order (BSTATE's sibling)
    state_id parent = no_state;        ///< parent, 0 (the top) for the root (BSTATE's ancestor)
    state_status status{};
    state_action entry = nullptr;           ///< null: no entry action
    state_action exit = nullptr;            ///< null: no exit action
    state_action initial_action = nullptr;  ///< a composite's initial transition's actions (on_initial); null: none

    // Derived columns.
    state_id initial = no_state;         ///< default child of a composite (of a history state: its default's path)
    state_id initial_target = no_state;  ///< its initial state: `initial`, or a descendant below it (a deep initial)
    std::array<state_id, 3>
        more_initial{};              ///< its initial states after the first (`initial<A, B>`); no_state where fewer
    std::uint16_t ordinal = 0;       ///< position among its siblings: the configuration entry that selects it
    std::int16_t slot = -1;          ///< the byte of the configuration a composite owns, -1 for others
    state_id end = 0;                ///< one past its last descendant: d is below s iff s < d < end
    std::int16_t timeout_slot = -1;  ///< the first slot of its timeout rows (see transition_row), else -1
    std::int16_t timeout_slots = 0;  ///< how many of its rows are timeouts: its slots follow the first
};

/// One row of the transition table (the paper's BTRANS, Figure 8).
template <class Chart, class Raise>
struct transition_row {
    using context_type = typename Chart::context_type;
    /// Whether a guard of the chart tests the configuration (bsc::in<S>): then every guard
    /// receives the configuration bytes too (bsc::configuration::active, null for a chart without
    /// composites), and the guards of other charts do not.
    static constexpr bool guards_read_configuration =
        bsc::detail::any_row_tests_configuration<typename Chart::row_types>;
    /// The guard, called with the event the transition is triggered by (bsc::eventless{} for
    /// eventless transitions) passed as `event`, and in a chart with bsc::in<S> with the
    /// configuration bytes as `active`.
    using guard_fn = std::conditional_t<guards_read_configuration,
                                        bool (*)(Chart const& chart, context_type const& context, void const* event,
                                                 typename bsc::detail::chart_model<Chart>::ordinal_type const* active),
                                        bool (*)(Chart const& chart, context_type const& context, void const* event)>;
    using action_fn = void (*)(Chart const& chart, context_type& context, void const* event, Raise& raise);
    /// The delay of a timeout. `after(d)` stores d in the chart object, not in its type, so the
    /// delay is read from the chart like a guard.
    using delay_fn = duration (*)(Chart const& chart);

    state_id from = no_state;       ///< origin state
    event_id event = eventless_id;  ///< trigger, or `eventless_id` / `timeout_id`
    state_id to = no_state;         ///< destination state; no_state: an internal transition
    guard_fn guard = nullptr;       ///< null: unguarded
    action_fn action = nullptr;     ///< null: no action
    state_id domain = no_state;     ///< the transition domain: the state whose active descendants it exits
    delay_fn delay = nullptr;       ///< a timeout's delay; null for the other transitions
    /// A timeout's slot: where the machine keeps the time its delay counts from (its origin's
    /// entry, or for an internal timeout the cycle it last fired in); -1 for the others.
    std::int16_t timeout_slot = -1;
    bool defers = false;  ///< the row defers its event (`/ bsc::defer`): it keeps the event, and has no action
    bool rearms = false;  ///< a timeout that leaves its source active: it counts again from when it fires
    /// A transition with several targets (bsc::targets): the others after `to`; no_state where
    /// there are fewer.
    std::array<state_id, 3> more_to{};
};

/// The operation rules of `Chart`: its topology table `states` and transition table
/// `transitions`, plus the indexes the engine uses to read them. `Policy` only fixes the
/// capacity of the queue that actions raise events into (the `Raise` argument of the thunks).
template <class Chart, class Policy = default_policy>
struct tables {
    using chart_type = std::remove_cv_t<Chart>;
    using context_type = typename chart_type::context_type;
    using raise_type = bsc::detail::queue_for<chart_type, Policy>;
    using state_row_type = state_row<chart_type, raise_type>;
    using transition_row_type = transition_row<chart_type, raise_type>;

private:
    using model = bsc::detail::chart_model<chart_type>;
    using layout = bsc::detail::chart_layout<model>;
    using row_kind = bsc::detail::row_kind;
    static constexpr auto const& tree = model::tree;
    static constexpr auto const& rows = model::rows;

    // The event type a transition row's guard and action receive.
    template <int Row>
    using event_type_of = bsc::detail::row_event_t<typename model::template row_at<Row>>;

    // ---- the thunks: one per state and per transition ---------------------------------------
    template <row_kind K, int S>
    static void state_thunk(chart_type const& chart, context_type& context, raise_type& raise,
                            bsc::detail::failure_sink const& failures) {
        constexpr auto const& actions = layout::template rows_of<K, S>;
        auto const report = [&](std::exception_ptr error) { failures.report(failures.machine, std::move(error)); };
        // clang-format off
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            (bsc::detail::run_block(
                 [&] { bsc::detail::row_at<static_cast<std::size_t>(actions[I])>(chart.rows).action(context, raise); },
                 report),
             ...);
        }(std::make_index_sequence<actions.size()>{});
        // clang-format on
    }

    template <int Row>
    static bool guard_thunk(chart_type const& chart, context_type const& context, void const* event) {
        return static_cast<bool>(bsc::detail::row_at<static_cast<std::size_t>(Row)>(chart.rows)
                                     .guard(context, *static_cast<event_type_of<Row> const*>(event)));
    }
    // The thunk of a guard in a chart with bsc::in<S>: a guard that tests the configuration sees
    // it through the view of its row (detail/model/configuration_view.hpp, tests resolved at
    // compile time), the others ignore it.
    template <int Row>
    static bool configuration_guard_thunk(chart_type const& chart, context_type const& context, void const* event,
                                          [[maybe_unused]] typename model::ordinal_type const* active) {
        auto const& guard = bsc::detail::row_at<static_cast<std::size_t>(Row)>(chart.rows).guard;
        auto const& e = *static_cast<event_type_of<Row> const*>(event);
        using view = bsc::detail::configuration_view<model, rows.source[Row]>;
        if constexpr (bsc::detail::tests_configuration<std::remove_cvref_t<decltype(guard)>>)
            return static_cast<bool>(guard(context, e, view{active}));
        else
            return static_cast<bool>(guard(context, e));
    }

    template <int Row>
    static void action_thunk(chart_type const& chart, context_type& context, void const* event, raise_type& raise) {
        bsc::detail::row_at<static_cast<std::size_t>(Row)>(chart.rows)
            .action(context, *static_cast<event_type_of<Row> const*>(event), raise);
    }

    template <int Row>
    static duration delay_thunk(chart_type const& chart) {
        return bsc::detail::row_at<static_cast<std::size_t>(Row)>(chart.rows).trigger_value.delay;
    }

    template <row_kind K, int S>
    static constexpr typename state_row_type::state_action state_action_of() {
        if constexpr (layout::template rows_of<K, S>.size() == 0)
            return nullptr;
        else
            return &state_thunk<K, S>;
    }

    static constexpr state_id id(int s) { return s < 0 ? no_state : static_cast<state_id>(s); }

    static constexpr state_kind kind_of(bsc::detail::kind k) {
        switch (k) {
            case bsc::detail::kind::top: return state_kind::top;
            case bsc::detail::kind::basic: return state_kind::basic;
            case bsc::detail::kind::final_state: return state_kind::final_state;
            case bsc::detail::kind::composite: return state_kind::composite;
            case bsc::detail::kind::parallel: return state_kind::parallel;
            case bsc::detail::kind::history: return state_kind::history;
        }
        return state_kind::basic;
    }
    static constexpr history_kind history_of(bsc::detail::history h) {
        switch (h) {
            case bsc::detail::history::none: return history_kind::none;
            case bsc::detail::history::shallow: return history_kind::shallow;
            case bsc::detail::history::deep: return history_kind::deep;
        }
        return history_kind::none;
    }

    template <int S>
    static constexpr state_row_type make_state_row() {
        constexpr auto i = static_cast<std::size_t>(S);
        state_row_type row{};
        row.state = static_cast<state_id>(S);
        row.first_child = id(tree.first_child[i]);
        row.next_sibling = id(tree.next_sibling[i]);
        row.parent = id(tree.parent[i]);
        row.status = {kind_of(tree.kinds[i]), history_of(tree.hist[i])};
        row.entry = state_action_of<row_kind::entry, S>();
        row.exit = state_action_of<row_kind::exit, S>();
        row.initial = id(tree.initial[i]);
        row.initial_target = id(tree.initial_target[i]);
        for (std::size_t k = 0; k < row.more_initial.size(); ++k) row.more_initial[k] = id(tree.more_initial[i][k]);
        row.initial_action = state_action_of<row_kind::initial, S>();
        row.ordinal = static_cast<std::uint16_t>(tree.ordinal[i]);
        row.slot = static_cast<std::int16_t>(tree.slot[i]);
        row.end = static_cast<state_id>(tree.end[i]);
        row.timeout_slot = static_cast<std::int16_t>(layout::timeout_slot[i]);
        row.timeout_slots = static_cast<std::int16_t>(layout::timeout_slot_count[i]);
        return row;
    }

    template <std::size_t K>
    static constexpr transition_row_type make_transition_row() {
        constexpr int r = layout::transition_rows[K];
        constexpr auto i = static_cast<std::size_t>(r);
        using R = typename model::template row_at<r>;
        transition_row_type row{};
        row.from = id(rows.source[i]);
        row.event = rows.trigger[i] >= 0                           ? static_cast<event_id>(rows.trigger[i])
                    : rows.trigger[i] == bsc::detail::eventless_id ? eventless_id
                                                                   : timeout_id;
        row.to = id(rows.target[i]);
        if constexpr (rows.guarded[i] && transition_row_type::guards_read_configuration)
            row.guard = &configuration_guard_thunk<r>;
        else if constexpr (rows.guarded[i])
            row.guard = &guard_thunk<r>;
        // (A deferring row keeps its event and runs nothing: no action either.)
        if constexpr (!std::is_same_v<std::remove_cvref_t<decltype(std::declval<R const&>().action)>,
                                      bsc::detail::no_action> &&
                      !std::is_same_v<std::remove_cvref_t<decltype(std::declval<R const&>().action)>,
                                      bsc::detail::defer_action>)
            row.action = &action_thunk<r>;
        row.domain = id(rows.domain[i]);
        if constexpr (bsc::detail::is_timeout_row<R>) row.delay = &delay_thunk<r>;
        row.timeout_slot = static_cast<std::int16_t>(layout::row_timeout_slot[i]);
        row.defers = rows.defers[i];
        row.rearms = layout::rearms(static_cast<int>(i));
        for (std::size_t k = 0; k < row.more_to.size(); ++k) row.more_to[k] = id(rows.more_targets[i][k]);
        return row;
    }

    static constexpr std::size_t transition_count = layout::transition_rows.size();
    static_assert(model::N <= 0xffff, "bsc::table: a chart has at most 65535 states");
    static_assert(transition_count <= 0x7fff, "bsc::table: a chart has at most 32767 transitions");

public:
    /// The position among make_chart's rows of each transition (what observers' on_row gets).
    static constexpr auto const& transition_chart_row = layout::transition_rows;

    /// Number of rows of each table.
    static constexpr std::size_t state_count = static_cast<std::size_t>(model::N);
    static constexpr std::size_t transition_rows = transition_count;
    /// Number of event types (valid event ids are 0 .. event_count - 1).
    static constexpr std::size_t event_count = model::events::size;
    /// Bytes of the active configuration: one per composite.
    static constexpr std::size_t slots = static_cast<std::size_t>(tree.slots);
    /// The root of the chart (row 1; row 0 is the implicit top).
    static constexpr state_id root = layout::root;
    /// The chart's priority among nested transitions (bsc/priority.hpp): whether a basic
    /// state tries its own transitions before its ancestors' (child_first) or after
    /// (parent_first).
    static constexpr bsc::priority order = model::order;
    /// The most states on one path from the top down: the longest list of origins a state tries.
    static constexpr std::size_t levels = [] {
        int deepest = 0;
        for (int d : tree.depth) deepest = d > deepest ? d : deepest;
        return static_cast<std::size_t>(deepest) + 1;
    }();
    /// The number of state S (its row in `states`).
    template <class S>
    static constexpr state_id state_of = id(model::template index_of_state<S>::value);
    /// The number of event type E (-1 if no transition takes it).
    template <class E>
    static constexpr event_id event_of = static_cast<event_id>(model::template trigger_of<E>::value);

    /// The topology table (BSTATE), in document order: row s describes state s.
    static constexpr std::array<state_row_type, state_count> states =
        // clang-format off
        []<std::size_t... S>(std::index_sequence<S...>) {
            return std::array<state_row_type, state_count>{make_state_row<static_cast<int>(S)>()...};
        }(std::make_index_sequence<state_count>{});
    // clang-format on

    /// The transition table (BTRANS), in declaration order.
    static constexpr std::array<transition_row_type, transition_count> transitions =
        // clang-format off
        []<std::size_t... K>(std::index_sequence<K...>) {
            return std::array<transition_row_type, transition_count>{make_transition_row<K>()...};
        }(std::make_index_sequence<transition_count>{});
    // clang-format on

    /// The unqualified names of the states, by row (row 0, the top, has an internal name).
    static constexpr auto const& names = bsc::detail::state_names_of<model>;

    /// The transitions leaving each state, as a list threaded through the transition table in
    /// declaration order: first_out[s] is the first, next_out[t] the one after t (-1: no more).
    static constexpr auto first_out = [] {
        std::array<std::int16_t, state_count> first{};
        for (auto& f : first) f = -1;
        for (std::size_t t = transition_count; t-- > 0;) first[transitions[t].from] = static_cast<std::int16_t>(t);
        return first;
    }();
    static constexpr auto next_out = [] {
        std::array<std::int16_t, transition_count> next{};
        for (std::size_t t = 0; t < transition_count; ++t) {
            next[t] = -1;
            for (std::size_t u = t + 1; u < transition_count; ++u)
                if (transitions[u].from == transitions[t].from) {
                    next[t] = static_cast<std::int16_t>(u);
                    break;
                }
        }
        return next;
    }();

    /// How many states keep an entry time for their timeouts.
    static constexpr std::size_t timeout_slots = static_cast<std::size_t>(layout::timeout_slots);
    /// Whether a state has several timeout rows, which compete by due time when due together.
    static constexpr bool competing_timeouts = layout::has_competing_timeouts;

    /// True if a transition triggered by `row_event` takes `event`: the same event, or a family
    /// of it (a base class of its type among the chart's events, or bsc::any_event).
    static constexpr bool takes(event_id row_event, event_id event) {
        if constexpr (model::has_families)
            return rows.takes(row_event, event);
        else
            return row_event == event;
    }

    /// True if some transition is triggered by `event` (an event id, or `eventless_id`), or by
    /// a family of it.
    static constexpr bool handles(event_id event) {
        for (auto const& t : transitions)
            if (takes(t.event, event)) return true;
        return false;
    }

    static constexpr bool has_eventless = handles(eventless_id);
    /// True if a BSC cycle has anything to consider: an eventless or timeout transition.
    static constexpr bool has_conditions = has_eventless || handles(timeout_id);

    /// The components of a BSC cycle, in the order they run: the root and every child of a
    /// parallel state, in document order.
    static constexpr auto components = [] {
        std::array<state_id, layout::components.size()> out{};
        for (std::size_t i = 0; i < out.size(); ++i) out[i] = static_cast<state_id>(layout::components[i]);
        return out;
    }();

    /// The configuration every composite starts from: its initial child.
    static constexpr auto const& initial_bytes = layout::initial_bytes;

    /// How many basic states can be active at once: the most transitions one event can select.
    static constexpr std::size_t max_active_leaves = static_cast<std::size_t>(layout::max_active_leaves());

    /// a is d or one of its ancestors.
    static constexpr bool contains(state_id a, state_id d) { return a <= d && d < states[a].end; }
};

}  // namespace bsc::table
// end include/bsc/detail/table/tables.hpp

namespace bsc::table {

/// The observer's hooks as data: one function pointer per state for on_entry and on_exit and
/// one per transition for on_transition and on_row, each null where the observer lacks the
/// hook. They turn the engine's numbers back into the calls of bsc::detail::notify.
template <class Chart, class Policy, class Observer>
struct observer_hooks {
    using state_hook = void (*)(Observer& observer);
    using transition_hook = void (*)(Observer& observer, Chart const& chart, void const* event);

private:
    using model = bsc::detail::chart_model<std::remove_cv_t<Chart>>;
    using notify = bsc::detail::notify<model, Observer>;
    using tables_type = tables<Chart, Policy>;

    template <int Row>
    using event_type = bsc::detail::row_event_t<typename model::template row_at<Row>>;

    template <int Row>
    static void transition(Observer& o, Chart const& chart, void const* event) {
        notify::template transition<Row>(o, bsc::detail::row_at<static_cast<std::size_t>(Row)>(chart.rows),
                                         *static_cast<event_type<Row> const*>(event));
    }

    template <std::size_t S>
    static constexpr state_hook entry_hook() {
        if constexpr (notify::template observes_entry_of<static_cast<int>(S)>)
            return &notify::template entered<static_cast<int>(S)>;
        else
            return nullptr;
    }
    template <std::size_t S>
    static constexpr state_hook exit_hook() {
        if constexpr (notify::template observes_exit_of<static_cast<int>(S)>)
            return &notify::template exited<static_cast<int>(S)>;
        else
            return nullptr;
    }
    template <std::size_t K>
    static constexpr transition_hook transition_hook_of() {
        constexpr int r = tables_type::transition_chart_row[K];
        if constexpr (notify::template observes_row<r, event_type<r>>)
            return &transition<r>;
        else
            return nullptr;
    }

    template <class Hook, std::size_t N, class Make>
    static constexpr std::array<Hook, N> make(Make make_one) {
        // clang-format off
        return [&]<std::size_t... I>(std::index_sequence<I...>) {
            return std::array<Hook, N>{make_one(std::integral_constant<std::size_t, I>{})...};
        }(std::make_index_sequence<N>{});
        // clang-format on
    }

public:
    static constexpr auto on_entry = make<state_hook, tables_type::state_count>(
        [](auto s) { return entry_hook<decltype(s)::value>(); });
    static constexpr auto on_exit = make<state_hook, tables_type::state_count>(
        [](auto s) { return exit_hook<decltype(s)::value>(); });
    static constexpr auto on_transition = make<transition_hook, tables_type::transition_rows>(
        [](auto t) { return transition_hook_of<decltype(t)::value>(); });
};

/// The observer hooks of an observer without hooks: no table at all.
template <class Chart, class Policy>
struct observer_hooks<Chart, Policy, no_observer> {};

/// A running instance of a chart, interpreted from its tables: its context, its active
/// configuration and its internal event queue. Same interface and same behaviour as
/// bsc::machine; no heap, no virtual calls, no RTTI, no exceptions. Unlike bsc::machine it
/// cannot run in constant expressions (its function pointers take the event as `void const*`).
///
/// Requirements: `Chart` is a bsc::statechart (the type of a chart from bsc::make_chart, or
/// bsc::chart_ref); `Policy` is a bsc::machine_policy (bsc::default_policy, or a class derived from
/// it); `Observer` implements any subset of the hooks in observer.hpp.
template <statechart Chart, machine_policy Policy = default_policy, class Observer = no_observer>
class machine : public bsc::detail::driver<machine<Chart, Policy, Observer>, Chart, Policy, Observer,
                                           typename tables<Chart, Policy>::raise_type> {
    using base = bsc::detail::driver<machine, Chart, Policy, Observer, typename tables<Chart, Policy>::raise_type>;
    friend base;
    // The driver's layers that call the hooks (detail/runtime/backend.hpp), and backend_hooks,
    // through which the driver checks them.
    friend bsc::detail::backend_hooks;
    template <class, class, class, class, class>
    friend class bsc::detail::settling;
    template <class, class, class, class, class>
    friend class bsc::detail::deferral;
    template <class, class, class, class, class>
    friend class bsc::detail::done_raising;
    static constexpr bool marks_running_lazily = false;  // a dispatch is marked running throughout
    using hooks = observer_hooks<Chart, Policy, Observer>;
    using base::observed;

public:
    using typename base::context_type;
    /// The operation rules this machine interprets.
    using tables_type = tables<Chart, Policy>;

    /// Enters the initial configuration (entry actions run) and settles eventless transitions.
    /// (The chart parameter's type_identity leaves deduction to the guides below.)
    explicit machine(std::type_identity_t<Chart> const& chart, context_type context = {}, Observer observer = {})
        : base(chart, std::move(context), std::move(observer)) {
        this->start();
    }

private:
    static constexpr std::size_t N = tables_type::state_count;
    static constexpr auto const& states = tables_type::states;
    static constexpr auto const& transitions = tables_type::transitions;
    using transition_row_type = typename tables_type::transition_row_type;

    // ---- the configuration ----------------------------------------------------------------
    int byte(std::int16_t slot) const {
        if constexpr (tables_type::slots > 0)
            return this->config_.active[static_cast<std::size_t>(slot)];
        else
            return 0;
    }
    void set_byte(std::int16_t slot, int value) {
        if constexpr (tables_type::slots > 0)
            this->config_.active[static_cast<std::size_t>(slot)] =
                static_cast<typename base::configuration_type::ordinal_type>(value);
    }
    // The child of a composite (or of the top) that its byte selects.
    state_id active_child(state_id s) const {
        state_id c = states[s].first_child;
        if (states[s].slot >= 0)
            for (int k = byte(states[s].slot); k > 0; --k) c = states[c].next_sibling;
        return c;
    }
    // s is active if its parent is: a composite parent selects it, a parallel parent or the
    // top always does.
    bool selected(state_id s) const {
        auto const slot = states[states[s].parent].slot;
        return slot < 0 || byte(slot) == states[s].ordinal;
    }
    bool active(state_id s) const {
        for (; s > tables_type::root; s = states[s].parent)
            if (!selected(s)) return false;
        return true;
    }
    template <int S>
    bool is_active() const {
        return active(static_cast<state_id>(S));
    }
    static bool is_leaf(state_id s) { return states[s].first_child == no_state; }

    // ---- entry and exit -------------------------------------------------------------------
    void run_entry(state_id s) {
        if (auto const f = states[s].entry) f(this->chart(), this->context_.value, this->queue_, this->sink());
        if constexpr (base::completion::raises)
            if (states[s].status.kind == state_kind::final_state) this->entered_final(s);
        // A state's timeouts count from its entry, at the time of the last cycle.
        if constexpr (tables_type::timeout_slots > 0)
            this->arm_timeouts(states[s].timeout_slot, states[s].timeout_slots);
        if constexpr (observed)
            if (auto const h = hooks::on_entry[s]) h(this->observer_.value);
    }
    void run_exit(state_id s) {
        if (auto const f = states[s].exit) f(this->chart(), this->context_.value, this->queue_, this->sink());
        if constexpr (observed)
            if (auto const h = hooks::on_exit[s]) h(this->observer_.value);
    }

    // The paper's StartStEng: the initial configuration, entered from the root down.
    void enter_initial() { enter_default(tables_type::root); }
    // When the machine halts: every active state's exit actions, innermost first.
    void exit_all() { deactivate_path(no_state); }

    // Enters s and its default completion: the initial child of a composite, or the child its
    // history remembers; every child of a parallel state.
    void enter_default(state_id s) {
        run_entry(s);
        enter_content(s);
    }
    void enter_content(state_id s) {
        auto const& row = states[s];
        if (row.status.kind == state_kind::composite) {
            switch (row.status.history) {
                case history_kind::none:
                    // The initial transition: its actions, then its target, a child or deeper.
                    if (auto const f = row.initial_action)
                        f(this->chart(), this->context_.value, this->queue_, this->sink());
                    if (states[row.initial].status.kind == state_kind::history) {
                        enter_history(row.initial);
                    } else if (row.more_initial[0] != no_state) {  // initial<A, B>: one state in each region
                        activate_all(s, target_set{row.initial_target, row.more_initial[0], row.more_initial[1],
                                                   row.more_initial[2]});
                    } else if (row.initial_target != row.initial) {
                        activate_path(s, row.initial_target);
                    } else {
                        set_byte(row.slot, states[row.initial].ordinal);
                        enter_default(row.initial);
                    }
                    break;
                case history_kind::shallow: enter_default(active_child(s)); break;
                case history_kind::deep: enter_restore(active_child(s)); break;
            }
        } else if (row.status.kind == state_kind::parallel) {
            this->regions_entering(s);
            for (state_id c = row.first_child; c != no_state; c = states[c].next_sibling) enter_default(c);
            this->regions_entered(s);
        }
    }
    // Enters history state h of composite p: p's remembered child (shallow) or remembered
    // sub-configuration (deep), or, if p has never been active (its byte selects a history
    // state), h's default transition.
    void enter_history(state_id h) {
        state_id const p = states[h].parent;
        state_id const remembered = active_child(p);
        if (states[remembered].status.kind == state_kind::history) {
            if (auto const f = states[h].initial_action)
                f(this->chart(), this->context_.value, this->queue_, this->sink());
            if (states[h].initial_target != states[h].initial) {
                activate_path(p, states[h].initial_target);
            } else {
                set_byte(states[p].slot, states[states[h].initial].ordinal);
                enter_default(states[h].initial);
            }
        } else if (states[h].status.history == history_kind::shallow) {
            enter_default(remembered);
        } else {
            enter_restore(remembered);
        }
    }

    // Deep history: re-enters s and the whole sub-configuration the bytes remember.
    void enter_restore(state_id s) {
        run_entry(s);
        auto const& row = states[s];
        if (row.status.kind == state_kind::composite)
            enter_restore(active_child(s));
        else if (row.status.kind == state_kind::parallel) {
            this->regions_entering(s);
            for (state_id c = row.first_child; c != no_state; c = states[c].next_sibling) enter_restore(c);
            this->regions_entered(s);
        }
    }

    // The paper's activPath: enters, below the active state `domain`, the states on the path
    // down to `target` (and, at every parallel state on the way, its other children by
    // default), then the target's default completion, which follows its history. Entries run
    // outermost first, in document order.
    void activate_path(state_id domain, state_id target) {
        state_id c = target;
        while (states[c].parent != domain) c = states[c].parent;
        if (states[domain].status.kind == state_kind::parallel) {
            // (A parallel `domain` here has just been entered: no transition's domain is parallel.)
            this->regions_entering(domain);
            for (state_id k = states[domain].first_child; k != no_state; k = states[k].next_sibling) {
                if (k == c)
                    enter_path_node(c, target);
                else
                    enter_default(k);
            }
            this->regions_entered(domain);
        } else if (states[c].status.kind == state_kind::history) {
            enter_history(c);  // `domain`, its composite, has been entered: now its history
        } else {
            if (states[domain].slot >= 0) set_byte(states[domain].slot, states[c].ordinal);
            enter_path_node(c, target);
        }
    }
    // Several targets (bsc::targets, bsc::initial<A, B>): the paths down to each of them, the
    // regions of a parallel state on the way that hold none entered by default. A set holds up
    // to four states, no_state where it has fewer.
    using target_set = std::array<state_id, 4>;
    static bool holds_target(state_id s, target_set const& targets) {
        for (state_id t : targets)
            if (t != no_state && tables_type::contains(s, t)) return true;
        return false;
    }
    static bool is_target(state_id s, target_set const& targets) {
        for (state_id t : targets)
            if (t != no_state && s == t) return true;
        return false;
    }
    void activate_all(state_id domain, target_set const& targets) {
        if (states[domain].status.kind == state_kind::parallel) {
            this->regions_entering(domain);
            for (state_id k = states[domain].first_child; k != no_state; k = states[k].next_sibling) {
                if (holds_target(k, targets))
                    enter_path_all(k, targets);
                else
                    enter_default(k);
            }
            this->regions_entered(domain);
        } else {
            // The child of `domain` toward the targets it holds (they lie below one child).
            state_id c = no_state;
            for (state_id t : targets)
                if (t != no_state && c == no_state && tables_type::contains(domain, t) && t != domain) c = t;
            while (states[c].parent != domain) c = states[c].parent;
            if (states[c].status.kind == state_kind::history) {
                enter_history(c);
            } else {
                if (states[domain].slot >= 0) set_byte(states[domain].slot, states[c].ordinal);
                enter_path_all(c, targets);
            }
        }
    }
    void enter_path_all(state_id s, target_set const& targets) {
        run_entry(s);
        if (is_target(s, targets))
            enter_content(s);
        else
            activate_all(s, targets);
    }
    // Step 5 for one transition: the entries of its target, or of its targets.
    void enter_targets(transition_row_type const& row) {
        if (row.to == no_state) return;
        if (row.more_to[0] != no_state)
            activate_all(row.domain, target_set{row.to, row.more_to[0], row.more_to[1], row.more_to[2]});
        else
            activate_path(row.domain, row.to);
    }

    void enter_path_node(state_id s, state_id target) {
        run_entry(s);
        if (s == target)
            enter_content(s);
        else
            activate_path(s, target);
    }

    // The paper's deActivPath: exits every active descendant of `domain`, innermost first and
    // in reverse document order, running exit actions. The bytes are left as they are: they
    // are the history of the states left.
    void deactivate_path(state_id domain) {
        std::array<state_id, N> path{};
        std::size_t n = 0;
        for (state_id s = domain + 1; s < states[domain].end;) {
            if (!selected(s)) {
                s = states[s].end;
                continue;
            }
            path[n++] = s;
            ++s;
        }
        while (n > 0) run_exit(path[--n]);
    }

    // ---- transitions ----------------------------------------------------------------------
    using selection = bsc::detail::selection<tables_type::max_active_leaves>;

    // (In a chart with bsc::in<S>, every guard receives the configuration bytes as well:
    // tables.hpp, guards_read_configuration.)
    bool guard_holds(std::int16_t t, void const* e) {
        auto const g = transitions[static_cast<std::size_t>(t)].guard;
        if constexpr (transition_row_type::guards_read_configuration)
            return g == nullptr || this->test(g, this->chart(), this->context_.value, e, configuration_bytes());
        else
            return g == nullptr || this->test(g, this->chart(), this->context_.value, e);
    }
    typename base::configuration_type::ordinal_type const* configuration_bytes() const {
        if constexpr (tables_type::slots > 0)
            return this->config_.active.data();
        else
            return nullptr;  // no composite: no test reads a byte
    }

    // The event a microstep processes, as the thunks of a transition receive it. Without
    // families, every transition on it takes it as it is.
    struct plain_event {
        void const* event;
        void const* as(event_id) const { return event; }
    };
    // With families, a transition on a family of the event receives the event as that family
    // (a base class subobject, or bsc::any_event): one pointer per event of the chart.
    struct family_event {
        std::array<void const*, tables_type::event_count> seen{};
        void const* as(event_id row_event) const { return seen[static_cast<std::size_t>(row_event)]; }
    };
    template <class E>
    static family_event as_families(E const& e) {
        family_event view;
        // clang-format off
        [&]<class... Us>(bsc::detail::type_list<Us...>) {
            std::size_t u = 0;
            ((view.seen[u++] = address_as<Us>(e)), ...);
        }(typename base::event_types{});
        // clang-format on
        return view;
    }
    template <class U, class E>
    static void const* address_as(E const& e) {
        if constexpr (std::is_same_v<U, E>)
            return &e;
        else if constexpr (std::is_same_v<U, bsc::any_event>)
            return &any_event_value;
        else if constexpr (BSC_DETAIL_IS_BASE_OF(U, E))
            return static_cast<U const*>(&e);
        else
            return nullptr;  // not a family of E: no transition on U takes E
    }
    static constexpr bsc::any_event any_event_value{};

    // Step 2 for one active basic state: its candidates are the transitions on the event (or on
    // a family of it) from the state itself and from each of its ancestors up to the root, in
    // the chart's priority order (tables::order: the state first, or the root first); among
    // those of one origin, declaration order. The first whose guard holds is selected.
    template <class Event>
    bool select_from(state_id leaf, event_id event, Event const& e, selection& sel) {
        return for_each_tried(leaf, tables_type::root, [&](state_id a) {
            for (std::int16_t t = tables_type::first_out[a]; t >= 0;
                 t = tables_type::next_out[static_cast<std::size_t>(t)]) {
                auto const on = transitions[static_cast<std::size_t>(t)].event;
                if (tables_type::takes(on, event) && guard_holds(t, e.as(on))) {
                    sel.add(static_cast<std::size_t>(t));
                    return true;
                }
            }
            return false;
        });
    }

    // Calls try_state(a) for each state a from `from` up to `top` (an ancestor of it, or
    // itself) in the chart's priority order, until one returns true; returns whether one did.
    template <class F>
    static bool for_each_tried(state_id from, state_id top, F&& try_state) {
        if constexpr (tables_type::order == bsc::priority::child_first) {
            for (state_id a = from;; a = states[a].parent) {
                if (try_state(a)) return true;
                if (a == top) return false;
            }
        } else {
            std::array<state_id, tables_type::levels> path{};
            std::size_t n = 0;
            for (state_id a = from;; a = states[a].parent) {
                path[n++] = a;
                if (a == top) break;
            }
            while (n > 0)
                if (try_state(path[--n])) return true;
            return false;
        }
    }

    void run_action(std::int16_t t, void const* e) {
        if constexpr (observed)
            if (auto const h = hooks::on_transition[static_cast<std::size_t>(t)])
                h(this->observer_.value, this->chart(), e);
        if constexpr (base::defers) {
            if (transitions[static_cast<std::size_t>(t)].defers) {  // keeps the event (driver's fire_or_defer)
                this->deferral_selected();
                return;
            }
            this->transition_fired(transitions[static_cast<std::size_t>(t)].to != no_state);
        }
        if (auto const action = transitions[static_cast<std::size_t>(t)].action)
            this->run(action, this->chart(), this->context_.value, e, this->queue_);
    }

    // fire() for a dispatched event: the same as for any other here (the compiled back end puts
    // it in line in the dispatch).
    template <int Trigger, class E>
    bool fire_dispatched(E const& e) {
        return fire<Trigger>(e);
    }
    // Selects and fires the transitions Trigger enables, without settling; true if a
    // transition was selected.
    template <int Trigger, class E>
    bool fire(E const& e) {
        if constexpr (Trigger >= 0 && base::model::has_families)
            return select_and_fire(static_cast<event_id>(Trigger), as_families(e));
        else if constexpr (Trigger >= 0)  // E, or an event the chart does not name, as the trigger's type
            return select_and_fire(
                static_cast<event_id>(Trigger),
                plain_event{
                    address_as<bsc::detail::at<static_cast<std::size_t>(Trigger), typename base::event_types>>(e)});
        else
            return select_and_fire(static_cast<event_id>(Trigger), plain_event{&e});
    }

    // The five steps of the paper's Figure 9 for an event; true if a transition was selected.
    template <class Event>
    bool select_and_fire(event_id event, Event const& e) {
        // 1. Sense the event: an event no transition is triggered by changes nothing.
        if (!tables_type::handles(event)) return false;

        // 2. Determine the transitions: every active basic state, in document order, selects
        //    its first enabled candidate (the event is broadcast to all parallel regions), and
        //    SCXML's conflict resolution keeps some of them.
        selection sel;
        bool any = false;
        for (state_id s = tables_type::root; s < N;) {
            if (!selected(s)) {
                s = states[s].end;
                continue;
            }
            if (is_leaf(s) && select_from(s, event, e, sel)) any = true;
            ++s;
        }
        if (sel.size == 0) return any;
        constexpr auto const& chart_row = tables_type::transition_chart_row;
        using shared_layout = typename base::layout;
        selection const fired = bsc::detail::resolve_conflicts(
            sel,
            [](std::size_t later, std::size_t earlier) {
                return shared_layout::conflict(chart_row[later], chart_row[earlier]);
            },
            [](std::size_t later, std::size_t earlier) {
                return shared_layout::preempts(chart_row[later], chart_row[earlier]);
            });

        // 3. Deactivate the states the transitions leave, running their exit actions.
        for (std::size_t i = fired.size; i-- > 0;) {
            auto const& row = transitions[fired.rows[i]];
            if (row.to != no_state) deactivate_path(row.domain);
        }
        // 4. Perform the transition actions, in selection order.
        for (std::size_t i = 0; i < fired.size; ++i)
            run_action(static_cast<std::int16_t>(fired.rows[i]), e.as(transitions[fired.rows[i]].event));
        // 5. Activate the states they enter, running entry actions, defaults and history.
        for (std::size_t i = 0; i < fired.size; ++i) enter_targets(transitions[fired.rows[i]]);
        return any;
    }

    // ---- the BSC cycle ----------------------------------------------------------------------
    template <int Component>
    bool component_step() {
        return run_component(static_cast<state_id>(Component));
    }

    // One component's turn: from its active frontier (the active basic state below it, or a
    // parallel state whose regions are components of their own) up to the component itself,
    // in the chart's priority order and table order among one origin's, the first
    // condition-driven transition whose condition holds fires.
    bool run_component(state_id component) {
        state_id frontier = component;
        while (states[frontier].status.kind == state_kind::composite) frontier = active_child(frontier);
        return for_each_tried(frontier, component, [&](state_id a) {
            for (std::int16_t t = tables_type::first_out[a]; t >= 0;
                 t = tables_type::next_out[static_cast<std::size_t>(t)])
                if (is_condition(transitions[static_cast<std::size_t>(t)].event) && condition_holds(t)) {
                    fire_condition(first_due(t));
                    return true;
                }
            return false;
        });
    }

    // A timeout's condition: its origin has been active for its delay (the origin is active: it
    // is on the component's active path). Then the guard, which receives bsc::eventless.
    bool condition_holds(std::int16_t t) {
        auto const& row = transitions[static_cast<std::size_t>(t)];
        if constexpr (tables_type::timeout_slots > 0)
            if (row.event == timeout_id && !this->timeout_due(row.timeout_slot, row.delay(this->chart()))) return false;
        return guard_holds(t, &no_event);
    }

    // The transition that fires when condition-driven transition t's condition holds: t, unless
    // it is a timeout and a timeout of the same origin declared after it is due too, came due
    // first (detail::came_due_first) and its guard holds; then the first of those to come due.
    // (The timeouts declared before t did not hold, or t would not be tried.) Only a chart with
    // a state of several timeout rows looks, and only at such a state's timeouts.
    std::int16_t first_due(std::int16_t t) {
        if constexpr (tables_type::competing_timeouts) {
            auto const& row = transitions[static_cast<std::size_t>(t)];
            if (row.event == timeout_id && states[row.from].timeout_slots > 1) {
                std::int16_t first = t;
                int slot = row.timeout_slot;
                duration delay = row.delay(this->chart());
                for (std::int16_t u = tables_type::next_out[static_cast<std::size_t>(t)]; u >= 0;
                     u = tables_type::next_out[static_cast<std::size_t>(u)]) {
                    auto const& other = transitions[static_cast<std::size_t>(u)];
                    if (other.event != timeout_id) continue;
                    duration const u_delay = other.delay(this->chart());
                    if (this->timeout_due(other.timeout_slot, u_delay) &&
                        this->came_due_before(other.timeout_slot, u_delay, slot, delay) && guard_holds(u, &no_event)) {
                        first = u;
                        slot = other.timeout_slot;
                        delay = u_delay;
                    }
                }
                return first;
            }
        }
        return t;
    }

    // Steps 3 to 5 of a microstep for one transition: a component's transition fires alone.
    void fire_condition(std::int16_t t) {
        auto const& row = transitions[static_cast<std::size_t>(t)];
        if (row.to != no_state) deactivate_path(row.domain);
        run_action(t, &no_event);
        enter_targets(row);
        // A timeout that leaves its state active counts again from now (layout.hpp, rearms).
        if constexpr (tables_type::timeout_slots > 0)
            if (row.rearms) this->rearm_timeout(row.timeout_slot);
    }

    // The event that eventless and timeout transitions receive.
    static constexpr bsc::eventless no_event{};
};

// As for bsc::machine: `machine{chart, ...}` and `machine<decltype(chart)>` name the same type.
// A machine of a chart that failed its checks does nothing (detail/runtime/rejected.hpp).
template <statechart Chart, machine_policy Policy, class Observer>
    requires bsc::detail::rejected<Chart>
class machine<Chart, Policy, Observer> : public bsc::detail::inert_machine<Chart> {
public:
    using bsc::detail::inert_machine<Chart>::inert_machine;
};

template <class C, class... A>
machine(C const&, A...) -> machine<C const, default_policy, bsc::detail::observer_argument_t<A...>>;

}  // namespace bsc::table
// end include/bsc/table/machine.hpp
// begin include/bsc/version.hpp
// The version of bsc. CMakeLists.txt reads its project version from these three lines, so that
// the header, the CMake package (bscConfigVersion.cmake) and the CHANGELOG name one version.

#define BSC_VERSION_MAJOR 0
#define BSC_VERSION_MINOR 2
#define BSC_VERSION_PATCH 0

/// The version as one number, major * 10000 + minor * 100 + patch (as fmt's FMT_VERSION), for
/// `#if BSC_VERSION >= 200`.
#define BSC_VERSION (BSC_VERSION_MAJOR * 10000 + BSC_VERSION_MINOR * 100 + BSC_VERSION_PATCH)
// end include/bsc/version.hpp
// end include/bsc/bsc.hpp
