// Twin of action_signature.fail.cpp: the action takes the context.
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
    void operator()(ctx&) const {}
};

inline constexpr auto chart = bsc::make_chart<ctx>(bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
                                                   bsc::state<Idle> + bsc::event<go> / bad_action{} = bsc::state<Busy>,
                                                   bsc::state<Busy> + bsc::event<stop> = bsc::state<Idle>);

void run() {
    bsc::machine m{chart, ctx{}};
    m.dispatch(go{});
}
}  // namespace cf
