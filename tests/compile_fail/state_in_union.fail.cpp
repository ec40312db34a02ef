// EXPECT: defect=state_out_of_reach<cf::ctx, member_number<1>, cf::status_word ?>
// status_word is a union: bsc cannot tell which of its members is alive, so it cannot walk it.
#include <bsc/bsc.hpp>
#include <cstdint>

namespace cf {
struct frame {
    std::uint16_t word;
};
struct Root;
struct Idle;
struct Fault;
union status_word {
    std::uint16_t raw;
    std::uint8_t bytes[2];
};
struct ctx {
    int faults = 0;
    status_word last{};
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Fault>),
    bsc::state<Idle> + bsc::event<frame> / [](ctx& c, frame const& f) { c.last.raw = f.word; } = bsc::state<Fault>,
    bsc::state<Fault> + bsc::event<frame> / [](ctx& c) { ++c.faults; } = bsc::state<Idle>);
}  // namespace cf

bool run() {
    bsc::machine m{cf::chart, cf::ctx{}};
    m.dispatch(cf::frame{0x0102});
    return m.is<cf::Fault>();
}
