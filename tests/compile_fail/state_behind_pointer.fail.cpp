// EXPECT: defect=state_out_of_reach<cf::ctx, member_number<0>, bsc::timer ?\*>
// The context points to a timer: the machine does not follow pointers, so it would never update it.
#include <bsc/bsc.hpp>
#include <chrono>

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Heating;
struct ctx {
    bsc::timer* heat_timer = nullptr;
    int cycles = 0;
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Heating>),
    bsc::state<Idle> + bsc::event<go> / [](ctx& c) { c.heat_timer->start(); } = bsc::state<Heating>,
    bsc::state<Heating>[([](ctx const& c) { return c.heat_timer->tm(); })] = bsc::state<Idle>);
}  // namespace cf

bool run() {
    bsc::timer t{std::chrono::seconds{2}};
    bsc::machine m{cf::chart, cf::ctx{&t}};
    m.dispatch(cf::go{});
    return m.is<cf::Heating>();
}
