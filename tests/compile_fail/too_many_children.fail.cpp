// EXPECT: defect=too_many_children<cf::Root>
// Root has 256 children, S<0> to S<255>; a composite's active child is kept in one byte.
#include <bsc/bsc.hpp>

#include <utility>

namespace cf {
struct go {};
struct Root;
template <int I>
struct S;
struct ctx {};

// Root(initial S<0>, S<1>, ..., S<N>), with S<i> -go-> S<i+1> and S<N> -go-> S<0>.
template <int... I>
constexpr auto ring(std::integer_sequence<int, I...>) {
    constexpr int last = static_cast<int>(sizeof...(I));
    return bsc::make_chart<ctx>(bsc::composite<Root>(bsc::initial<S<0>>, bsc::state<S<I + 1>>...),
                                bsc::state<S<I>> + bsc::event<go> = bsc::state<S<I + 1>>...,
                                bsc::state<S<last>> + bsc::event<go> = bsc::state<S<0>>);
}

inline constexpr auto chart = ring(std::make_integer_sequence<int, 255>{});
}  // namespace cf
