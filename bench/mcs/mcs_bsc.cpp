// Workload mcs, bsc: the chart of examples/mcs/mcs.hpp run by the compiled back end
// (bsc::machine) and by the table-driven back end (bsc::table::machine).
//
// Built twice, each a translation unit of its own so that their compile times are measured apart
// (docs/benchmarks.md): as itself, the compiled back end; included by mcs_bsc_table.cpp with
// BENCH_BSC_TABLE defined, the table-driven back end. The compiled machine names its chart with
// bsc::chart_ref, as docs/api.md recommends.

#include <bsc/bsc.hpp>
#if defined(BENCH_BSC_TABLE)
#include <bsc/table/machine.hpp>
#endif

#include "../../examples/mcs/mcs.hpp"
#include "mcs_buttons.hpp"
#include "mcs_workload.hpp"

namespace {

using namespace mcs_bench;

template <class Machine>
class supervisor {
public:
    void on(std::uint8_t event) {
        bench::with_index<event_count>(
            event, [&](auto i) { m_.dispatch(typename mcs_bench::button_at<decltype(i)::value>::type{}); });
    }

    workload::observation observe() const {
        return workload::observe(active(), m_.context().error, m_.context().display);
    }

private:
    leaf active() const {
        if (m_.template is<mcs::Off>()) return leaf::Off;
        if (m_.template is<mcs::Estop>()) return leaf::Estop;
        if (m_.template is<mcs::Mem>()) return leaf::Mem;
        if (m_.template is<mcs::Mdi>()) return leaf::Mdi;
        if (m_.template is<mcs::Tape>()) return leaf::Tape;
        if (m_.template is<mcs::Handle>()) return leaf::Handle;
        if (m_.template is<mcs::Jog>()) return leaf::Jog;
        if (m_.template is<mcs::Rpd>()) return leaf::Rpd;
        if (m_.template is<mcs::Zrn>()) return leaf::Zrn;
        if (m_.template is<mcs::Edit>()) return leaf::Edit;
        return leaf::Setup;
    }

    Machine m_{mcs::chart};
};

using compiled = bsc::machine<bsc::chart_ref<mcs::chart>>;
#if defined(BENCH_BSC_TABLE)
using table = decltype(bsc::table::machine{mcs::chart});
#endif

}  // namespace

#if defined(BENCH_BSC_TABLE)
BENCH_IMPL(mcs_bench::workload, "bsc_table", supervisor<table>);
#else
BENCH_IMPL(mcs_bench::workload, "bsc_compiled", supervisor<compiled>);
#endif
