// Workload fsmb_deep, bsc: the chart of fsmb_deep_workload.hpp, generated with templates, on the
// compiled back end; the completions are bsc::done events of the composites.

#include <bsc/bsc.hpp>
#include <type_traits>

#include "../bsc_variant.hpp"
#include "fsmb_deep_workload.hpp"

namespace {

namespace deep {
struct Root;
template <int X>
struct lvl0 {};
template <int X>
struct done0 {};  // lvl0_x's final state
template <int X, int Y>
struct lvl1 {};
template <int X, int Y>
struct done1 {};  // lvl1_xy's final state
template <int X, int Y, int Z>
struct lvl2 {};
template <int K>
struct event {};  // the event of basic state 9x + 3y + z
struct context {
    std::uint64_t counter = 0;
};

// (noexcept: bench/bsc_variant.hpp.)
template <int X, int Y, int Z>
inline constexpr auto leave = [](context& c) noexcept(BENCH_NOEXCEPT_ACTIONS) { c.counter += X + Y + Z + 1; };

template <int X, int Y>
constexpr auto level1() {
    return bsc::composite<lvl1<X, Y>>(bsc::initial<lvl2<X, Y, 0>>, bsc::state<lvl2<X, Y, 1>>, bsc::state<lvl2<X, Y, 2>>,
                                      bsc::final_state<done1<X, Y>>);
}
template <int X>
constexpr auto level0() {
    return bsc::composite<lvl0<X>>(bsc::initial<lvl1<X, 0>>, level1<X, 0>(), level1<X, 1>(), level1<X, 2>(),
                                   bsc::final_state<done0<X>>);
}

// The rows of basic state xyz: its event (to the next basic state, or the final state after the
// last), and its exit action.
template <int X, int Y, int Z>
constexpr auto leaf_rows() {
    using next = std::conditional_t<(Z < 2), lvl2<X, Y, Z + 1>, done1<X, Y>>;
    return bsc::rows(bsc::state<lvl2<X, Y, Z>> + bsc::event<event<9 * X + 3 * Y + Z>> = bsc::state<next>,
                     bsc::state<lvl2<X, Y, Z>> + bsc::on_exit / leave<X, Y, Z>);
}
// The completion of lvl1_xy (to the next, or the final state after the last), and its children's rows.
template <int X, int Y>
constexpr auto level1_rows() {
    using next = std::conditional_t<(Y < 2), lvl1<X, Y + 1>, done0<X>>;
    return bsc::rows(bsc::state<lvl1<X, Y>> + bsc::event<bsc::done<lvl1<X, Y>>> = bsc::state<next>,
                     leaf_rows<X, Y, 0>(), leaf_rows<X, Y, 1>(), leaf_rows<X, Y, 2>());
}
template <int X>
constexpr auto level0_rows() {
    return bsc::rows(bsc::state<lvl0<X>> + bsc::event<bsc::done<lvl0<X>>> = bsc::state<lvl0<(X + 1) % 3>>,
                     level1_rows<X, 0>(), level1_rows<X, 1>(), level1_rows<X, 2>());
}

inline constexpr auto chart = bsc::make_chart<context>(
    bsc::composite<Root>(bsc::initial<lvl0<0>>, level0<0>(), level0<1>(), level0<2>()), level0_rows<0>(),
    level0_rows<1>(), level0_rows<2>());
}  // namespace deep

class deep_machine {
public:
    void on(std::uint8_t e) {
        bench::with_index<fsmb_deep_bench::workload::leaves>(
            e, [&](auto k) { m_.dispatch(deep::event<static_cast<int>(decltype(k)::value)>{}); });
    }
    fsmb_deep_bench::workload::observation observe() const {
        std::size_t leaf = 0;
        // clang-format off
        [&]<int... K>(std::integer_sequence<int, K...>) {
            ((m_.is<deep::lvl2<K / 9, K / 3 % 3, K % 3>>() ? (void)(leaf = K) : (void)0), ...);
        }(std::make_integer_sequence<int, static_cast<int>(fsmb_deep_bench::workload::leaves)>{});
        // clang-format on
        return {leaf, m_.context().counter};
    }

private:
    bsc::machine<bsc::chart_ref<deep::chart>, bench::bsc_policy> m_{deep::chart};
};

}  // namespace

BENCH_IMPL(fsmb_deep_bench::workload, "bsc_compiled", deep_machine);
