// EXPECT: defect=eventless_livelock<cf::A>
// Child first, A and B, in a region of P, take their unguarded eventless rows before P's own:
// the region cycles between them (region_cycle.hpp).
#include "region_cycle.hpp"

inline constexpr auto chart = cf::region_cycle<bsc::child_first>();
