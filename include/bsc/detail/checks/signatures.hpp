#pragma once
// Guards and actions that cannot be called, found where the chart is declared so that the
// error names the row they belong to (bsc::error::in_row) instead of surfacing later inside a
// machine's dispatch. A guard is called as g(context const&, event const&), g(context const&)
// or g(); an action as a(context&, event const&, raise&), a(context&, event const&), a(context&)
// or a(); an entry or exit action as a(context&, raise&), a(context&) or a() (the predicates of
// detail/invoke.hpp, which calls them so). Guards and actions combined with bsc::guard and bsc::action (!, &&, ||, the
// comma) are checked part by part; a callable of another kind is left to the machine.

#include <type_traits>

#include <bsc/detail/invoke.hpp>
#include <bsc/detail/meta.hpp>
#include <bsc/dsl/action.hpp>
#include <bsc/dsl/guard.hpp>
#include <bsc/dsl/named.hpp>
#include <bsc/dsl/row.hpp>
#include <bsc/error.hpp>

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
