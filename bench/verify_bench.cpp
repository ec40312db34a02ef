// Exploration speed of bsc::verify on the example models: states explored per second, one core.

#include <benchmark/benchmark.h>

#include <chrono>

#include "../examples/manufacturing_cell/verification.hpp"
#include "../examples/mcs/mcs.hpp"
#include "../examples/production_cell/cell.hpp"

template <>
inline constexpr bool bsc::transient<mcs::display> = true;

namespace {
template <class Model>
void explore(benchmark::State& state, Model const& model) {
    bsc::verify::statistics last;
    for (auto _ : state) {
        bsc::verify::explorer ex{model};
        last = ex.run();
        benchmark::DoNotOptimize(last.states);
    }
    state.counters["states"] = static_cast<double>(last.states);
    state.counters["transitions"] = static_cast<double>(last.transitions);
    state.counters["depth"] = static_cast<double>(last.depth);
    state.counters["key_bytes"] = static_cast<double>(last.key_bytes);
    state.counters["bytes_per_state"] = static_cast<double>(last.memory_bytes) / static_cast<double>(last.states);
    state.counters["states_per_s"] = benchmark::Counter(
        static_cast<double>(last.states) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

// The manufacturing cell in closed loop with its finite plant; scan periods of 500, 100 and
// 50 ms: the same cell, more cycles per timer, more states.
void manufacturing_cell(benchmark::State& state) {
    explore(state, cell::finite::model(cell::chart, std::chrono::milliseconds{state.range(0)}));
}
BENCHMARK(manufacturing_cell)->Arg(500)->Arg(100)->Arg(50)->Unit(benchmark::kMillisecond);

// The Mode Control Supervisor, its 13 buttons offered in every state.
void mcs_panel(benchmark::State& state) {
    explore(state, bsc::verify::event_model<mcs::machine, mcs::on_p, mcs::off_p, mcs::estop_p, mcs::reset_p, mcs::mem_p,
                                            mcs::mdi_p, mcs::tape_p, mcs::hnd_p, mcs::jog_p, mcs::rpd_p, mcs::zrn_p,
                                            mcs::edit_p, mcs::setup_p>{mcs::machine{mcs::chart, mcs::panel{}}});
}
BENCHMARK(mcs_panel)->Unit(benchmark::kMillisecond);

// The production cell, bricks put on the feed belt whenever the operator chooses, up to N.
void production_cell(benchmark::State& state) {
    auto const bricks = static_cast<std::uint8_t>(state.range(0));
    auto step = [bricks](pcell::cell& s, std::size_t choice, bsc::duration now) {
        auto& belt = s.actors.env_feed_belt.context();
        bool const put = choice == 1 && belt.fed < bricks && belt.start_free.get();
        belt.put.set(put ? pcell::brick{static_cast<std::uint8_t>(belt.fed + 1), false} : pcell::brick{});
        s.step(now);
    };
    pcell::cell initial{};
    initial.actors.feed_belt.context().on.set(true);
    initial.actors.table.context().on.set(true);
    initial.actors.robot.context().on.set(true);
    initial.actors.press.context().on.set(true);
    initial.actors.deposit_belt.context().on.set(true);
    explore(state,
            bsc::verify::system_model{initial, pcell::period, 2, step, [](pcell::cell const&) { return std::string{}; },
                                      [](std::uint16_t) { return std::string{}; }});
}
BENCHMARK(production_cell)->Arg(2)->Arg(4)->Unit(benchmark::kMillisecond);
}  // namespace
