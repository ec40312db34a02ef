// EXPECT: defect=at_row<2, in_row<cf::Busy, bsc::detail::entry_keyword, bsc::detail::no_target, action_signature_not_supported<cf::bad_entry> ?>
// Busy's entry action takes the event, which an entry action is never given: make_chart
// reports it with its row, state<Busy> + on_entry.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct Root;
struct Idle;
struct Busy;
struct ctx {
    int count = 0;
};
struct bad_entry {
    void operator()(ctx& c, go const&) const { ++c.count; }
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>), bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
    bsc::state<Busy> + bsc::on_entry / bad_entry{}, bsc::state<Busy> + bsc::event<stop> = bsc::state<Idle>);
}  // namespace cf
