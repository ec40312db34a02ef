// EXPECT: bsc::error::pending_events_not_encoded<.*bsc: the explorer \(bsc::verify\) and bsc::save / bsc::restore encode a machine|bsc: the explorer \(bsc::verify\) and bsc::save / bsc::restore encode a machine.*bsc::error::pending_events_not_encoded<
// The explorer would encode a machine of this chart without the jobs Busy keeps deferred.
#include <bsc/bsc.hpp>
#include <bsc/verify.hpp>

namespace cf {
struct start {};
struct job {};
struct finish {};
struct Root;
struct Idle;
struct Busy;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Idle>, bsc::state<Busy>),
    bsc::state<Idle> + bsc::event<start> = bsc::state<Busy>,
    bsc::state<Idle> + bsc::event<job> = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<job> / bsc::defer,
    bsc::state<Busy> + bsc::event<finish> = bsc::state<Idle>);
}  // namespace cf

int main() {
    bsc::verify::explorer ex{bsc::verify::event_model<bsc::machine<decltype(cf::chart)>, cf::start, cf::job, cf::finish>{
        bsc::machine{cf::chart, cf::ctx{}}}};
    return static_cast<int>(ex.run().states);
}
