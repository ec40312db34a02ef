// bsc::logger (<bsc/logger.hpp>): one record per dispatch, exit, transition and entry, with the
// machine's time, the cycle's number and the trigger as the chart writes it, on both back ends;
// and the observer hooks it is built on (on_dispatch, on_cycle, on_cycle_end, timeout_elapsed).

#include <doctest/doctest.h>

#include <bsc/bsc.hpp>
#include <bsc/logger.hpp>

#include <chrono>
#include <cstdint>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "backends.hpp"

namespace logger_test {

using namespace std::chrono_literals;

struct go {};
struct ping {};
struct Root;
struct Idle;
struct Busy;
struct Done;
struct ctx {
    bsc::input<bool> ready;
    int pings = 0;
};

// One transition of each kind of trigger: an event, a timeout, a condition, an internal
// transition, and an event raised by an action.
inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>, bsc::state<Done>),
    bsc::state<Idle> + bsc::event<go> / bsc::raise(ping{}) = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<ping> / [](ctx& c) { ++c.pings; },
    bsc::state<Busy> + bsc::after(1500ms) = bsc::state<Done>,
    bsc::state<Done>[([](ctx const& c) { return c.ready.get(); })] = bsc::state<Idle>);

template <class Backend>
using logged_machine = bsc_test::machine_t<Backend, decltype(chart), bsc::scan_policy, bsc::logger>;

}  // namespace logger_test

using bsc_test::compiled;
using bsc_test::table;

TEST_CASE_TEMPLATE("the logger writes one line per dispatch, exit, transition and entry, with time and cycle", Backend,
                   compiled, table) {
    using namespace logger_test;
    std::ostringstream out;
    logged_machine<Backend> m{chart, ctx{}, bsc::logger{out}};
    m.step(0ms);
    m.step(250ms);
    m.dispatch(go{});
    m.step(1s);
    m.step(1750ms);  // 1500 ms after Busy was entered (at the 250 ms cycle's time)
    m.context().ready.set(true);
    m.step(2s);
    CHECK(out.str() ==
          "[0s] entry Root\n"
          "[0s] entry Idle\n"
          "[250ms] dispatch go\n"
          "[250ms] exit Idle\n"
          "[250ms] transition Idle -> Busy on go\n"
          "[250ms] entry Busy\n"
          "[250ms] transition Busy -> internal on ping\n"
          "[1750ms #4] exit Busy\n"
          "[1750ms #4] transition Busy -> Done on after(1500ms)\n"
          "[1750ms #4] entry Done\n"
          "[2s #5] exit Done\n"
          "[2s #5] transition Done -> Idle on condition\n"
          "[2s #5] entry Idle\n");
    CHECK(m.context().pings == 1);
    CHECK(m.observer().cycles() == 5);
}

namespace logger_test {
struct job {
    int n = 0;
};
struct finish {};
struct jobs {
    bsc::input<bool> ready;
    bsc::input<bool> done;
    int taken = 0;
};
inline constexpr auto is_ready = bsc::named<"ready">(bsc::guard([](jobs const& c) { return c.ready.get(); }));
inline constexpr auto is_done = bsc::named("done", bsc::guard([](jobs const& c) { return c.done.get(); }));
// Named guards (by type and by value) on an event's row and on an eventless row, and a row
// that defers an event.
inline constexpr auto guarded_chart = bsc::make_chart<jobs>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>, bsc::state<Done>),
    bsc::state<Idle> + bsc::event<go>[is_ready] = bsc::state<Busy>,
    bsc::state<Idle> + bsc::event<job> / [](jobs& c) { ++c.taken; }, bsc::state<Busy> + bsc::event<job> / bsc::defer,
    bsc::state<Busy>[is_done && !is_ready] = bsc::state<Done>, bsc::state<Done> + bsc::event<job> / bsc::defer,
    bsc::state<Done> + bsc::event<finish> = bsc::state<Idle>);
}  // namespace logger_test

TEST_CASE_TEMPLATE("the logger names a transition's named guard, and reports a deferral as one", Backend, compiled,
                   table) {
    using namespace logger_test;
    std::ostringstream out;
    bsc_test::machine_t<Backend, decltype(guarded_chart), bsc::scan_policy, bsc::logger> m{guarded_chart, jobs{},
                                                                                           bsc::logger{out}};
    m.context().ready.set(true);
    m.step(0ms);
    m.dispatch(go{});
    m.dispatch(job{7});
    m.context().ready.set(false);
    m.context().done.set(true);
    m.step(1s);
    m.dispatch(finish{});
    CHECK(m.context().taken == 1);
    CHECK(out.str() ==
          "[0s] entry Root\n"
          "[0s] entry Idle\n"
          "[0s] dispatch go\n"
          "[0s] exit Idle\n"
          "[0s] transition Idle -> Busy on go [ready]\n"
          "[0s] entry Busy\n"
          "[0s] dispatch job\n"
          "[0s] defer job in Busy\n"
          "[1s #2] exit Busy\n"
          "[1s #2] transition Busy -> Done on [done && !ready]\n"
          "[1s #2] entry Done\n"
          "[1s #2] defer job in Done\n"  // retried after the change of configuration, deferred again
          "[1s] dispatch finish\n"
          "[1s] exit Done\n"
          "[1s] transition Done -> Idle on finish\n"
          "[1s] entry Idle\n"
          "[1s] transition Idle -> internal on job\n");
}

// An observer with the guard and deferral hooks only: the machine calls them with no
// on_transition beside them, on either back end.
struct guards_and_deferrals {
    std::vector<std::string> seen;
    void on_guard(std::string_view guard) { seen.emplace_back(guard); }
    template <class State, class E>
    void on_defer(State, E const&) {
        seen.emplace_back("defer");
    }
};

TEST_CASE_TEMPLATE("an observer of guards and deferrals alone is called", Backend, compiled, table) {
    using namespace logger_test;
    bsc_test::machine_t<Backend, decltype(guarded_chart), bsc::scan_policy, guards_and_deferrals> m{
        guarded_chart, jobs{}, guards_and_deferrals{}};
    m.context().ready.set(true);
    m.step(0ms);
    m.dispatch(go{});
    m.dispatch(job{7});
    CHECK(m.observer().seen == std::vector<std::string>{"ready", "defer"});
}

TEST_CASE_TEMPLATE("the logger's records go to a callback, with the cycle's number only inside a cycle", Backend,
                   compiled, table) {
    using namespace logger_test;
    struct seen {
        bsc::log_record::kind what;
        std::int64_t ms;
        std::uint64_t cycle;
        std::string state, target, trigger;
        bool operator==(seen const&) const = default;
    };
    std::vector<seen> records;
    logged_machine<Backend> m{
        chart, ctx{}, bsc::logger{[&](bsc::log_record const& r) {
            records.push_back({r.what, std::chrono::duration_cast<std::chrono::milliseconds>(r.time).count(), r.cycle,
                               std::string(r.state), std::string(r.target), std::string(r.trigger)});
        }}};
    using kind = bsc::log_record::kind;
    records.clear();
    m.step(100ms);
    CHECK(records.empty());  // a cycle that does nothing records nothing
    m.dispatch(go{});
    REQUIRE(records.size() == 5);
    CHECK(records[0] == seen{kind::dispatch, 100, 0, "", "", "go"});
    CHECK(records[2] == seen{kind::transition, 100, 0, "Idle", "Busy", "go"});
    CHECK(records[4] == seen{kind::transition, 100, 0, "Busy", "internal", "ping"});
    records.clear();
    m.step(1600ms);
    REQUIRE(records.size() == 3);
    CHECK(records[1] == seen{kind::transition, 1600, 2, "Busy", "Done", "after(1500ms)"});
    records.clear();
    m.dispatch(go{}, bsc::allow_unhandled);  // Done does not take go: still reported, at the last cycle's time
    REQUIRE(records.size() == 1);
    CHECK(records[0] == seen{kind::dispatch, 1600, 0, "", "", "go"});
}

TEST_CASE_TEMPLATE("a cycle earlier than the machine's clock runs, and is counted, at the clock's time", Backend,
                   compiled, table) {
    using namespace logger_test;
    int calls = 0;
    logged_machine<Backend> m{chart, ctx{}, bsc::logger{[&](bsc::log_record const&) { ++calls; }}};
    CHECK(calls == 2);  // entry Root, entry Idle
    m.step(1s);
    m.step(500ms);  // earlier than the clock: the cycle runs at the machine's time, 1 s
    CHECK(m.observer().cycles() == 2);
    CHECK(calls == 2);
    std::int64_t at = 0;
    m.observer() = bsc::logger{[&](bsc::log_record const& r) { at = r.time.count(); }};
    m.step(900ms);
    m.dispatch(logger_test::go{});
    CHECK(at == std::chrono::nanoseconds(1s).count());
}

TEST_CASE("bsc::to_string of a log record") {
    using namespace std::chrono_literals;
    bsc::log_record r;
    r.what = bsc::log_record::kind::exit;
    r.time = 2500us;
    r.cycle = 7;
    r.state = "Heating";
    CHECK(bsc::to_string(r) == "[2500us #7] exit Heating");
    r.what = bsc::log_record::kind::transition;
    r.target = "Done";
    r.trigger = "after(3s)";
    r.cycle = 0;
    r.time = -1s;
    CHECK(bsc::to_string(r) == "[-1s] transition Heating -> Done on after(3s)");
}
