// The twin: Busy's timeout is guarded, so Step's fires whenever Busy's guard is false.
#include <bsc/bsc.hpp>

#include <chrono>

using namespace std::chrono_literals;

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Busy;
struct Step;
struct Retry;
struct ctx {
    bool abort = false;
};

inline constexpr auto chart = bsc::make_chart<ctx, bsc::parent_first>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Idle>,
                         bsc::composite<Busy>(bsc::initial<Step>, bsc::state<Step>), bsc::state<Retry>),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
    bsc::state<Busy> + bsc::after(1s)[([](ctx const& c) { return c.abort; })] = bsc::state<Idle>,
    bsc::state<Step> + bsc::after(1s) = bsc::state<Retry>, bsc::state<Retry> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
