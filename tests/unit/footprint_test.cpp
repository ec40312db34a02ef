// What a machine stores and what a dispatch pays for: a machine holds its configuration and
// what its chart really needs (no copy of a chart whose rows carry no data, no record of
// failures where nothing can throw, no timeout slots without timeouts), and the mark of a run
// under way is written only when the machine's own code could call it back.

#include <doctest/doctest.h>

#include <bsc/bsc.hpp>
#include <bsc/table/machine.hpp>
#include <array>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <type_traits>

#include "backends.hpp"
#include "inside.hpp"

using namespace std::chrono_literals;

namespace fp {
struct Root;
struct A;
struct B;
struct C;
struct go {};
struct back {};

struct none {};
struct count {
    int n = 0;
};

// The smallest useful chart: three states, empty context, no action.
inline constexpr auto bare = bsc::make_chart<none>(
    bsc::composite<Root>(bsc::initial<A>, bsc::state<B>, bsc::state<C>), bsc::state<A> + bsc::event<go> = bsc::state<B>,
    bsc::state<B> + bsc::event<go> = bsc::state<C>, bsc::state<C> + bsc::event<back> = bsc::state<A>);

// The same with actions and a guard that cannot throw (noexcept), and with ones that can.
inline constexpr auto quiet = bsc::make_chart<count>(
    bsc::composite<Root>(bsc::initial<A>, bsc::state<B>, bsc::state<C>),
    bsc::state<A> + bsc::event<go>[([](count const& c) noexcept { return c.n < 100; })] /
                        [](count& c) noexcept { ++c.n; } = bsc::state<B>,
    bsc::state<B> + bsc::on_entry / [](count& c) noexcept { c.n += 10; },
    bsc::state<B> + bsc::event<go> / [](count& c) noexcept { ++c.n; } = bsc::state<C>,
    bsc::state<C> + bsc::event<back> = bsc::state<A>);
inline constexpr auto loud = bsc::make_chart<count>(
    bsc::composite<Root>(bsc::initial<A>, bsc::state<B>, bsc::state<C>),
    bsc::state<A> +
        bsc::event<go>[([](count const& c) { return c.n < 100; })] / [](count& c) { ++c.n; } = bsc::state<B>,
    bsc::state<B> + bsc::on_entry / [](count& c) { c.n += 10; },
    bsc::state<B> + bsc::event<go> / [](count& c) { ++c.n; } = bsc::state<C>,
    bsc::state<C> + bsc::event<back> = bsc::state<A>);

// A chart whose action captures a value: its rows carry data, so a machine keeps its copy.
inline constexpr int step_size = 7;
inline constexpr auto capturing = bsc::make_chart<count>(
    bsc::composite<Root>(bsc::initial<A>, bsc::state<B>, bsc::state<C>),
    bsc::state<A> + bsc::event<go> / [k = step_size](count& c) noexcept { c.n += k; } = bsc::state<B>,
    bsc::state<B> + bsc::event<go> = bsc::state<C>, bsc::state<C> + bsc::event<back> = bsc::state<A>);

// With a timeout: its delay is data, and the machine has a timeout slot.
inline constexpr auto timed = bsc::make_chart<none>(bsc::composite<Root>(bsc::initial<A>, bsc::state<B>, bsc::state<C>),
                                                    bsc::state<A> + bsc::after(5ms) = bsc::state<B>,
                                                    bsc::state<B> + bsc::event<go> = bsc::state<C>,
                                                    bsc::state<C> + bsc::event<back> = bsc::state<A>);

constexpr std::size_t padded(std::size_t bytes, std::size_t alignment) {
    return (bytes + alignment - 1) / alignment * alignment;
}
}  // namespace fp

TEST_CASE_TEMPLATE("a machine stores its configuration and what its chart needs, nothing more", Backend,
                   bsc_test::compiled, bsc_test::table) {
    using bare = bsc_test::machine_t<Backend, decltype(fp::bare)>;
    using quiet = bsc_test::machine_t<Backend, decltype(fp::quiet)>;
    using loud = bsc_test::machine_t<Backend, decltype(fp::loud)>;
    using capturing = bsc_test::machine_t<Backend, decltype(fp::capturing)>;
    using timed = bsc_test::machine_t<Backend, decltype(fp::timed)>;
    constexpr std::size_t clock = sizeof(bsc::duration);
    constexpr std::size_t bytes = 3;  // the configuration, the status (last outcome, running), clock started
    // No chart, no context, no queue, no failure record: the clock and three bytes.
    CHECK(sizeof(bare) == fp::padded(clock + bytes, alignof(bsc::duration)));
    // Its context (an int) on top, and still no chart: guards and actions that capture nothing
    // are made again from nothing.
    CHECK(sizeof(quiet) == fp::padded(clock + sizeof(int) + bytes, alignof(bsc::duration)));
    // Guards and actions that may throw: the record of a failure (one pointer) on top.
    CHECK(sizeof(loud) == fp::padded(clock + sizeof(void*) + sizeof(int) + bytes, alignof(bsc::duration)));
    // A captured value: the chart's copy (which holds the capture) on top.
    CHECK(sizeof(decltype(fp::capturing)) >= sizeof(int));
    CHECK(sizeof(capturing) ==
          fp::padded(fp::padded(sizeof(decltype(fp::capturing)), alignof(bsc::duration)) + clock + sizeof(int) + bytes,
                     alignof(bsc::duration)));
    // A timeout: the chart's copy (which holds the delay) and the state's entry time on top.
    CHECK(sizeof(decltype(fp::timed)) >= clock);
    CHECK(sizeof(timed) == fp::padded(sizeof(decltype(fp::timed)), alignof(bsc::duration)) + clock + clock +
                               fp::padded(bytes, alignof(bsc::duration)));
}

TEST_CASE_TEMPLATE("a machine that stores no chart behaves as one that does", Backend, bsc_test::compiled,
                   bsc_test::table) {
    bsc_test::machine_t<Backend, decltype(fp::quiet)> quiet{fp::quiet};
    bsc_test::machine_t<Backend, decltype(fp::loud)> loud{fp::loud};
    for (int i = 0; i < 9; ++i) {
        CHECK(quiet.dispatch(fp::back{}) == loud.dispatch(fp::back{}));  // ignored in A
        CHECK(quiet.dispatch(fp::go{}) == loud.dispatch(fp::go{}));
        CHECK(quiet.dispatch(fp::go{}) == loud.dispatch(fp::go{}));
        CHECK(quiet.dispatch(fp::back{}) == loud.dispatch(fp::back{}));
        CHECK(quiet.context().n == loud.context().n);
        CHECK(quiet.last_outcome() == loud.last_outcome());
    }
    CHECK(quiet.context().n == 9 * 12);
    CHECK(quiet.last_failure() == nullptr);  // nothing can have failed: always null
    bsc_test::machine_t<Backend, decltype(fp::capturing)> capturing{fp::capturing};
    CHECK(capturing.dispatch(fp::go{}) == bsc::outcome::consumed);
    CHECK(capturing.context().n == fp::step_size);
}

namespace fp {
// A context with tail padding (8 + 1 bytes in 16): the machine's own bytes must not live there,
// or copying bytes over the whole context would overwrite them.
struct padded_context {
    std::int64_t total = 0;
    bool flag = false;
};
inline constexpr auto padded_chart = bsc::make_chart<padded_context>(
    bsc::composite<Root>(bsc::initial<A>, bsc::state<B>, bsc::state<C>),
    bsc::state<A> + bsc::event<go> / [](padded_context& c) noexcept { c.total += 1; } = bsc::state<B>,
    bsc::state<B> + bsc::event<go> = bsc::state<C>, bsc::state<C> + bsc::event<back> = bsc::state<A>);
}  // namespace fp

TEST_CASE_TEMPLATE("bytes copied over the whole context leave the machine's configuration and outcome alone", Backend,
                   bsc_test::compiled, bsc_test::table) {
    bsc_test::machine_t<Backend, decltype(fp::padded_chart)> m{fp::padded_chart};
    CHECK(m.dispatch(fp::go{}) == bsc::outcome::consumed);
    CHECK(m.dispatch(fp::go{}) == bsc::outcome::consumed);
    REQUIRE(m.template is<fp::C>());
    // Bytes copied into the context, padding included, as a trivially copyable object may be
    // (restored from a buffer, say): allowed because the context is not a potentially
    // overlapping subobject, whose tail padding could hold the machine's own bytes.
    static_assert(std::is_trivially_copyable_v<fp::padded_context>);
    fp::padded_context replacement;
    std::memset(static_cast<void*>(&replacement), 0xff, sizeof replacement);
    replacement.total = 40;
    replacement.flag = true;
    std::memcpy(static_cast<void*>(&inside::context(m)), &replacement, sizeof replacement);
    CHECK(m.template is<fp::C>());
    CHECK(m.last_outcome() == bsc::outcome::consumed);
    CHECK(m.dispatch(fp::back{}) == bsc::outcome::consumed);
    CHECK(m.dispatch(fp::go{}) == bsc::outcome::consumed);
    CHECK(m.context().total == 41);
    CHECK(m.template is<fp::B>());
}

namespace fp {
// A machine called back from its own guard, entry action or observer: each is refused.
// The machine and the call it makes are given by the environment, as inputs.
struct callback {
    bsc::input<void*> self;
    bsc::input<bsc::outcome (*)(void*)> poke;
    bsc::outcome from_guard = bsc::outcome::consumed;
    bsc::outcome from_entry = bsc::outcome::consumed;
};
inline constexpr auto calls_back = bsc::make_chart<callback>(
    bsc::composite<Root>(bsc::initial<A>, bsc::state<B>, bsc::state<C>),
    bsc::state<A> + bsc::event<go>[([](callback const& c) {
        // The guard's context is const; the callback goes through the stored pointer.
        const_cast<callback&>(c).from_guard = c.poke.get()(c.self.get());
        return true;
    })] = bsc::state<B>,
    bsc::state<B> + bsc::on_entry / [](callback& c) { c.from_entry = c.poke.get()(c.self.get()); },
    bsc::state<B> + bsc::event<go> = bsc::state<C>, bsc::state<C> + bsc::event<back> = bsc::state<A>);

struct calling_observer {
    void* self = nullptr;
    bsc::outcome (*poke)(void*) = nullptr;
    bsc::outcome seen = bsc::outcome::consumed;
    template <class E>
    void on_dispatch(E const&) {
        if (self != nullptr) seen = poke(self);
    }
};
}  // namespace fp

TEST_CASE_TEMPLATE("a dispatch from the machine's own guard or entry action is refused", Backend, bsc_test::compiled,
                   bsc_test::table) {
    using machine = bsc_test::machine_t<Backend, decltype(fp::calls_back)>;
    machine m{fp::calls_back};
    m.context().self.set(&m);
    m.context().poke.set([](void* self) { return static_cast<machine*>(self)->dispatch(fp::back{}); });
    CHECK(m.dispatch(fp::back{}) ==
          bsc::outcome::ignored);  // no guard or action ran: a plain dispatch (it latches both)
    CHECK(m.dispatch(fp::go{}) == bsc::outcome::consumed);
    CHECK(m.context().from_guard == bsc::outcome::reentrant);
    CHECK(m.context().from_entry == bsc::outcome::reentrant);
    CHECK(m.template is<fp::B>());
    CHECK(m.last_outcome() == bsc::outcome::consumed);
    // The run is over: the machine takes events again.
    CHECK(m.dispatch(fp::go{}) == bsc::outcome::consumed);
    CHECK(m.dispatch(fp::back{}) == bsc::outcome::consumed);
    CHECK(m.template is<fp::A>());
}

TEST_CASE_TEMPLATE("a dispatch from the machine's observer is refused", Backend, bsc_test::compiled, bsc_test::table) {
    using machine = bsc_test::machine_t<Backend, decltype(fp::bare), bsc::default_policy, fp::calling_observer>;
    machine m{fp::bare, fp::none{}, fp::calling_observer{}};
    m.observer().self = &m;
    m.observer().poke = [](void* self) { return static_cast<machine*>(self)->dispatch(fp::back{}); };
    CHECK(m.dispatch(fp::go{}) == bsc::outcome::consumed);
    CHECK(m.observer().seen == bsc::outcome::reentrant);
    CHECK(m.template is<fp::B>());
}

TEST_CASE_TEMPLATE("a machine under bsc::lean_policy behaves as one under the default policy and returns each outcome",
                   Backend, bsc_test::compiled, bsc_test::table) {
    bsc_test::machine_t<Backend, decltype(fp::quiet)> kept{fp::quiet};
    bsc_test::machine_t<Backend, decltype(fp::quiet), bsc::lean_policy> lean{fp::quiet};
    static_assert(!bsc::lean_policy::refuse_reentry && !bsc::lean_policy::keep_last_outcome);
    auto const same = [&] {
        return kept.context().n == lean.context().n && kept.template is<fp::A>() == lean.template is<fp::A>() &&
               kept.template is<fp::B>() == lean.template is<fp::B>() &&
               kept.template is<fp::C>() == lean.template is<fp::C>();
    };
    for (int i = 0; i < 20; ++i) {
        auto const outcome = lean.dispatch(fp::go{});
        CHECK(outcome == kept.dispatch(fp::go{}));
        CHECK(outcome == kept.last_outcome());
        CHECK(lean.dispatch(fp::back{}) == kept.dispatch(fp::back{}));
        CHECK(lean.step(bsc::duration{i}).status == kept.step(bsc::duration{i}).status);
        CHECK(same());
    }
    CHECK(lean.context().n > 0);
    CHECK(lean.dispatch(fp::back{}, bsc::allow_unhandled) == bsc::outcome::ignored);
}

namespace fp {
// A flat chart whose actions are empty (as in Boost.SML's benchmark charts; declared noexcept,
// or the machine keeps the record of a failure, as `loud` above), and a context with a timer: a
// machine keeps a clock for the timer even where its policy keeps none.
inline constexpr auto nothing = []() noexcept {};
inline constexpr auto empty_actions = bsc::make_chart<none>(
    bsc::composite<Root>(bsc::initial<A>, bsc::state<B>, bsc::state<C>),
    bsc::state<A> + bsc::event<go> / nothing = bsc::state<B>, bsc::state<B> + bsc::event<go> / nothing = bsc::state<C>,
    bsc::state<C> + bsc::event<back> / nothing = bsc::state<A>);
struct timing {
    bsc::timer wait{3ms};
};
inline constexpr auto timer_chart = bsc::make_chart<timing>(
    bsc::composite<Root>(bsc::initial<A>, bsc::state<B>, bsc::state<C>),
    bsc::state<A> + bsc::event<go> / [](timing& t) { t.wait.start(); } = bsc::state<B>,
    bsc::state<B>[([](timing const& t) { return t.wait.tm(); })] = bsc::state<C>,
    bsc::state<C> + bsc::event<back> = bsc::state<A>);
}  // namespace fp

TEST_CASE_TEMPLATE("under bsc::lean_policy a machine of a chart that needs no time keeps no clock", Backend,
                   bsc_test::compiled, bsc_test::table) {
    using lean = bsc_test::machine_t<Backend, decltype(fp::empty_actions), bsc::lean_policy>;
    using kept = bsc_test::machine_t<Backend, decltype(fp::empty_actions)>;
    // The configuration (a byte) and the status byte: neither chart, context, clock nor queue.
    CHECK(sizeof(lean) == 2);
    // The default policy keeps the clock (8 bytes) and its started flag.
    CHECK(sizeof(kept) == fp::padded(sizeof(bsc::duration) + 3, alignof(bsc::duration)));
    static_assert(!bsc::lean_policy::keep_clock && bsc::default_policy::keep_clock);

    // Nothing it does depends on time: it behaves as the machine with a clock, whatever the
    // caller's time does, and cannot tell that time went backwards.
    lean m{fp::empty_actions};
    kept k{fp::empty_actions};
    for (int i : {5, 9, 2, 2, 11, 0}) {
        CHECK(m.dispatch(fp::go{}) == k.dispatch(fp::go{}));
        auto const mine = m.step(bsc::duration{i});
        auto const theirs = k.step(bsc::duration{i});
        CHECK(mine.status == theirs.status);
        CHECK_FALSE(mine.clock_went_backwards);
        CHECK(m.template is<fp::A>() == k.template is<fp::A>());
        CHECK(m.template is<fp::C>() == k.template is<fp::C>());
    }
    CHECK(k.now() == bsc::duration{11});  // the clock that was kept never went back
}

TEST_CASE_TEMPLATE("under bsc::lean_policy a machine keeps the clock its timeouts or timers run on", Backend,
                   bsc_test::compiled, bsc_test::table) {
    using timed = bsc_test::machine_t<Backend, decltype(fp::timed), bsc::lean_policy>;
    using timer = bsc_test::machine_t<Backend, decltype(fp::timer_chart), bsc::lean_policy>;
    CHECK(sizeof(timed) == sizeof(bsc_test::machine_t<Backend, decltype(fp::timed)>));
    // (The same as under the default policy, which keeps the clock whatever the chart.)
    CHECK(sizeof(timer) == sizeof(bsc_test::machine_t<Backend, decltype(fp::timer_chart)>));

    // A timeout counts from the clock, which does not follow the caller's time back.
    timed t{fp::timed};
    CHECK(t.step(10ms).status == bsc::outcome::ignored);
    CHECK(t.step(4ms).clock_went_backwards);
    CHECK(t.now() == 10ms);
    CHECK(t.step(14ms).status == bsc::outcome::ignored);  // 4 ms after entry
    CHECK(t.template is<fp::A>());
    CHECK(t.step(15ms).status == bsc::outcome::consumed);
    CHECK(t.template is<fp::B>());

    // A timer started in a dispatch times from the next cycle, on the clock.
    timer m{fp::timer_chart};
    CHECK(m.dispatch(fp::go{}) == bsc::outcome::consumed);
    CHECK(m.step(20ms).status == bsc::outcome::ignored);
    CHECK(m.step(1ms).clock_went_backwards);  // runs at 20 ms
    CHECK(m.step(22ms).status == bsc::outcome::ignored);
    CHECK(m.template is<fp::B>());
    CHECK(m.step(23ms).status == bsc::outcome::consumed);
    CHECK(m.template is<fp::C>());
}

namespace fp {
// A large event the chart takes but never raises, and a small one its actions raise: with
// bsc::raise, the queue holds the small one only; with an action that may raise anything, every
// event of the chart.
struct large {
    std::array<char, 512> payload{};
};
struct small {
    int n = 0;
};
inline constexpr auto raises_small = bsc::make_chart<count>(
    bsc::composite<Root>(bsc::initial<A>, bsc::state<B>, bsc::state<C>),
    bsc::state<A> + bsc::event<large> / bsc::raise(small{5}) = bsc::state<B>,
    bsc::state<B> + bsc::event<small> / [](count& c, small const& s) noexcept { c.n += s.n; } = bsc::state<C>,
    bsc::state<C> + bsc::on_exit / bsc::raise(small{1}), bsc::state<C> + bsc::event<go> = bsc::state<A>);
inline constexpr auto raises_anything = bsc::make_chart<count>(
    bsc::composite<Root>(bsc::initial<A>, bsc::state<B>, bsc::state<C>),
    bsc::state<A> +
        bsc::event<large> / [](count&, large const&, auto& raise) noexcept { (void)raise(small{5}); } = bsc::state<B>,
    bsc::state<B> + bsc::event<small> / [](count& c, small const& s) noexcept { c.n += s.n; } = bsc::state<C>,
    bsc::state<C> + bsc::on_exit / bsc::raise(small{1}), bsc::state<C> + bsc::event<go> = bsc::state<A>);
}  // namespace fp

namespace fp {
// An action that asks its raise argument for room before it raises: the chart's checks and the
// choice of its queue see an action that raises, and the machine's queue answers it.
inline constexpr auto asks_for_room = bsc::make_chart<count>(
    bsc::composite<Root>(bsc::initial<A>, bsc::state<B>, bsc::state<C>),
    bsc::state<A> + bsc::event<go> /
                        [](count& c, go const&, auto& raise) {
                            c.n = static_cast<int>(raise.capacity() - raise.size());
                            if (raise.empty() && !raise.overflowed()) raise(back{});
                        } = bsc::state<B>,
    bsc::state<B> + bsc::event<back> = bsc::state<C>, bsc::state<C> + bsc::event<go> = bsc::state<A>);
}  // namespace fp

TEST_CASE_TEMPLATE("an action may ask its raise argument for room before it raises", Backend, bsc_test::compiled,
                   bsc_test::table) {
    bsc_test::machine_t<Backend, decltype(fp::asks_for_room)> m{fp::asks_for_room};
    CHECK(m.dispatch(fp::go{}) == bsc::outcome::consumed);
    CHECK(m.context().n == static_cast<int>(bsc::default_policy::queue_capacity));
    CHECK(m.template is<fp::C>());  // the raised back took B to C
}

TEST_CASE_TEMPLATE("the queue of a chart that raises with bsc::raise holds only the events it raises", Backend,
                   bsc_test::compiled, bsc_test::table) {
    using narrow = bsc_test::machine_t<Backend, decltype(fp::raises_small)>;
    using wide = bsc_test::machine_t<Backend, decltype(fp::raises_anything)>;
    // Eight queued events of at most 8 bytes each, against eight of the 512-byte event.
    CHECK(sizeof(narrow) < sizeof(fp::large));
    CHECK(sizeof(wide) > 8 * sizeof(fp::large));
    // And both run alike: large raises small{5} (B to C, +5); go leaves C, whose exit raises
    // small{1}, which A ignores.
    narrow n{fp::raises_small};
    wide w{fp::raises_anything};
    CHECK(n.dispatch(fp::large{}) == bsc::outcome::consumed);
    CHECK(w.dispatch(fp::large{}) == bsc::outcome::consumed);
    CHECK((n.template is<fp::C>() && w.template is<fp::C>()));
    CHECK(n.context().n == 5);
    CHECK(w.context().n == 5);
    CHECK(n.dispatch(fp::go{}) == bsc::outcome::consumed);
    CHECK(w.dispatch(fp::go{}) == bsc::outcome::consumed);
    CHECK((n.template is<fp::A>() && w.template is<fp::A>()));
    CHECK(n.context().n == 5);
    CHECK(w.context().n == 5);
}

TEST_CASE_TEMPLATE("a machine of bsc::chart_ref stores no copy of its chart, and reads the chart's values", Backend,
                   bsc_test::compiled, bsc_test::table) {
    using scan_timed = bsc_test::machine_t<Backend, decltype(fp::timed), bsc::scan_policy>;
    using scan_timed_ref = bsc_test::machine_t<Backend, bsc::chart_ref<fp::timed>, bsc::scan_policy>;
    using capturing = bsc_test::machine_t<Backend, decltype(fp::capturing)>;
    using capturing_ref = bsc_test::machine_t<Backend, bsc::chart_ref<fp::capturing>>;
    // The delay and the captured value are the chart's: the machines of chart_ref do without.
    CHECK(sizeof(scan_timed_ref) + sizeof(decltype(fp::timed)) <= sizeof(scan_timed));
    CHECK(sizeof(capturing_ref) + sizeof(decltype(fp::capturing)) <= sizeof(capturing));
    // And they run the chart's values: A leaves after 5 ms, go adds the captured 7.
    scan_timed t{fp::timed};
    scan_timed_ref r{fp::timed};
    t.step(0ms);
    r.step(0ms);
    t.step(4ms);
    r.step(4ms);
    CHECK((t.template is<fp::A>() && r.template is<fp::A>()));
    t.step(5ms);
    r.step(5ms);
    CHECK((t.template is<fp::B>() && r.template is<fp::B>()));
    capturing c{fp::capturing};
    capturing_ref cr{fp::capturing};
    CHECK(c.dispatch(fp::go{}) == bsc::outcome::consumed);
    CHECK(cr.dispatch(fp::go{}) == bsc::outcome::consumed);
    CHECK(c.context().n == fp::step_size);
    CHECK(cr.context().n == fp::step_size);
}

namespace fp {
// Every raising action is a bsc::raise of one event type, which carries a value: the queue keeps
// the values, without an index. (A leaves with three raises, in declaration order.)
struct tick {
    int value = 0;
};
struct burst {};
struct log {
    std::array<int, 32> seen{};
    int count = 0;
};
inline constexpr auto raises_ticks = bsc::make_chart<log>(
    bsc::composite<Root>(bsc::initial<A>, bsc::state<B>), bsc::state<A> + bsc::on_exit / bsc::raise(tick{1}),
    bsc::state<A> + bsc::on_exit / bsc::raise(tick{2}), bsc::state<A> + bsc::on_exit / bsc::raise(tick{3}),
    bsc::state<A> + bsc::event<burst> = bsc::state<B>,
    bsc::state<B> +
        bsc::event<tick> /
            [](log& l, tick const& t) noexcept { l.seen[static_cast<std::size_t>(l.count++ % 32)] = t.value; },
    bsc::state<B> + bsc::event<go> = bsc::state<A>);
// One empty event: the queue keeps how many, nothing else. A leaves with 8 raises, which fit;
// C with 9, one too many.
template <class S, std::size_t... I>
constexpr auto pings(std::index_sequence<I...>) {
    return bsc::rows(((void)I, bsc::state<S> + bsc::on_exit / bsc::raise(back{}))...);
}
inline constexpr auto raises_pings = bsc::make_chart<count>(
    bsc::composite<Root>(bsc::initial<A>, bsc::state<B>, bsc::state<C>), pings<A>(std::make_index_sequence<8>{}),
    pings<C>(std::make_index_sequence<9>{}), bsc::state<A> + bsc::event<burst> = bsc::state<B>,
    bsc::state<C> + bsc::event<burst> = bsc::state<B>,
    bsc::state<B> + bsc::event<back> / [](count& c) noexcept { c.n += 100; },
    bsc::state<B> + bsc::event<go> = bsc::state<C>);
// An event whose default constructor is not constexpr: the single-event queue would construct
// its slots with it, so the chart gets the general queue, and its machine still runs in a
// constant expression.
struct late {
    int value;
    late() {}  // NOLINT: the point is a default constructor that is not constexpr
    constexpr explicit late(int v) : value(v) {}
};
inline constexpr auto raises_late = bsc::make_chart<count>(
    bsc::composite<Root>(bsc::initial<A>, bsc::state<B>), bsc::state<A> + bsc::on_exit / bsc::raise(late{3}),
    bsc::state<A> + bsc::event<go> = bsc::state<B>,
    bsc::state<B> + bsc::event<late> / [](count& c, late const& l) noexcept { c.n += l.value; },
    bsc::state<B> + bsc::event<go> = bsc::state<A>);
constexpr int late_total() {
    bsc::machine<bsc::chart_ref<raises_late>> m{raises_late};
    (void)m.dispatch(go{});
    (void)m.dispatch(go{});
    (void)m.dispatch(go{});
    return m.context().n;
}
}  // namespace fp

TEST_CASE(
    "an event whose default construction is not a constant keeps the general queue, usable in constant expressions") {
    static_assert(!std::is_same_v<inside::queue_for<decltype(fp::raises_late), bsc::default_policy>,
                                  inside::single_event_queue<8, fp::late>>);
    static_assert(fp::late_total() == 6);
    CHECK(fp::late_total() == 6);
}

TEST_CASE_TEMPLATE(
    "a chart that raises one event type keeps the events in order, without an index, or only their count", Backend,
    bsc_test::compiled, bsc_test::table) {
    using tick_queue = inside::queue_for<decltype(fp::raises_ticks), bsc::default_policy>;
    using ping_queue = inside::queue_for<decltype(fp::raises_pings), bsc::default_policy>;
    static_assert(std::is_same_v<tick_queue, inside::single_event_queue<8, fp::tick>>);
    static_assert(std::is_same_v<ping_queue, inside::single_event_queue<8, fp::back>>);
    // Eight ints and the ring's two counters and flag; for the empty event, only those.
    static_assert(sizeof(tick_queue) ==
                  fp::padded(8 * sizeof(int) + 2 * sizeof(std::size_t) + 1, alignof(std::size_t)));
    static_assert(sizeof(ping_queue) == fp::padded(2 * sizeof(std::size_t) + 1, alignof(std::size_t)));

    // The values come out in the order raised, across the ring's end (3 per round, 8 slots).
    bsc_test::machine_t<Backend, decltype(fp::raises_ticks)> t{fp::raises_ticks};
    for (int round = 0; round < 5; ++round) {
        CHECK(t.dispatch(fp::burst{}) == bsc::outcome::consumed);
        CHECK(t.dispatch(fp::go{}) == bsc::outcome::consumed);
    }
    REQUIRE(t.context().count == 15);
    for (std::size_t k = 0; k < 15; ++k) CHECK(t.context().seen[k] == static_cast<int>(k % 3) + 1);

    // Eight pings fit; the ninth is an overflow, reported, and the eight are still processed.
    bsc_test::machine_t<Backend, decltype(fp::raises_pings)> p{fp::raises_pings};
    CHECK(p.dispatch(fp::burst{}) == bsc::outcome::consumed);
    CHECK(p.context().n == 800);
    CHECK(p.dispatch(fp::go{}) == bsc::outcome::consumed);
    CHECK(p.dispatch(fp::burst{}) == bsc::outcome::queue_overflow);
    CHECK(p.context().n == 1600);
    // The overflow ended with the run that had it.
    CHECK(p.dispatch(fp::go{}) == bsc::outcome::consumed);
    CHECK(p.dispatch(fp::back{}) == bsc::outcome::ignored);
}
