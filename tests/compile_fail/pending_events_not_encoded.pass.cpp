// Twin of pending_events_not_encoded.fail.cpp: Busy takes the jobs (an internal transition)
// instead of deferring them, and the machine can be explored.
#include <bsc/bsc.hpp>
#include <bsc/verify.hpp>

namespace cf {
struct start {};
struct job {};
struct finish {};
struct Root;
struct Idle;
struct Busy;
struct ctx {
    int jobs = 0;
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Idle>, bsc::state<Busy>),
    bsc::state<Idle> + bsc::event<start> = bsc::state<Busy>,
    bsc::state<Idle> + bsc::event<job> = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<job> / [](ctx& c) { c.jobs = (c.jobs + 1) % 4; },
    bsc::state<Busy> + bsc::event<finish> = bsc::state<Idle>);
}  // namespace cf

int main() {
    bsc::verify::explorer ex{bsc::verify::event_model<bsc::machine<decltype(cf::chart)>, cf::start, cf::job, cf::finish>{
        bsc::machine{cf::chart, cf::ctx{}}}};
    return static_cast<int>(ex.run().states);
}
