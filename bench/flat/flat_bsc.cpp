// Workload flat, bsc: the compiled back end (bsc::machine) and the table-driven back end
// (bsc::table::machine) on the generated chart of flat/flat_chart_bsc.hpp.
//
// Built twice, each a translation unit of its own so that their compile times are measured apart
// (docs/benchmarks.md): as itself, the compiled back end; included by flat_bsc_table.cpp with
// BENCH_BSC_TABLE defined, the table-driven back end. The compiled machine names its chart with
// bsc::chart_ref, as docs/api.md recommends.

#include <bsc/bsc.hpp>
#if defined(BENCH_BSC_TABLE)
#include <bsc/table/machine.hpp>
#endif

#include "flat_chart_bsc.hpp"
#include "flat_workload.hpp"

namespace {

constexpr std::size_t N = flat_bench::workload::states;
constexpr auto const& chart = flat_bsc::chart<N>;

template <class Machine>
class flat_machine {
public:
    void on(std::uint8_t event) {
        bench::with_index<N>(event, [&](auto i) { m_.dispatch(flat_bsc::E<decltype(i)::value>{}); });
    }

    flat_bench::workload::observation observe() const {
        std::size_t state = 0;
        bench::with_index<1>(0, [&](auto) {
            // clang-format off
            [&]<std::size_t... I>(std::index_sequence<I...>) {
                ((m_.template is<flat_bsc::S<I>>() ? (void)(state = I) : (void)0), ...);
            }(std::make_index_sequence<N>{});
            // clang-format on
        });
        return {state, m_.context().count};
    }

private:
    Machine m_{chart};
};

using compiled = bsc::machine<bsc::chart_ref<flat_bsc::chart<N>>, bench::bsc_policy>;  // bench/bsc_variant.hpp
#if defined(BENCH_BSC_TABLE)
using table = decltype(bsc::table::machine{chart});
#endif

}  // namespace

#if defined(BENCH_BSC_TABLE)
BENCH_IMPL(flat_bench::workload, "bsc_table", flat_machine<table>);
#else
BENCH_IMPL(flat_bench::workload, "bsc_compiled", flat_machine<compiled>);
#endif
