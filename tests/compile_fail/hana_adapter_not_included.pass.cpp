// Twin of hana_adapter_not_included.fail.cpp: with <bsc/adapt/hana.hpp> included, bsc walks
// cf::axis by its Hana accessors and latches its private input like any other.
#include <boost/hana/define_struct.hpp>
#include <bsc/adapt/hana.hpp>
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
    void sense(bool at_home) const { home.set(at_home); }  // the environment's: on the const context
};
struct ctx {
    axis x;
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Homing>, bsc::state<Ready>),
    bsc::state<Homing> + bsc::event<scan>[([](ctx const& c) { return c.x.homed(); })] = bsc::state<Ready>,
    bsc::state<Ready> + bsc::event<scan>[([](ctx const& c) { return !c.x.homed(); })] = bsc::state<Homing>);
}  // namespace cf

int main() {
    bsc::machine m{cf::chart, cf::ctx{cf::axis{100}}};
    m.context().x.sense(true);
    m.dispatch(cf::scan{});  // latches the input inside axis
    return m.is<cf::Ready>() ? 0 : 1;
}
