// Workload fsmb_large, bsc: the chart of fsmb_large_workload.hpp, generated with templates, on
// the compiled back end; the exit actions raise ievent with bsc::raise.

#include <bsc/bsc.hpp>

#include "../bsc_variant.hpp"
#include "fsmb_large_workload.hpp"

namespace {

namespace large {
constexpr std::size_t N = fsmb_large_bench::workload::states;
struct Large;
template <std::size_t K>
struct state {};
template <std::size_t K>
struct sevent {
    int two = 2;
};
struct ievent {
    int two = 2;
};
struct context {
    int counter = 0;
};

// (noexcept: bench/bsc_variant.hpp.)
inline constexpr auto two_positive = [](context const&, auto const& e) noexcept(BENCH_NOEXCEPT_ACTIONS) {
    return e.two >= 0;
};
inline constexpr auto grow = [](context& c, auto const& e) noexcept(BENCH_NOEXCEPT_ACTIONS) {
    c.counter = (c.counter + 1) * e.two;
};
inline constexpr auto halve = [](context& c, ievent const& e) noexcept(BENCH_NOEXCEPT_ACTIONS) { c.counter /= e.two; };

template <std::size_t... Others, std::size_t... K>
constexpr auto make_chart(std::index_sequence<Others...>, std::index_sequence<K...>) {
    return bsc::make_chart<context>(
        bsc::composite<Large>(bsc::initial<state<0>>, bsc::state<state<Others + 1>>...),
        (bsc::state<state<K>> + bsc::event<sevent<K>>[two_positive] / grow = bsc::state<state<(K + 1) % N>>)...,
        (bsc::state<state<K>> + bsc::event<ievent> / halve)...,
        (bsc::state<state<K>> + bsc::on_exit / bsc::raise(ievent{}))...);
}
inline constexpr auto chart = make_chart(std::make_index_sequence<N - 1>{}, std::make_index_sequence<N>{});
}  // namespace large

class large_machine {
public:
    void on(std::uint8_t e) {
        bench::with_index<large::N>(e, [&](auto k) { m_.dispatch(large::sevent<decltype(k)::value>{}); });
    }
    fsmb_large_bench::workload::observation observe() const {
        std::size_t state = 0;
        // clang-format off
        [&]<std::size_t... K>(std::index_sequence<K...>) {
            ((m_.is<large::state<K>>() ? (void)(state = K) : (void)0), ...);
        }(std::make_index_sequence<large::N>{});
        // clang-format on
        return {state, m_.context().counter};
    }

private:
    bsc::machine<bsc::chart_ref<large::chart>, bench::bsc_policy> m_{large::chart};
};

}  // namespace

BENCH_IMPL(fsmb_large_bench::workload, "bsc_compiled", large_machine);
