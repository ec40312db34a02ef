// EXPECT: defect=member_not_explorable<std::(__cxx11::)?basic_string<char
// The context holds a std::string, which the explorer can neither encode nor copy byte for byte.
#include <bsc/bsc.hpp>
#include <bsc/verify.hpp>
#include <string>

namespace cf {
struct go {};
struct stop {};
struct Root;
struct Idle;
struct Busy;
struct ctx {
    int runs = 0;
    std::string last_message;  // for the operator's display
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
    bsc::state<Idle> + bsc::event<go> / [](ctx& c) { c.last_message = "started"; } = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<stop> / [](ctx& c) { c.runs = (c.runs + 1) % 3; } = bsc::state<Idle>);
}  // namespace cf

std::size_t explore() {
    using machine = bsc::machine<decltype(cf::chart)>;
    bsc::verify::explorer ex{bsc::verify::event_model<machine, cf::go, cf::stop>{machine{cf::chart, cf::ctx{}}}};
    return ex.run().states;
}
