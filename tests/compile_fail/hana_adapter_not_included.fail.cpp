// EXPECT: defect=hana_adapter_not_included<cf::axis>
// cf::axis is adapted with Boost.Hana, but <bsc/adapt/hana.hpp> is not included: bsc cannot see its members.
#include <boost/hana/define_struct.hpp>
#include <bsc/bsc.hpp>

namespace cf {
struct scan {};
struct Root;
struct Homing;
struct Ready;
struct axis {  // a constructor: no aggregate, so adapted with Boost.Hana
    BOOST_HANA_DEFINE_STRUCT(axis, (bsc::input<bool>, home), (int, limit));

    axis() : limit{0} {}
    explicit axis(int max) : limit{max} {}
    bool homed() const { return home.get(); }
};
struct ctx {
    axis x;
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Homing>, bsc::state<Ready>),
    bsc::state<Homing> + bsc::event<scan>[([](ctx const& c) { return c.x.homed(); })] = bsc::state<Ready>,
    bsc::state<Ready> + bsc::event<scan>[([](ctx const& c) { return !c.x.homed(); })] = bsc::state<Homing>);
}  // namespace cf

bool run() {
    bsc::machine m{cf::chart, cf::ctx{cf::axis{100}}};
    m.dispatch(cf::scan{});
    return m.is<cf::Ready>();
}
