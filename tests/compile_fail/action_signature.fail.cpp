// EXPECT: defect=at_row<1, in_row<cf::Idle, cf::go, cf::Busy, action_signature_not_supported<cf::bad_action> ?>
// The action takes a cf::unrelated&, which is neither the context, the event nor the raise
// queue. make_chart reports it with its row, bsc::error::in_row<cf::Idle, cf::go, cf::Busy, ...>.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct unrelated {};
struct Root;
struct Idle;
struct Busy;
struct ctx {
    int count = 0;
};
struct bad_action {
    void operator()(unrelated&) const {}
};

inline constexpr auto chart = bsc::make_chart<ctx>(bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
                                                   bsc::state<Idle> + bsc::event<go> / bad_action{} = bsc::state<Busy>,
                                                   bsc::state<Busy> + bsc::event<stop> = bsc::state<Idle>);

void run() {
    bsc::machine m{chart, ctx{}};
    m.dispatch(go{});
}
}  // namespace cf
