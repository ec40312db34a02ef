// EXPECT: defect=input_not_driven<&cf::actors::first, member_number<0>
// Nothing drives the first relay's input: no link, and no bsc::from_outside entry.
#include <bsc/bsc.hpp>

namespace cf {
struct Root;
struct Off;
struct On;
// A relay: its output follows its input.
struct io {
    bsc::input<bool> in;
    bsc::output<bool> out;
    bsc::output<int> count;
};
inline constexpr auto relay = bsc::make_chart<io>(
    bsc::composite<Root>(bsc::initial<Off>, bsc::state<On>),
    bsc::state<Off>[([](io const& c) { return c.in.get(); })] / [](io& c) { c.out.set(true); } = bsc::state<On>,
    bsc::state<On>[([](io const& c) { return !c.in.get(); })] / [](io& c) { c.out.set(false); } = bsc::state<Off>);
struct actors {
    bsc::machine<bsc::chart_ref<relay>> first{relay};
    bsc::machine<bsc::chart_ref<relay>> second{relay};
};
using chain = bsc::system<actors, bsc::order<&actors::first, &actors::second>,
                          bsc::link<&actors::first, &io::out, &actors::second, &io::in>>;

inline int run() {
    chain s{};
    return s.step(bsc::duration{}).transitions;
}
}  // namespace cf
