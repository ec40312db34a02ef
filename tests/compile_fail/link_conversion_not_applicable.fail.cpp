// EXPECT: defect=link_conversion_not_applicable<bsc::convert<
// The link's conversion takes a string, and the source publishes an int.
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
inline constexpr auto positive = [](int n) { return n > 0; };
inline constexpr auto named = [](char const* name) { return name != nullptr; };
using chain =
    bsc::system<actors, bsc::order<&actors::first, &actors::second>, bsc::from_outside<&actors::first, &io::in>,
                bsc::link<&actors::first, &io::count, &actors::second, &io::in, bsc::convert<named>>>;

inline int run() {
    chain s{};
    return s.step(bsc::duration{}).transitions;
}
}  // namespace cf
