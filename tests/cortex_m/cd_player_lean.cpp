// The CD player as a bsc machine under bsc::lean_policy.

#define CORTEX_M_LEAN 1
#include "cd_player_bsc.cpp"
