// Twin of state_in_container.fail.cpp: the input channels are the elements of a std::array,
// which the machine walks element by element: each is latched at every dispatch.
#include <array>
#include <bsc/bsc.hpp>

namespace cf {
struct scan {};
struct Root;
struct Waiting;
struct Full;
struct ctx {
    std::array<bsc::input<bool>, 4> sensors{};
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
    m.dispatch(cf::scan{});  // latches the four inputs
    bool const full = m.is<cf::Full>();
    m.context().sensors[2].set(false);
    m.dispatch(cf::scan{});
    return full && m.is<cf::Waiting>() ? 0 : 1;
}
