// EXPECT: defect=output_written_from_outside<bool>
// The environment writes the chart's output, which only the chart's actions write.
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
    bsc::state<Off>[([](io const& c) { return c.in.get(); })] / [](io& c) { c.out.set(true); } = bsc::state<On>,
    bsc::state<On>[([](io const& c) { return !c.in.get(); })] / [](io& c) { c.out.set(false); } = bsc::state<Off>);

inline bool run() {
    bsc::machine<bsc::chart_ref<chart>> m{chart};
    m.context().out.set(true);
    m.step(bsc::duration{});
    return m.is<On>();
}
}  // namespace cf
