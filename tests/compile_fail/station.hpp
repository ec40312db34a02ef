#pragma once
// The states and events of the compile-fail tests about priority among nested transitions
// (bsc/priority.hpp): a filling station whose outer state Normal and inner state Filling take the
// same events. Each test declares its own rows on this tree.
#include <bsc/bsc.hpp>

namespace cf {
struct bottle {};
struct fault {};
struct overheat : fault {};
struct estop {
    bool latched = true;
};
struct reset {};
struct Station;
struct Normal;
struct Idle;
struct Filling;
struct EStop;
struct ctx {
    bool hot = false;
};

inline constexpr auto station = bsc::composite<Station>(
    bsc::initial<Normal>, bsc::composite<Normal>(bsc::initial<Idle>, bsc::state<Idle>, bsc::state<Filling>),
    bsc::state<EStop>);
}  // namespace cf
