#pragma once
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

#include <bsc/data/channel.hpp>
#include <bsc/data/timer.hpp>
#include <bsc/detail/chrono.hpp>
#include <bsc/detail/config.hpp>
#include <bsc/detail/fields.hpp>
#include <bsc/detail/machine_base.hpp>
#include <bsc/detail/member_names.hpp>
#include <bsc/detail/meta.hpp>
#include <bsc/error.hpp>
#include <bsc/fields.hpp>
#include <bsc/transient.hpp>

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
