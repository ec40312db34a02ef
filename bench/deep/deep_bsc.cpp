// Workload deep, bsc: the chart of deep/deep_workload.hpp, generated with templates, run by
// the compiled back end (bsc::machine) and the table-driven back end (bsc::table::machine).
//
// Built twice, each a translation unit of its own so that their compile times are measured apart
// (docs/benchmarks.md): as itself, the compiled back end; included by deep_bsc_table.cpp with
// BENCH_BSC_TABLE defined, the table-driven back end. The compiled machine names its chart with
// bsc::chart_ref, as docs/api.md recommends.

#include <bsc/bsc.hpp>
#if defined(BENCH_BSC_TABLE)
#include <bsc/table/machine.hpp>
#endif

#include "../bsc_variant.hpp"
#include "deep_workload.hpp"

namespace {

struct R;
template <int K>
struct D {};
template <int K>
struct P {};
template <int K>
struct L {};

struct counters {
    std::uint64_t count = 0;
    std::uint64_t entries = 0;
};

// The actions' noexcept and the machine's policy: bench/bsc_variant.hpp.
template <int K>
inline constexpr auto leave =
    [](counters& c) noexcept(BENCH_NOEXCEPT_ACTIONS) { c.count += static_cast<std::uint64_t>(K); };
template <int K>
inline constexpr auto come_back =
    [](counters& c) noexcept(BENCH_NOEXCEPT_ACTIONS) { c.count += 100u * static_cast<std::uint64_t>(K); };
inline constexpr auto entered = [](counters& c) noexcept(BENCH_NOEXCEPT_ACTIONS) { ++c.entries; };

template <int K>
constexpr auto level() {
    if constexpr (K == 8)
        return bsc::state<D<8>>;
    else
        return bsc::composite<D<K>>(bsc::initial<D<K + 1>>, level<K + 1>(), bsc::state<P<K + 1>>);
}

template <int... K>
constexpr auto make_chart(std::integer_sequence<int, K...>) {
    return bsc::make_chart<counters, bench::priority>(  // child first, or parent first (bench/bsc_variant.hpp)
        bsc::composite<R>(bsc::initial<D<1>>, level<1>(), bsc::state<P<1>>),
        (bsc::state<D<K + 1>> + bsc::on_entry / entered)...,
        (bsc::state<D<K + 1>> + bsc::event<L<K + 1>> / leave<K + 1> = bsc::state<P<K + 1>>)...,
        (bsc::state<P<K + 1>> + bsc::event<L<K + 1>> / come_back<K + 1> = bsc::state<D<K + 1>>)...);
}

inline constexpr auto chart = make_chart(std::make_integer_sequence<int, 8>{});

template <class Machine>
class deep_machine {
public:
    void on(std::uint8_t event) {
        bench::with_index<deep_bench::levels>(event, [&](auto i) { m_.dispatch(L<int(decltype(i)::value) + 1>{}); });
    }
    deep_bench::workload::observation observe() const {
        int depth = 8;
        // clang-format off
        [&]<int... K>(std::integer_sequence<int, K...>) {
            ((m_.template is<P<K + 1>>() ? (void)(depth = K) : (void)0), ...);
        }(std::make_integer_sequence<int, 8>{});
        // clang-format on
        return {depth, m_.context().count, m_.context().entries};
    }

private:
    Machine m_{chart};
};

using compiled = bsc::machine<bsc::chart_ref<chart>, bench::bsc_policy>;  // bench/bsc_variant.hpp
#if defined(BENCH_BSC_TABLE)
using table = decltype(bsc::table::machine{chart});
#endif

}  // namespace

#if defined(BENCH_BSC_TABLE)
BENCH_IMPL(deep_bench::workload, "bsc_table", deep_machine<table>);
#else
BENCH_IMPL(deep_bench::workload, "bsc_compiled", deep_machine<compiled>);
#endif
