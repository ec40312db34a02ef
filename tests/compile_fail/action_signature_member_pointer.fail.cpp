// EXPECT: defect=at_row<1, in_row<cf::Idle, cf::go, cf::Busy, action_signature_not_supported<void \(cf::ctx::\*\)\(\)> ?>
// The action is a pointer to a member function of the context: bsc calls an action with
// parentheses, never with .* or ->*, so make_chart reports it with its row, as any callable
// it cannot call (wrap it: `[](ctx& c) { c.bump(); }`).
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct Root;
struct Idle;
struct Busy;
struct ctx {
    int count = 0;
    void bump() { ++count; }
};

inline constexpr auto chart = bsc::make_chart<ctx>(bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
                                                   bsc::state<Idle> + bsc::event<go> / & ctx::bump = bsc::state<Busy>,
                                                   bsc::state<Busy> + bsc::event<stop> = bsc::state<Idle>);

void run() {
    bsc::machine m{chart, ctx{}};
    m.dispatch(go{});
}
}  // namespace cf
