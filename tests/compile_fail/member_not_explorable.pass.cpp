// Twin of member_not_explorable.fail.cpp: the message is a bsc::transient_member, left out of
// the explored state (it is what the operator sees, not what the machine does next), and the
// explorer finds the 6 states: Idle or Busy, with 0, 1 or 2 runs.
#include <bsc/bsc.hpp>
#include <bsc/verify.hpp>
#include <string>

namespace cf {
struct go {};
struct stop {};
struct Root;
struct Idle;
struct Busy;
struct ctx {
    int runs = 0;
    bsc::transient_member<std::string> last_message;  // for the operator's display
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
    bsc::state<Idle> + bsc::event<go> / [](ctx& c) { c.last_message = "started"; } = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<stop> / [](ctx& c) { c.runs = (c.runs + 1) % 3; } = bsc::state<Idle>);
}  // namespace cf

int main() {
    using machine = bsc::machine<decltype(cf::chart)>;
    bsc::verify::explorer ex{bsc::verify::event_model<machine, cf::go, cf::stop>{machine{cf::chart, cf::ctx{}}}};
    auto const& stats = ex.run();
    return stats.complete && stats.states == 6 && bsc::verify::deadlock_free(ex).holds() ? 0 : 1;
}
