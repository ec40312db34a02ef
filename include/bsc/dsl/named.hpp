#pragma once
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

#include <bsc/detail/fixed_string.hpp>
#include <bsc/detail/invoke.hpp>
#include <bsc/dsl/action.hpp>
#include <bsc/dsl/guard.hpp>

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
