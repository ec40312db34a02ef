// The CD player (cd_player.hpp) as a bsc machine, under bsc::default_policy, or under
// bsc::lean_policy when built as cd_player_lean.cpp.

#include "cd_player.hpp"

#if defined(CORTEX_M_LEAN)
using policy = bsc::lean_policy;
#else
using policy = bsc::default_policy;
#endif

bsc::machine<bsc::chart_ref<cd::chart>, policy> subject{cd::chart};

int main(int argc, char** argv) { return cm::run_events<cd::workload, cd::bsc_adapter<subject>>(argc, argv); }
