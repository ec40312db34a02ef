// Twin of pending_events_not_encoded.fail.cpp: the job's payload is an int, so the jobs Busy
// keeps deferred are encoded with the rest of the machine's state, and explored.
#include <bsc/bsc.hpp>
#include <bsc/verify.hpp>

namespace cf {
struct start {};
struct job {
    int recipe = 0;
};
struct finish {};
struct Root;
struct Idle;
struct Busy;
struct ctx {
    int done = 0;
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>), bsc::state<Idle> + bsc::event<start> = bsc::state<Busy>,
    bsc::state<Idle> + bsc::event<job> = bsc::state<Busy>, bsc::state<Busy> + bsc::event<job> / bsc::defer,
    bsc::state<Busy> + bsc::event<finish> / [](ctx& c) { c.done = (c.done + 1) % 2; } = bsc::state<Idle>);
}  // namespace cf

int main() {
    bsc::verify::explorer ex{
        bsc::verify::event_model<bsc::machine<decltype(cf::chart)>, cf::start, cf::job, cf::finish>{
            bsc::machine{cf::chart, cf::ctx{}}}};
    auto const& stats = ex.run();
    // Idle, with done 0 or 1 (a job never waits there: Idle takes it), and Busy, with done 0 or 1
    // and 0 to 8 jobs deferred (the default policy's deferred_capacity): machines that differ only
    // in the jobs they keep are told apart.
    constexpr std::size_t waiting = bsc::default_policy::deferred_capacity + 1;
    return stats.complete && stats.states == 2 + 2 * waiting && bsc::verify::deadlock_free(ex).holds() ? 0 : 1;
}
