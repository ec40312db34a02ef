// The twin of action_signature_entry.fail.cpp: the entry action takes the context only.
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
struct good_entry {
    void operator()(ctx& c) const { ++c.count; }
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>), bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
    bsc::state<Busy> + bsc::on_entry / good_entry{}, bsc::state<Busy> + bsc::event<stop> = bsc::state<Idle>);
}  // namespace cf
