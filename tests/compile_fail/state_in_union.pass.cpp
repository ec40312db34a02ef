// Twin of state_in_union.fail.cpp: status_word is declared transient (bsc::transient), a scratch
// value that is not part of the machine's state: neither walked, saved, explored nor recorded.
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
}  // namespace cf

template <>
inline constexpr bool bsc::transient<cf::status_word> = true;

namespace cf {
inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Fault>),
    bsc::state<Idle> + bsc::event<frame> / [](ctx& c, frame const& f) { c.last.raw = f.word; } = bsc::state<Fault>,
    bsc::state<Fault> + bsc::event<frame> / [](ctx& c) { ++c.faults; } = bsc::state<Idle>);
}  // namespace cf

int main() {
    bsc::machine m{cf::chart, cf::ctx{}};
    m.dispatch(cf::frame{0x0102});
    bool const fault = m.is<cf::Fault>() && m.context().last.raw == 0x0102;
    m.dispatch(cf::frame{0});
    return fault && m.is<cf::Idle>() && m.context().faults == 1 ? 0 : 1;
}
