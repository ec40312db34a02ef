#pragma once
// bsc::allow: a chart's explicit allowance of findings of the static checks that it accepts by
// design, as a chart compiled from an SCXML document does (SCXML accepts states never entered
// and transitions that never fire).

#include <cstddef>

#include <bsc/detail/meta.hpp>
#include <bsc/error.hpp>

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
