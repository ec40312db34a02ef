// EXPECT: (bsc::error::eventless_livelock<cf::A>.*bsc: eventless livelock|bsc: eventless livelock.*bsc::error::eventless_livelock<cf::A>)
// A and B lead to each other by unguarded eventless transitions: once A is entered,
// dispatch would go round the cycle forever.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct back {};
struct Root;
struct Idle;
struct A;
struct B;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<A>, bsc::state<B>),
    bsc::state<Idle> + bsc::event<go> = bsc::state<A>,
    bsc::state<A> = bsc::state<B>,
    bsc::state<B> = bsc::state<A>);
}  // namespace cf
