// The Mode Control Supervisor (mcs_supervisor.hpp) as a bsc machine of examples/mcs's chart,
// under bsc::default_policy, or under bsc::lean_policy when built as mcs_lean.cpp.

#include "mcs_supervisor.hpp"

#if defined(CORTEX_M_LEAN)
using policy = bsc::lean_policy;
#else
using policy = bsc::default_policy;
#endif

bsc::machine<bsc::chart_ref<mcs::chart>, policy> subject{mcs::chart};

int main(int argc, char** argv) {
    return cm::run_events<supervisor::workload, supervisor::bsc_adapter<subject>>(argc, argv);
}
