#pragma once
// bsc::duration: the machine's notion of time. The library never reads a clock: time is given
// to step(now) by the caller, so simulations and tests are deterministic.

#include <chrono>

namespace bsc {

/// A duration since an origin the caller chooses, as given to step(now).
using duration = std::chrono::nanoseconds;

}  // namespace bsc
