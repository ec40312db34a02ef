// EXPECT: defect=chart_ref_from_another_chart
// A machine of chart_ref<fast> runs the chart `fast` itself, whatever it is built from: built
// from `slow`, a chart of the same type with another delay, it would silently run `fast`.
#include <bsc/bsc.hpp>

#include <chrono>

using namespace std::chrono_literals;

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Busy;
struct ctx {};

constexpr auto chart_with(bsc::duration delay) {
    return bsc::make_chart<ctx>(bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
                                bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
                                bsc::state<Busy> + bsc::after(delay) = bsc::state<Idle>);
}
inline constexpr auto fast = chart_with(1ms);
inline constexpr auto slow = chart_with(1s);
}  // namespace cf

int main() {
    bsc::machine<bsc::chart_ref<cf::fast>> m{cf::slow};
    return m.is<cf::Idle>() ? 0 : 1;
}
