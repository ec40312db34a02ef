// EXPECT: defect=dead_end_state<cf::Estop>
// Estop's only transition re-enters Estop: the machine can never come out (the machine-tool
// paper [MCS] in docs/references.md, Figure 5).
#include <bsc/bsc.hpp>

namespace cf {
struct estop_p {};
struct reset_p {};
struct Root;
struct On;
struct Estop;
struct ctx {
    int error = 0;
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<On>, bsc::state<Estop>),
    bsc::state<On> + bsc::event<estop_p> / [](ctx& c) { c.error = 1; } = bsc::state<Estop>,
    bsc::state<Estop> + bsc::event<reset_p> / [](ctx& c) { c.error = 0; } = bsc::state<Estop>);
}  // namespace cf
