// EXPECT: defect=context_type_has_c_array<cf::ctx>
// sensors is a C array: bsc cannot walk it, so the machine would not latch these inputs.
#include <bsc/bsc.hpp>

namespace cf {
struct scan {};
struct Root;
struct Waiting;
struct Full;
struct ctx {
    bsc::input<bool> sensors[4];
    int scans = 0;
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
