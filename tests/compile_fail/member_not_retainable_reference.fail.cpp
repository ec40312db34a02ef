// EXPECT: defect=member_not_retainable<cf::ctx>
// cf::ctx holds a reference to the plant: what lies behind it is not the machine's to save.
#include <bsc/bsc.hpp>
#include <bsc/retain.hpp>

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Busy;
struct plant {
    int pieces = 0;
};
struct ctx {
    int count = 0;
    plant& io;
    bsc::input<bool> start;
};

inline constexpr auto chart = bsc::make_chart<ctx>(bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
                                                   bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
                                                   bsc::state<Busy> + bsc::event<go> = bsc::state<Idle>);

std::size_t run(plant& p) {
    bsc::machine m{chart, ctx{0, p, {}}};
    return bsc::save(m).size();
}
}  // namespace cf
