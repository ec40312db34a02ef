// The library built without exceptions (-fno-exceptions, set on this file by tests/strict.cmake):
// guards and actions are plain calls, the explorer aborts where it would throw. Both back ends,
// an explored chart with a timeout, and the exports.

#include <bsc/bsc.hpp>
#include <bsc/export.hpp>
#include <bsc/verify.hpp>

#include <chrono>

#include "mcs/mcs.hpp"

using namespace std::chrono_literals;

namespace no_exceptions {
struct go {};
struct Root;
struct Idle;
struct Busy;
struct ctx {
    int n = 0;
};
inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
    bsc::state<Idle> + bsc::event<go> / [](ctx& c) { ++c.n; } = bsc::state<Busy>,
    bsc::state<Busy> + bsc::after(10ms) = bsc::state<Idle>);
}  // namespace no_exceptions

int run_without_exceptions() {
    bsc::machine m{no_exceptions::chart};
    m.dispatch(no_exceptions::go{});
    m.step(0ms);
    m.step(10ms);
    bsc::table::machine t{mcs::chart, mcs::panel{}};
    t.dispatch(mcs::on_p{});
    auto model = bsc::verify::cycle_model{bsc::machine{no_exceptions::chart}, 1ms, 1,
                                          [](no_exceptions::ctx const&, std::size_t) {}};
    bsc::verify::explorer ex{model};
    ex.run();
    return m.context().n + static_cast<int>(ex.count() + bsc::to_dot(no_exceptions::chart).size());
}
