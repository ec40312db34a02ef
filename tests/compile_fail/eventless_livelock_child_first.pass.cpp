// The twin: parent first, P's unguarded eventless row is tried before those of A and B in every
// configuration, so the machine leaves P for Done and no eventless cycle can run.
#include "region_cycle.hpp"

inline constexpr auto chart = cf::region_cycle<bsc::parent_first>();
