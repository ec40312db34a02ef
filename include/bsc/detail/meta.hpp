#pragma once
// Small type-level toolkit: type lists, lookup by type and by position.
// Everything heavier than this is done by constexpr functions over arrays.

#include <cstddef>
#include <type_traits>
#include <utility>

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
// instantiation per element, so n lookups in a list of n cost O(n), not O(n^2).
template <class T, std::size_t I>
constexpr std::size_t position_by_type(indexed<I, T> const*) {
    return I;
}

template <class List>
struct indexer_of;
template <class... Ts>
struct indexer_of<type_list<Ts...>> {
    using type = indexer<std::index_sequence_for<Ts...>, Ts...>;
};

// Position of the first T in List, or -1. Instantiated with the list as one type, so that n
// lookups in a list of n do not each spell out the n elements.
template <class T, class List>
constexpr int index_of_impl() {
    using index = typename indexer_of<List>::type;
    if constexpr (requires { position_by_type<T>(static_cast<index const*>(nullptr)); }) {
        return static_cast<int>(position_by_type<T>(static_cast<index const*>(nullptr)));
    } else {  // absent, or present more than once (the base is ambiguous): scan
        return []<class... Ts>(type_list<Ts...>) {
            constexpr bool same[] = {std::is_same_v<T, Ts>..., false};
            for (std::size_t i = 0; i < sizeof...(Ts); ++i)
                if (same[i])
                    return static_cast<int>(i);
            return -1;
        }(List{});
    }
}
template <class T, class List>
inline constexpr int index_of = index_of_impl<T, List>();

// Position of the first T in Ts..., or -1.
template <class T, class... Ts>
constexpr int index_in() {
    return index_of<T, type_list<Ts...>>;
}

template <std::size_t I, class List>
struct at_impl;
template <std::size_t I, class... Ts>
struct at_impl<I, type_list<Ts...>> {
    using type = typename decltype(select_indexed<I>(indexer<std::index_sequence_for<Ts...>, Ts...>{}))::type;
};
template <std::size_t I, class List>
using at = typename at_impl<I, List>::type;

template <int I>
using int_c = std::integral_constant<int, I>;

// Calls f(int_c<I>) for the I in [0, N) equal to i; compilers turn the chain into a jump table.
template <int N, class F, int... Is>
constexpr void visit_index_impl(int i, F& f, std::integer_sequence<int, Is...>) {
    (void)((i == Is ? (f(int_c<Is>{}), true) : false) || ...);
}
template <int N, class F>
constexpr void visit_index(int i, F&& f) {
    visit_index_impl<N>(i, f, std::make_integer_sequence<int, N>{});
}

}  // namespace bsc::detail
