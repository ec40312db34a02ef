// The twin of chart_ref_from_another_chart.fail.cpp: each machine is built from the chart its
// type names, and runs it (the fast one's timeout fires after 1 ms, the slow one's does not).
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
    bsc::machine<bsc::chart_ref<cf::fast>, bsc::scan_policy> f{cf::fast};
    bsc::machine<bsc::chart_ref<cf::slow>, bsc::scan_policy> s{cf::slow};
    f.dispatch(cf::go{});
    s.dispatch(cf::go{});
    f.step(0ms);
    s.step(0ms);
    f.step(2ms);
    s.step(2ms);
    return f.is<cf::Idle>() && s.is<cf::Busy>() ? 0 : 1;
}
