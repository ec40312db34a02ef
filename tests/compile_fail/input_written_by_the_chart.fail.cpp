// EXPECT: defect=input_written_by_the_chart<bool>
// An action writes the chart's own input, which only the environment writes.
#include <bsc/bsc.hpp>

namespace cf {
struct Root;
struct Off;
struct On;
struct io {
    bsc::input<bool> in;
    bsc::output<bool> out;
};

inline constexpr auto chart = bsc::make_chart<io>(
    bsc::composite<Root>(bsc::initial<Off>, bsc::state<On>),
    bsc::state<Off>[([](io const& c) { return c.in.get(); })] / [](io& c) { c.in.set(false); } = bsc::state<On>,
    bsc::state<On>[([](io const& c) { return !c.in.get(); })] = bsc::state<Off>);
}  // namespace cf
