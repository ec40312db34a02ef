#pragma once
// Small type-level toolkit: type lists, lookup by type and by position.
// Everything heavier than this is done by constexpr functions over arrays.

#include <cstddef>
#include <initializer_list>
#include <type_traits>
#include <utility>

#include <bsc/detail/config.hpp>

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
