// EXPECT: defect=pending_events_not_encoded<.*, cf::job ?> ?>
// Busy defers jobs, so a waiting job is part of the machine's state, and its std::string cannot be encoded.
#include <bsc/bsc.hpp>
#include <bsc/verify.hpp>
#include <string>

namespace cf {
struct start {};
struct job {
    std::string recipe;
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

std::size_t explore() {
    bsc::verify::explorer ex{
        bsc::verify::event_model<bsc::machine<decltype(cf::chart)>, cf::start, cf::job, cf::finish>{
            bsc::machine{cf::chart, cf::ctx{}}}};
    return ex.run().states;
}
