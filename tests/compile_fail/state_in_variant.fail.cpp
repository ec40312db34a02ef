// EXPECT: defect=state_out_of_reach<cf::ctx, member_number<0>, std::variant<int, bsc::input<int> ?> ?>
// The input channel is one alternative of a std::variant: the machine cannot latch it.
#include <bsc/bsc.hpp>
#include <variant>

namespace cf {
struct check {};
struct Root;
struct Normal;
struct High;
struct ctx {
    std::variant<int, bsc::input<int>> setpoint;  // a fixed value, or read from an input
    int limit = 100;
};

inline constexpr auto too_high = bsc::guard([](ctx const& c) {
    int const value = c.setpoint.index() == 0 ? std::get<0>(c.setpoint) : std::get<1>(c.setpoint).get();
    return value > c.limit;
});
inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Normal>, bsc::state<High>),
    bsc::state<Normal> + bsc::event<check>[too_high] = bsc::state<High>,
    bsc::state<High> + bsc::event<check>[!too_high] = bsc::state<Normal>);
}  // namespace cf

bool run() {
    bsc::machine m{cf::chart, cf::ctx{}};
    m.dispatch(cf::check{});
    return m.is<cf::High>();
}
