// Workload sml_complex, bsc: the ring of sml_complex_workload.hpp, generated with templates, on
// the compiled back end.

#include <bsc/bsc.hpp>

#include "../bsc_variant.hpp"
#include "sml_complex_workload.hpp"

namespace {

namespace ring {
constexpr std::size_t N = sml_complex_bench::workload::states;
struct Ring;
template <std::size_t K>
struct S {};
template <std::size_t K>
struct E {};
struct none {};

// As in Boost.SML's benchmark: a guard that holds, an action that does nothing.
inline constexpr auto holds = []() noexcept(BENCH_NOEXCEPT_ACTIONS) { return true; };
inline constexpr auto nothing = []() noexcept(BENCH_NOEXCEPT_ACTIONS) {};

template <std::size_t... Others, std::size_t... K>
constexpr auto make_chart(std::index_sequence<Others...>, std::index_sequence<K...>) {
    return bsc::make_chart<none>(
        bsc::composite<Ring>(bsc::initial<S<0>>, bsc::state<S<Others + 1>>...),
        (bsc::state<S<K>> + bsc::event<E<K>>[holds] / nothing = bsc::state<S<(K + 1) % N>>)...);
}
inline constexpr auto chart = make_chart(std::make_index_sequence<N - 1>{}, std::make_index_sequence<N>{});
}  // namespace ring

class ring_machine {
public:
    void on(std::uint8_t e) {
        bench::with_index<ring::N>(e, [&](auto k) { m_.dispatch(ring::E<decltype(k)::value>{}); });
    }
    sml_complex_bench::workload::observation observe() const {
        std::size_t state = 0;
        // clang-format off
        [&]<std::size_t... K>(std::index_sequence<K...>) {
            ((m_.is<ring::S<K>>() ? (void)(state = K) : (void)0), ...);
        }(std::make_index_sequence<ring::N>{});
        // clang-format on
        return {state};
    }

private:
    bsc::machine<bsc::chart_ref<ring::chart>, bench::bsc_policy> m_{ring::chart};
};

}  // namespace

BENCH_IMPL(sml_complex_bench::workload, "bsc_compiled", ring_machine);
