// The twin of dead_transition.fail.cpp: B's row on stop is guarded, so while B is active the
// event can reach Work's row.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct Root;
struct Idle;
struct Work;
struct A;
struct B;
struct ctx {
    bool hold = false;
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::composite<Work>(bsc::initial<A>, bsc::state<B>)),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Work>,
    bsc::state<A> + bsc::event<go> = bsc::state<B>,
    bsc::state<A> + bsc::event<stop> = bsc::state<Idle>,
    bsc::state<B> + bsc::event<stop>[([](ctx const& c) { return c.hold; })] = bsc::state<A>,
    bsc::state<Work> + bsc::event<stop> = bsc::state<Idle>);
}  // namespace cf
