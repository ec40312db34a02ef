// EXPECT: (bsc::error::action_signature_not_supported<cf::bad_action>.*bsc: an action must be callable as|bsc: an action must be callable as.*bsc::error::action_signature_not_supported<cf::bad_action>)
// The action takes a cf::unrelated&, which is neither the context, the event nor the raise
// queue. The action is called, and so checked, when the machine's dispatch of cf::go is
// instantiated.
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

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
    bsc::state<Idle> + bsc::event<go> / bad_action{} = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<stop> = bsc::state<Idle>);

void run() {
    bsc::machine m{chart, ctx{}};
    m.dispatch(go{});
}
}  // namespace cf
