// EXPECT: defect=state_out_of_reach<cf::ctx, member_number<0>, std::vector<bsc::input<bool>
// The input channels are elements of a std::vector, which the machine does not look into.
#include <bsc/bsc.hpp>
#include <vector>

namespace cf {
struct scan {};
struct Root;
struct Waiting;
struct Full;
struct ctx {
    std::vector<bsc::input<bool>> sensors = std::vector<bsc::input<bool>>(4);
};

inline constexpr auto all_on = bsc::guard([](ctx const& c) {
    for (auto const& s : c.sensors)
        if (!s.get()) return false;
    return true;
});
inline constexpr auto chart = bsc::make_chart<ctx>(bsc::composite<Root>(bsc::initial<Waiting>, bsc::state<Full>),
                                                   bsc::state<Waiting> + bsc::event<scan>[all_on] = bsc::state<Full>,
                                                   bsc::state<Full> + bsc::event<scan>[!all_on] = bsc::state<Waiting>);
}  // namespace cf

bool run() {
    bsc::machine m{cf::chart, cf::ctx{}};
    m.dispatch(cf::scan{});
    return m.is<cf::Full>();
}
