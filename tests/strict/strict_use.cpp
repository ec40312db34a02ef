// The library's headers under the warning flags users commonly turn on (tests/CMakeLists.txt:
// -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion -Wold-style-cast -Werror),
// instantiated the way programs use them: both back ends on the examples' charts (hierarchy,
// history, parallel states, channels, timers, timeouts, raised events), a system of actors,
// the exports and the explorer. A warning in a header fails the build.

#include <bsc/bsc.hpp>
#include <bsc/export.hpp>
#include <bsc/inspector.hpp>
#include <bsc/logger.hpp>
#include <bsc/observers.hpp>
#include <bsc/retain.hpp>
#include <bsc/trace.hpp>
#include <bsc/trace_reader.hpp>
#include <bsc/vcd.hpp>
#include <bsc/verify.hpp>

#include <chrono>
#include <sstream>
#include <string>

#include "manufacturing_cell/controller.hpp"
#include "manufacturing_cell/verification.hpp"
#include "mcs/mcs.hpp"
#include "production_cell/cell.hpp"

using namespace std::chrono_literals;

namespace strict {
struct go {};
struct tick {};
struct Root;
struct Par;
struct Left;
struct L1;
struct L2;
struct Right;
struct R1;
struct R2;
struct Done;
struct io {
    bsc::input<int> level{};
    bsc::output<bool> lamp{};
    bsc::timer t{10ms};
    int count = 0;
};
struct trace {
    std::string log;
    void on_entry(auto s) { log += s.name; }
    void on_exit(auto s) { log += s.name; }
    void on_transition(auto, auto, auto const&) { log += '>'; }
    void on_row(int row) { log += std::to_string(row); }
};
inline constexpr auto chart = bsc::make_chart<io>(
    bsc::composite<Root>(bsc::initial<Par>,
                         bsc::parallel<Par>(bsc::composite<Left>(bsc::deep_history, bsc::initial<L1>, bsc::state<L2>),
                                            bsc::composite<Right>(bsc::initial<R1>, bsc::state<R2>)),
                         bsc::final_state<Done>),
    bsc::state<L1> + bsc::event<go> /
                         [](io& d, go const&, auto& raise) {
                             ++d.count;
                             raise(tick{});
                         } = bsc::state<L2>,
    bsc::state<L2> + bsc::event<go> = bsc::state<L1>,
    bsc::state<R1> + bsc::event<tick>[([](io const& d) { return d.count > 0; })] = bsc::state<R2>,
    bsc::state<R2> + bsc::after(20ms) / [](io& d) { d.lamp.set(true); } = bsc::state<R1>,
    bsc::state<R1>[([](io const& d) { return d.level > 100; })] = bsc::state<Done>,
    bsc::state<L2> + bsc::on_entry / [](io& d) { d.t.start(); });
}  // namespace strict

template <class Machine>
int run(Machine m) {
    int fired = 0;
    for (int i = 0; i < 4; ++i) {
        fired += m.dispatch(strict::go{}) == bsc::outcome::consumed;
        fired += m.step(bsc::duration{i * 10ms}).transitions;
    }
    return fired + static_cast<int>(m.active_states().size()) + (m.halted() ? 1 : 0);
}

int main() {
    int sum = 0;
    sum += run(bsc::machine{strict::chart, strict::io{}, strict::trace{}});
    sum += run(bsc::table::machine{strict::chart, strict::io{}, strict::trace{}});
    sum += run(bsc::machine<bsc::chart_ref<strict::chart>, bsc::scan_policy>{strict::chart});

    bsc::machine mcs_machine{mcs::chart, mcs::panel{}};
    sum += mcs_machine.dispatch(mcs::on_p{}) == bsc::outcome::consumed;
    bsc::table::machine mcs_table{mcs::chart, mcs::panel{}};
    sum += mcs_table.dispatch(mcs::on_p{}) == bsc::outcome::consumed;

    bsc::machine<decltype(cell::chart), bsc::scan_policy> controller{cell::chart};
    sum += controller.step(500ms).transitions;

    std::ostringstream wave;
    {
        bsc::vcd_recorder cell_vcd{wave, controller};
        cell_vcd.sample();
        bsc::machine strict_machine{strict::chart, strict::io{}};
        bsc::vcd_recorder strict_vcd{wave, strict_machine, "strict"};
        strict_vcd.sample();
        auto const bytes = bsc::save(strict_machine);
        sum += bsc::restore(strict_machine, bytes, bsc::resume_at{1s}) ? 1 : 0;
        bsc::table::machine strict_table{strict::chart, strict::io{}};
        sum += bsc::restore(strict_table, bytes) ? 1 : 0;
    }
    auto const saved = bsc::save(controller);
    sum += bsc::restore(controller, saved) ? static_cast<int>(wave.str().size() > 0) : 0;

    pcell::cell system{};
    sum += system.step(100ms).transitions;

    sum += static_cast<int>(bsc::to_mermaid(strict::chart).size() + bsc::to_dot(mcs::chart).size() +
                            bsc::to_plantuml(strict::chart).size() + bsc::to_scxml(cell::chart).size());

    bsc::verify::explorer ex{bsc::verify::event_model<bsc::machine<decltype(strict::chart)>, strict::go, strict::tick>{
        bsc::machine{strict::chart}}};
    ex.run();
    sum += bsc::verify::deadlock_free(ex).holds();
    sum += bsc::verify::reachable(ex, "R2", [](auto const& m) { return m.template is<strict::R2>(); }).holds();
    sum += bsc::verify::always_reachable(ex, "L1", [](auto const& m) { return m.template is<strict::L1>(); }).holds();
    // The trace stream of the cell's controller, logged at once, read back; an inspector that
    // only listens.
    {
        std::array<std::byte, 1 << 14> storage{};
        bsc::trace_buffer buffer{storage};
        bsc::machine traced{cell::chart, cell::data{},
                            bsc::observers{bsc::logger{bsc::logger::sink_type{}}, bsc::tracer{cell::chart, buffer}}};
        traced.step(0ms);
        traced.observer().get<1>().sample(traced);
        bsc::inspector view{traced, buffer, {}};
        view.poll();
        sum += static_cast<int>(view.may_step());
        std::array<std::byte, 1 << 14> bytes{};
        bsc::trace_reader reader;
        reader.feed(std::span{bytes}.first(buffer.read(bytes)));
        while (auto r = reader.next()) sum += static_cast<int>(reader.describe(*r).size() > 0);
    }
    bsc::verify::explorer cell_ex{cell::finite::model(cell::chart)};
    cell_ex.run();
    sum += static_cast<int>(cell_ex.count() > 0);
    return sum > 0 ? 0 : 1;
}
