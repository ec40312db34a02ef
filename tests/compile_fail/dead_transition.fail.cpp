// EXPECT: (bsc::error::at_row<5, bsc::error::dead_transition<cf::Work, cf::stop, cf::Idle>.*bsc: dead transition|bsc: dead transition.*bsc::error::at_row<5, bsc::error::dead_transition<cf::Work, cf::stop, cf::Idle>)
// Work's row on stop can never fire: both of Work's children take stop first with unguarded
// rows of their own, so the event never reaches Work.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct Root;
struct Idle;
struct Work;
struct A;
struct B;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::composite<Work>(bsc::initial<A>, bsc::state<B>)),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Work>,
    bsc::state<A> + bsc::event<go> = bsc::state<B>,
    bsc::state<A> + bsc::event<stop> = bsc::state<Idle>,
    bsc::state<B> + bsc::event<stop> = bsc::state<A>,
    bsc::state<Work> + bsc::event<stop> = bsc::state<Idle>);
}  // namespace cf
