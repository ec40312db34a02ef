// Twin of context_type_has_c_array.fail.cpp: sensors is a std::array, which the machine walks
// element by element, latching each input at every dispatch.
#include <array>
#include <bsc/bsc.hpp>

namespace cf {
struct scan {};
struct Root;
struct Waiting;
struct Full;
struct ctx {
    std::array<bsc::input<bool>, 4> sensors{};
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

int main() {
    bsc::machine m{cf::chart, cf::ctx{}};
    for (auto& s : m.context().sensors) s.set(true);
    m.dispatch(cf::scan{});
    return m.is<cf::Full>() ? 0 : 1;
}
