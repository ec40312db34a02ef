// Twin of event_not_constructible.fail.cpp: a decoder builds cf::speed from the message.
#include <bsc/bsc.hpp>

#include <type_traits>

namespace cf {
struct go {};
struct speed {
    explicit speed(int v) : value(v) {}
    int value;
};
struct Root;
struct Idle;
struct Busy;
struct ctx {
    int speed = 0;
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>), bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<speed> / [](ctx& c, speed const& s) { c.speed = s.value; } = bsc::state<Idle>);

void run() {
    bsc::machine m{chart, ctx{}};
    m.dispatch_by_name("go", [](std::type_identity<speed>) { return speed{7}; });
}
}  // namespace cf
