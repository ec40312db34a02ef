// The Mode Control Supervisor as a bsc machine under bsc::lean_policy.

#define CORTEX_M_LEAN 1
#include "mcs_bsc.cpp"
