#pragma once
// The chart of the retentive-state tests and fuzz target: deep history, a parallel state,
// timeouts, a final root child, and a context with a member of every kind bsc::save stores
// (channels of each direction, a timer, a duration, integers of both signs, an enum, floating
// point, nested aggregates and std::arrays) and one it does not (bsc::transient).

#include <bsc/bsc.hpp>
#include <bsc/retain.hpp>

#include <array>
#include <chrono>
#include <cstdint>
#include <string>

namespace retain_test {

using namespace std::chrono_literals;

struct go {};
struct next {};
struct leave {};
struct back {};

struct Root;
struct Work;
struct Hold;
struct Setup;
struct Run;
struct Fast;
struct Slow;
struct Done;
struct Panel;
struct Lamp;
struct LampOff;
struct LampOn;
struct Horn;
struct Quiet;
struct Loud;

enum class mode : std::int16_t { manual = -3, automatic = 7 };

// Not saved: a restored machine keeps its own.
struct display {
    display() = default;
    explicit display(int v) : shown(v) {}
    int shown = 0;
};

struct axis {
    double position = 0;
    float speed = 0;
    std::array<bool, 3> limits{};
};

struct ctx {
    bsc::input<bool> start;
    bsc::output<int> count;
    bsc::inout<mode> operating;
    bool flag = false;
    std::int8_t small = 0;
    std::uint64_t big = 0;
    axis x;
    std::array<axis, 2> more{};
    bsc::timer settle{250ms};
    bsc::duration spent{};
    display screen;
};

}  // namespace retain_test

template <>
inline constexpr bool bsc::transient<retain_test::display> = true;

namespace retain_test {

// Wraps around rather than overflow: the fuzz target restores any value a member can hold.
constexpr std::uint64_t wrapping_add(std::int64_t a, std::uint64_t b) { return static_cast<std::uint64_t>(a) + b; }

inline constexpr auto work = [](ctx& c) {
    c.count.set(static_cast<int>(static_cast<std::uint32_t>(wrapping_add(c.count.pending(), 1))));
    c.flag = !c.flag;
    c.small = static_cast<std::int8_t>(c.small - 3);
    c.big = c.big * 3 + 0x9000000000000001ull;
    c.x.position += 0.125;
    c.x.speed -= 1.5f;
    c.x.limits[static_cast<std::uint32_t>(c.count.pending()) % 3] = true;
    c.more[1].position = -c.x.position;
    c.spent = bsc::duration{static_cast<bsc::duration::rep>(wrapping_add(c.spent.count(), 15'000'000))};
    c.operating.set(c.flag ? mode::automatic : mode::manual);
    c.screen.shown = static_cast<int>(static_cast<std::uint32_t>(wrapping_add(c.screen.shown, 1)));
    c.settle.start();
};

// Deep history, a parallel state, timeouts and a final root child: everything save keeps.
inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Hold>,
                         bsc::composite<Work>(bsc::deep_history, bsc::initial<Setup>,
                                              bsc::composite<Run>(bsc::initial<Fast>, bsc::state<Slow>)),
                         bsc::parallel<Panel>(bsc::composite<Lamp>(bsc::initial<LampOff>, bsc::state<LampOn>),
                                              bsc::composite<Horn>(bsc::initial<Quiet>, bsc::state<Loud>)),
                         bsc::final_state<Done>),
    bsc::state<Hold> + bsc::event<go> / work = bsc::state<Work>,
    bsc::state<Hold>[([](ctx const& c) { return c.start.get(); })] / work = bsc::state<Work>,
    bsc::state<Setup> + bsc::after(300ms) / work = bsc::state<Run>,
    bsc::state<Fast> + bsc::event<next> / work = bsc::state<Slow>,
    bsc::state<Slow> + bsc::after(1s) / work = bsc::state<Fast>,
    bsc::state<Work> + bsc::event<leave> = bsc::state<Hold>, bsc::state<Hold> + bsc::event<back> = bsc::state<Panel>,
    bsc::state<LampOff> + bsc::after(200ms) = bsc::state<LampOn>,
    bsc::state<LampOn> + bsc::event<go> = bsc::state<LampOff>,
    bsc::state<Quiet>[([](ctx const& c) { return c.settle.tm(); })] = bsc::state<Loud>,
    bsc::state<Loud> + bsc::event<next> = bsc::state<Done>, bsc::state<Panel> + bsc::event<leave> = bsc::state<Hold>);

// A chart with the same context and other states.
struct Other;
inline constexpr auto other_chart = bsc::make_chart<ctx>(bsc::composite<Root>(bsc::initial<Hold>, bsc::state<Other>),
                                                         bsc::state<Hold> + bsc::event<go> = bsc::state<Other>,
                                                         bsc::state<Other> + bsc::event<back> = bsc::state<Hold>);

template <class M>
std::string describe(M const& m) {
    auto const& c = m.context();
    return m.active_states().joined() + " | " + std::to_string(c.start.get()) + std::to_string(c.start.pending()) +
           " " + std::to_string(c.count.get()) + "/" + std::to_string(c.count.pending()) + " " +
           std::to_string(static_cast<int>(c.operating.get())) + " " + std::to_string(c.flag) + " " +
           std::to_string(c.small) + " " + std::to_string(c.big) + " " + std::to_string(c.x.position) + " " +
           std::to_string(c.x.speed) + " " + std::to_string(c.x.limits[0]) + std::to_string(c.x.limits[1]) +
           std::to_string(c.x.limits[2]) + " " + std::to_string(c.more[1].position) + " " +
           std::to_string(c.settle.tm()) + std::to_string(c.settle.running()) + " " +
           std::to_string(c.settle.elapsed().count()) + " " + std::to_string(c.spent.count()) + " @" +
           std::to_string(m.now().count());
}

// One scripted step of the run: an event or a cycle at time t (milliseconds).
template <class M>
std::string drive(M& m, int k) {
    bsc::outcome o{};
    switch (k % 7) {
        case 0: o = m.dispatch(go{}, bsc::allow_unhandled); break;
        case 1: o = m.dispatch(next{}, bsc::allow_unhandled); break;
        case 2: o = m.dispatch(leave{}, bsc::allow_unhandled); break;
        case 3: o = m.dispatch(back{}, bsc::allow_unhandled); break;
        default: {
            m.context().start.set(k % 3 == 0);
            o = m.step(std::chrono::milliseconds{100 * k}).status;
        }
    }
    return std::to_string(static_cast<int>(o)) + " " + describe(m);
}

}  // namespace retain_test
