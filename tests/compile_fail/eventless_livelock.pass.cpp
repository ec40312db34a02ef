// Twin of eventless_livelock.fail.cpp: the transition from B back to A waits for an event.
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
    bsc::state<B> + bsc::event<back> = bsc::state<A>);
}  // namespace cf
