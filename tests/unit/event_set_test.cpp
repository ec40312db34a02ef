// Events by name and number (bsc::event_set, dispatch_by_name, dispatch_by_number) on both back
// ends: names (a static member `name`, else the type's name), numbers in order of first
// appearance, exact matching, unknown names and numbers, events with data built by a decoder.

#include <doctest/doctest.h>

#include <bsc/bsc.hpp>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

#include "backends.hpp"

namespace event_set_test {

struct on_p {
    static constexpr std::string_view name = "ON_P";
};
struct off_p {
    static constexpr std::string_view name = "OFF_P";
};
struct speed {  // carries data, and cannot be built without it
    explicit speed(int v) : value(v) {}
    int value;
};
struct reset {};
struct Root;
struct Off;
struct On;
struct ctx {
    int speed = 0;
    int resets = 0;
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Off>, bsc::state<On>), bsc::state<Off> + bsc::event<on_p> = bsc::state<On>,
    bsc::state<On> + bsc::event<speed> / [](ctx& c, speed const& s) { c.speed = s.value; },
    bsc::state<On> + bsc::event<off_p> = bsc::state<Off>,
    bsc::state<Root> + bsc::event<reset> / [](ctx& c) { ++c.resets; });

using events = bsc::event_set<decltype(chart)>;

// Builds speed from a number received with it; the other events need no data.
struct decoder {
    int received = 0;
    speed operator()(std::type_identity<speed>) const { return speed{received}; }
};

}  // namespace event_set_test

using bsc_test::compiled;
using bsc_test::table;

TEST_CASE("an event_set names and numbers the chart's events at compile time") {
    using event_set_test::events;
    static_assert(events::size == 4);
    static_assert(events::names == std::array<std::string_view, 4>{"ON_P", "speed", "OFF_P", "reset"});
    static_assert(events::number_of<event_set_test::off_p> == 2);
    static_assert(events::find("OFF_P") == std::optional<std::size_t>{2});
    CHECK(events::find("off_p") == std::nullopt);  // exact: the name, case included
    CHECK(events::find("") == std::nullopt);
    CHECK(events::find("ON_P ") == std::nullopt);
    CHECK(events::unknown("on") == "no event of this chart is named 'on'; its events are ON_P, speed, OFF_P, reset");
    std::string visited;
    for (std::size_t i = 0; i < events::size; ++i)
        events::visit(i, [&]<class E>(std::type_identity<E>) { visited += bsc::event_name<E>; });
    CHECK(visited == "ON_PspeedOFF_Preset");
    CHECK(bsc::event_name<event_set_test::reset> == "reset");
}

TEST_CASE_TEMPLATE("dispatch_by_name and dispatch_by_number dispatch the event they name, built by a decoder", Backend,
                   compiled, table) {
    using namespace event_set_test;
    bsc_test::machine_t<Backend, decltype(chart)> m{chart, ctx{}};
    decoder decode{};
    CHECK(m.dispatch_by_name("ON_P", decode) == bsc::outcome::consumed);
    CHECK(m.template is<On>());
    decode.received = 1200;
    CHECK(m.dispatch_by_name("speed", decode) == bsc::outcome::consumed);
    CHECK(m.context().speed == 1200);
    decode.received = 300;
    CHECK(m.dispatch_by_number(events::number_of<speed>, decode) == bsc::outcome::consumed);
    CHECK(m.context().speed == 300);
    CHECK(m.dispatch_by_number(3, decode) == bsc::outcome::consumed);  // reset, from the root
    CHECK(m.context().resets == 1);
    CHECK(m.dispatch_by_number(2, decode) == bsc::outcome::consumed);  // OFF_P
    CHECK(m.template is<Off>());
    CHECK(m.dispatch_by_name("OFF_P", decode) == bsc::outcome::ignored);  // known, but Off does not take it
}

TEST_CASE_TEMPLATE("an unknown name or number is reported and changes nothing", Backend, compiled, table) {
    using namespace event_set_test;
    bsc_test::machine_t<Backend, decltype(chart)> m{chart, ctx{}};
    decoder const decode{};
    CHECK(m.dispatch_by_name("ON_P", decode) == bsc::outcome::consumed);
    CHECK(m.dispatch_by_name("on_p", decode) == bsc::outcome::unknown_event);
    CHECK(m.last_outcome() == bsc::outcome::unknown_event);
    CHECK(m.dispatch_by_number(events::size, decode) == bsc::outcome::unknown_event);
    CHECK(m.dispatch_by_number(static_cast<std::size_t>(-1), decode) == bsc::outcome::unknown_event);
    CHECK(m.template is<On>());
    CHECK(m.context().speed == 0);
    CHECK(m.context().resets == 0);
}

namespace event_set_test {
struct load {  // carries a name as data: that is not the event's name
    std::string name;
};
struct Loaded;
struct fail_ctx {
    int failures = 0;
};
// A chart that takes bsc::action_failed: that event is raised by the machine, not sent by name.
inline constexpr auto guarded = bsc::make_chart<fail_ctx>(
    bsc::composite<Root>(bsc::initial<Off>, bsc::state<Loaded>),
    bsc::state<Off> + bsc::event<load> = bsc::state<Loaded>,
    bsc::state<Loaded> + bsc::event<bsc::action_failed> / [](fail_ctx& c) { ++c.failures; } = bsc::state<Off>,
    bsc::state<Loaded> + bsc::event<reset> = bsc::state<Off>);
}  // namespace event_set_test

TEST_CASE("a data member called name is not the event's name; bsc::action_failed cannot be sent by name") {
    using set = bsc::event_set<decltype(event_set_test::guarded)>;
    CHECK(bsc::event_name<event_set_test::load> == "load");
    static_assert(set::size == 2);
    CHECK(set::names == std::array<std::string_view, 2>{"load", "reset"});
    CHECK(set::number_of<event_set_test::reset> == 1);
    CHECK(set::find("action_failed") == std::nullopt);
    bsc::machine m{event_set_test::guarded, event_set_test::fail_ctx{}};
    auto const decode = [](std::type_identity<event_set_test::load>) { return event_set_test::load{"tray 3"}; };
    CHECK(m.dispatch_by_name("action_failed", decode) == bsc::outcome::unknown_event);
    CHECK(m.dispatch_by_name("load", decode) == bsc::outcome::consumed);
    CHECK(m.dispatch_by_name("reset", decode) == bsc::outcome::consumed);
    CHECK(m.context().failures == 0);
}

namespace event_set_test {
struct start {};
struct finish {};
struct Idle;
struct Work;
struct Busy;
struct Finished;
struct Next;
struct done_ctx {
    int others = 0;
};
// Work completes when it enters Finished, and the machine raises bsc::done<Work>; Next takes every
// event through bsc::any_event. Neither is an event the environment can send.
inline constexpr auto completing = bsc::make_chart<done_ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::composite<Work>(bsc::initial<Busy>, bsc::final_state<Finished>),
                         bsc::state<Next>),
    bsc::state<Idle> + bsc::event<start> = bsc::state<Work>,
    bsc::state<Busy> + bsc::event<finish> = bsc::state<Finished>,
    bsc::state<Work> + bsc::event<bsc::done<Work>> = bsc::state<Next>,
    bsc::state<Next> + bsc::event<start> = bsc::state<Idle>,
    bsc::state<Next> + bsc::event<bsc::any_event> / [](done_ctx& c) { ++c.others; });
}  // namespace event_set_test

TEST_CASE_TEMPLATE("done.state.S and * name no event the environment can send: unknown, and nothing changes", Backend,
                   compiled, table) {
    using namespace event_set_test;
    using set = bsc::event_set<decltype(completing)>;
    static_assert(set::size == 2);
    CHECK(set::names == std::array<std::string_view, 2>{"start", "finish"});
    CHECK(set::find("done.state.Work") == std::nullopt);
    CHECK(set::find("*") == std::nullopt);
    CHECK(set::unknown("done.state.Work") ==
          "no event of this chart is named 'done.state.Work'; its events are start, finish");
    CHECK(bsc::event_name<bsc::done<Work>> == "done.state.Work");  // its name where the chart is drawn
    bsc_test::machine_t<Backend, decltype(completing)> m{completing, done_ctx{}};
    CHECK(m.dispatch_by_name("start") == bsc::outcome::consumed);
    CHECK(m.active_states().joined() == "Root Work Busy");
    CHECK(m.dispatch_by_name("done.state.Work") == bsc::outcome::unknown_event);  // Work has not completed
    CHECK(m.active_states().joined() == "Root Work Busy");
    CHECK(m.last_outcome() == bsc::outcome::unknown_event);
    CHECK(m.dispatch_by_name("*") == bsc::outcome::unknown_event);
    CHECK(m.dispatch_by_number(set::size) == bsc::outcome::unknown_event);
    CHECK(m.active_states().joined() == "Root Work Busy");
    CHECK(m.context().others == 0);
    CHECK(m.dispatch_by_number(set::number_of<finish>) == bsc::outcome::consumed);  // Work completes: done<Work>
    CHECK(m.active_states().joined() == "Root Next");
    CHECK(m.dispatch_by_name("*") == bsc::outcome::unknown_event);  // not even where a row takes any event
    CHECK(m.context().others == 0);
    CHECK(m.dispatch_by_name("finish") == bsc::outcome::consumed);  // taken by Next's row on any event
    CHECK(m.context().others == 1);
}
