// Workload wide, bsc: the chart of wide/wide_workload.hpp, generated with templates, run by
// the compiled back end (bsc::machine) and the table-driven back end (bsc::table::machine).
//
// Built twice, each a translation unit of its own so that their compile times are measured apart
// (docs/benchmarks.md): as itself, the compiled back end; included by wide_bsc_table.cpp with
// BENCH_BSC_TABLE defined, the table-driven back end. The compiled machine names its chart with
// bsc::chart_ref, as docs/api.md recommends.

#include <bsc/bsc.hpp>
#if defined(BENCH_BSC_TABLE)
#include <bsc/table/machine.hpp>
#endif

#include "../bsc_variant.hpp"
#include "wide_workload.hpp"

namespace {

using namespace wide_bench;

struct W;
template <int R>
struct G {};
template <int R, int J>
struct A {};
struct step {};
struct reset {};
struct flip {};

struct counters {
    std::array<std::uint64_t, regions> n{};
};

// The actions' noexcept and the machine's policy: bench/bsc_variant.hpp.
template <int R, int V>
inline constexpr auto add = [](counters& c) noexcept(BENCH_NOEXCEPT_ACTIONS) { c.n[R] += V; };

template <int R>
constexpr auto region() {
    return bsc::composite<G<R>>(bsc::initial<A<R, initial_of(R)>>, bsc::state<A<R, (initial_of(R) + 1) % 3>>,
                                bsc::state<A<R, (initial_of(R) + 2) % 3>>);
}

template <int R>
constexpr auto rows() {
    return bsc::rows(bsc::state<A<R, 0>> + bsc::event<step> / add<R, 1> = bsc::state<A<R, 1>>,
                     bsc::state<A<R, 1>> + bsc::event<step> / add<R, 1> = bsc::state<A<R, 2>>,
                     bsc::state<A<R, 2>> + bsc::event<step> / add<R, 1> = bsc::state<A<R, 0>>,
                     bsc::state<A<R, 1>> + bsc::event<reset> / add<R, 16> = bsc::state<A<R, 0>>,
                     bsc::state<A<R, 2>> + bsc::event<reset> / add<R, 16> = bsc::state<A<R, 0>>,
                     bsc::state<A<R, 0>> + bsc::event<flip> / add<R, 4> = bsc::state<A<R, flip_target(R)>>);
}

template <int... R>
constexpr auto make_chart(std::integer_sequence<int, R...>) {
    return bsc::make_chart<counters>(bsc::parallel<W>(region<R>()...), rows<R>()...);
}

inline constexpr auto chart = make_chart(std::make_integer_sequence<int, int(regions)>{});

template <class Machine>
class wide_machine {
public:
    void on(std::uint8_t event) {
        switch (event) {
        case 0: m_.dispatch(step{}); break;
        case 1: m_.dispatch(reset{}); break;
        default: m_.dispatch(flip{}); break;
        }
    }
    workload::observation observe() const {
        workload::observation o{{}, m_.context().n};
        // clang-format off
        [&]<int... R>(std::integer_sequence<int, R...>) {
            ((o.state[R] = m_.template is<A<R, 0>>() ? 0 : m_.template is<A<R, 1>>() ? 1 : 2), ...);
        }(std::make_integer_sequence<int, int(regions)>{});
        // clang-format on
        return o;
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
BENCH_IMPL(wide_bench::workload, "bsc_table", wide_machine<table>);
#else
BENCH_IMPL(wide_bench::workload, "bsc_compiled", wide_machine<compiled>);
#endif
