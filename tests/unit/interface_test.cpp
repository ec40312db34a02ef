// The public interface both back ends share (include/bsc/detail/runtime/driver.hpp), tested once
// against each: construction and the deduction guides, copies, the configuration and the
// queries on it, observers, unhandled events, the queue's capacity. What only one back end
// has is tested in machine_test.cpp (compiled) and table_test.cpp (table-driven).

#include <doctest/doctest.h>

#include <cstddef>
#include <string>
#include <type_traits>

#include "backends.hpp"
#include "trace.hpp"

using bsc_test::compiled;
using bsc_test::machine_t;
using bsc_test::table;
using bsc_test::trace_observer;

namespace api {
struct go {};
struct back {};
struct ping {};
struct Root;
struct A;
struct A1;
struct A2;
struct B;
struct B1;
struct B2;
struct P;
struct R1;
struct X;
struct Y;
struct counter {
    int count = 0;
};

// 4 composites (Root, A, B, R1), one parallel (P), basic states.
inline constexpr auto chart = bsc::make_chart<counter>(
    bsc::composite<Root>(bsc::initial<A>, bsc::composite<A>(bsc::initial<A1>, bsc::state<A2>),
                         bsc::composite<B>(bsc::deep_history, bsc::initial<B1>, bsc::state<B2>),
                         bsc::parallel<P>(bsc::composite<R1>(bsc::initial<X>), bsc::state<Y>)),
    bsc::state<A1> + bsc::event<go> = bsc::state<A2>, bsc::state<A2> + bsc::event<go> = bsc::state<B>,
    bsc::state<B1> + bsc::event<go> / [](counter& c) { ++c.count; } = bsc::state<B2>,
    bsc::state<B2> + bsc::event<go> = bsc::state<P>, bsc::state<P> + bsc::event<back> = bsc::state<A>,
    bsc::state<B> + bsc::event<back> = bsc::state<A>, bsc::state<A> + bsc::event<back> = bsc::state<B>);

struct partial {  // only one hook: the others are not required
    int exits = 0;
    void on_exit(auto) { ++exits; }
};
struct row_log {  // on_row: the position of the fired row in make_chart's arguments
    int calls = 0;
    int last = -1;
    void on_row(int row) {
        ++calls;
        last = row;
    }
};
// Every hook and no data: it counts its calls outside itself, so that it stays an empty type.
inline int stateless_calls = 0;
struct stateless_observer {
    void on_entry(auto) const { ++stateless_calls; }
    void on_exit(auto) const { ++stateless_calls; }
    void on_transition(auto, auto, auto const&) const { ++stateless_calls; }
    void on_row(int) const { ++stateless_calls; }
};

// go raises two pings, each of which counts.
inline constexpr auto raising = bsc::make_chart<counter>(
    bsc::composite<Root>(bsc::initial<A>, bsc::state<B>),
    bsc::state<A> + bsc::event<go> / (bsc::raise(ping{}), bsc::raise(ping{})),
    bsc::state<A> + bsc::event<ping> / [](counter& c) { ++c.count; }, bsc::state<A> + bsc::event<back> = bsc::state<B>,
    bsc::state<B> + bsc::event<back> = bsc::state<A>);
struct two_events : bsc::default_policy {
    static constexpr std::size_t queue_capacity = 2;
};
}  // namespace api

using namespace api;

TEST_CASE_TEMPLATE("machine{chart, context, observer} deduces machine<decltype(chart), default_policy, Observer>",
                   Backend, compiled, table) {
    using machine = machine_t<Backend, decltype(chart)>;
    static_assert(std::is_same_v<decltype(Backend::deduce(chart)), machine>);
    static_assert(std::is_same_v<decltype(Backend::deduce(chart, counter{})), machine>);
    static_assert(std::is_same_v<decltype(Backend::deduce(chart, counter{}, trace_observer{})),
                                 machine_t<Backend, decltype(chart), bsc::default_policy, trace_observer>>);
    static_assert(std::is_same_v<typename machine::chart_type, std::remove_const_t<decltype(chart)>>);
    static_assert(std::is_same_v<typename machine::context_type, counter>);
    // A policy and an observer given explicitly are the machine's, not the defaults.
    using scanning = machine_t<Backend, decltype(chart), bsc::scan_policy, trace_observer>;
    static_assert(std::is_same_v<typename scanning::policy_type, bsc::scan_policy>);
    static_assert(std::is_same_v<typename scanning::observer_type, trace_observer>);
    auto m = Backend::deduce(chart, counter{3});
    CHECK(m.context().count == 3);
    CHECK(m.template is<A1>());
    CHECK(m.last_outcome() == bsc::outcome::ignored);  // construction fired no transition
}

TEST_CASE_TEMPLATE("the active configuration takes one byte per composite state", Backend, compiled, table) {
    using machine = machine_t<Backend, decltype(chart)>;
    CHECK(sizeof(typename machine::configuration_type) == 4);
    // One byte per composite (Root, A, B, R1); P, a parallel state, has none.
    machine m{chart, counter{}};
    auto const before = m.active_configuration();
    m.dispatch(go{});
    CHECK(m.active_configuration() != before);  // the bytes hold the configuration
}

TEST_CASE_TEMPLATE("is<S> and active_states follow the configuration, composites and parallel states included", Backend,
                   compiled, table) {
    machine_t<Backend, decltype(chart)> m{chart, counter{}};
    CHECK(m.template is<Root>());
    CHECK(m.template is<A>());
    CHECK(m.template is<A1>());
    CHECK_FALSE(m.template is<A2>());
    CHECK_FALSE(m.template is<B>());
    CHECK_FALSE(m.template is<B1>());  // B's byte says B1, but B is inactive
    CHECK(m.active_states().joined() == "Root A A1");
    for (int i = 0; i < 4; ++i) CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(m.template is<P>());
    CHECK(m.template is<X>());
    CHECK(m.template is<Y>());
    CHECK_FALSE(m.template is<B1>());
    CHECK(m.active_states().joined() == "Root P R1 X Y");
    CHECK(m.active_states().contains("Y"));
    CHECK(m.active_states().size() == 5);
    CHECK(m.context().count == 1);
    m.dispatch(back{});
    m.dispatch(back{});  // B's deep history: B2
    CHECK(m.active_states().joined() == "Root B B2");
    CHECK(m.last_outcome() == bsc::outcome::consumed);
    CHECK(bsc::name_of<R1> == "R1");
    CHECK(bsc::qualified_name<R1> == "api::R1");
}

TEST_CASE_TEMPLATE("a machine is a value: copies run independently", Backend, compiled, table) {
    machine_t<Backend, decltype(chart)> a{chart, counter{}};
    a.dispatch(go{});
    auto b = a;
    b.dispatch(go{});
    CHECK(a.template is<A2>());
    CHECK(b.template is<B1>());
    b.dispatch(go{});  // B1 -> B2 counts in b's context only
    CHECK(b.context().count == 1);
    CHECK(a.context().count == 0);
    a = b;
    CHECK(a.template is<B2>());
    CHECK(a.context().count == 1);
}

TEST_CASE_TEMPLATE("observers see entries, exits and transitions in order; a machine without one stores nothing for it",
                   Backend, compiled, table) {
    std::string trace;
    machine_t<Backend, decltype(chart), bsc::default_policy, trace_observer> m{chart, counter{},
                                                                               trace_observer{&trace}};
    CHECK(trace == "+Root +A +A1");
    trace.clear();
    m.dispatch(go{});
    m.dispatch(go{});
    CHECK(trace == "-A1 A1>A2 +A2 -A2 -A A2>B +B +B1");

    machine_t<Backend, decltype(chart), bsc::default_policy, partial> p{chart, counter{}, partial{}};
    p.dispatch(go{});
    CHECK(p.observer().exits == 1);
    machine_t<Backend, decltype(chart), bsc::default_policy, row_log> r{chart, counter{}, row_log{}};
    r.dispatch(go{});  // A1 -> A2, the first row
    CHECK(r.observer().calls == 1);
    CHECK(r.observer().last == 0);
    r.dispatch(go{});  // A2 -> B, the second
    CHECK(r.observer().calls == 2);
    CHECK(r.observer().last == 1);

    // An observer without data takes no room, whatever hooks it has; one with data does.
    stateless_calls = 0;
    machine_t<Backend, decltype(chart), bsc::default_policy, stateless_observer> s{chart, counter{}};
    CHECK(stateless_calls == 3);  // +Root +A +A1
    s.dispatch(go{});
    CHECK(stateless_calls == 7);  // -A1, the transition, its row, +A2
    static_assert(std::is_empty_v<stateless_observer>);
    CHECK(sizeof(machine_t<Backend, decltype(chart)>) == sizeof(s));
    CHECK(sizeof(machine_t<Backend, decltype(chart)>) < sizeof(r));
}

TEST_CASE_TEMPLATE("dispatch with allow_unhandled accepts an event no transition handles, and ignores it", Backend,
                   compiled, table) {
    struct stranger {};
    machine_t<Backend, decltype(chart)> m{chart, counter{}};
    auto const before = m.active_configuration();
    CHECK(m.dispatch(stranger{}, bsc::allow_unhandled) == bsc::outcome::ignored);
    CHECK(m.last_outcome() == bsc::outcome::ignored);
    CHECK(m.active_configuration() == before);
    CHECK(m.template is<A1>());
    CHECK(m.dispatch(go{}, bsc::allow_unhandled) == bsc::outcome::consumed);  // a handled event is dispatched
    CHECK(m.template is<A2>());
}

TEST_CASE_TEMPLATE("queue_capacity is the policy's: the number of raised events a dispatch can hold", Backend, compiled,
                   table) {
    static_assert(machine_t<Backend, decltype(raising)>::queue_capacity == bsc::default_policy::queue_capacity);
    using small = machine_t<Backend, decltype(raising), two_events>;
    static_assert(small::queue_capacity == 2);
    small m{raising, counter{}};
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);  // both pings fit, and are processed
    CHECK(m.context().count == 2);
}

TEST_CASE("both back ends keep the same configuration bytes, run for run") {
    using compiled_machine = bsc::machine<decltype(chart)>;
    using table_machine = bsc::table::machine<decltype(chart)>;
    compiled_machine a{chart, counter{}};
    table_machine b{chart, counter{}};
    CHECK(a.active_configuration() == b.active_configuration());
    for (int i = 0; i < 4; ++i) {
        CHECK(a.dispatch(go{}) == b.dispatch(go{}));
        CHECK(a.active_configuration() == b.active_configuration());
    }
    for (int i = 0; i < 2; ++i) {
        CHECK(a.dispatch(back{}) == b.dispatch(back{}));
        CHECK(a.active_configuration() == b.active_configuration());
    }
    CHECK(a.active_states() == b.active_states());
}
