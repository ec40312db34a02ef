// What is particular to the table-driven back end (bsc::table::machine): the tables it
// interprets (the BSTATE and BTRANS rows of the machine-tool paper), the thunks in their
// function-pointer columns, the transitions threaded through first_out/next_out, and the
// delays of the timeout rows. The interface it shares with bsc::machine is tested in
// interface_test.cpp, its semantics in semantics_test.cpp and cycle_test.cpp (both back ends),
// and differential_test.cpp compares the two event by event.

#include <doctest/doctest.h>

#include <chrono>
#include <string>

#include <bsc/table/machine.hpp>

#include "trace.hpp"

#include "inside.hpp"

namespace tbl {
struct go {};
struct back {};
struct A;
struct B;
struct Root;
struct ctx {
    bool flag = false;
    std::string log;
};
inline constexpr auto log = bsc_test::log_action<ctx>;
}  // namespace tbl

using namespace tbl;

// ---- the tables ---------------------------------------------------------------------------------

// The part of the Mode Control Supervisor that Figures 12 and 13 of the machine-tool paper
// [MCS] (docs/references.md) show.
namespace tbl::mcs_like {
struct on_p {};
struct off_p {};
struct estop_p {};
struct reset_p {};
struct mem_p {};
struct mdi_p {};
struct jog_p {};
struct MCS;
struct Off;
struct Estop;
struct On;
struct Auto;
struct Manual;
struct MEM;
struct MDI;
struct JOG;
struct panel {
    int error = 0;
    std::string shown;
};
template <class S>
inline constexpr auto show_entry = [](panel& p) { p.shown += "+" + std::string(bsc::name_of<S>); };
template <class S>
inline constexpr auto show_exit = [](panel& p) { p.shown += "-" + std::string(bsc::name_of<S>); };
inline constexpr auto set_error0 = [](panel& p) { p.error = 0; };
inline constexpr auto set_error1 = [](panel& p) { p.error = 1; };
inline constexpr auto cond = [](panel const& p) { return p.error == 0; };

inline constexpr auto chart = [] {
    using bsc::state, bsc::event, bsc::on_entry, bsc::on_exit;
    return bsc::make_chart<panel>(
        bsc::composite<MCS>(bsc::initial<Off>, state<Off>, state<Estop>,
                            bsc::composite<On>(bsc::deep_history, bsc::initial<Auto>,
                                               bsc::composite<Auto>(bsc::initial<MEM>, state<MDI>),
                                               bsc::composite<Manual>(bsc::initial<JOG>))),
        state<MCS> + on_entry / show_entry<MCS>, state<MCS> + on_exit / show_exit<MCS>,
        state<Off> + on_entry / show_entry<Off>, state<Off> + on_exit / show_exit<Off>,
        state<Estop> + on_entry / show_entry<Estop>, state<Estop> + on_exit / show_exit<Estop>,
        state<On> + on_entry / show_entry<On>, state<On> + on_exit / show_exit<On>,
        state<Auto> + on_entry / show_entry<Auto>, state<MEM> + on_exit / show_exit<MEM>,
        // Figure 13
        state<Off> + event<on_p> = state<On>, state<Estop> + event<reset_p> / set_error0 = state<Estop>,
        state<Estop> + event<off_p>[cond] = state<Off>, state<On> + event<off_p> = state<Off>,
        state<On> + event<estop_p> / set_error1 = state<Estop>,
        // mode changes
        state<MEM> + event<mdi_p> = state<MDI>, state<MDI> + event<mem_p> = state<MEM>,
        state<Auto> + event<jog_p> = state<JOG>, state<Manual> + event<mem_p> = state<MEM>);
}();
using tables = bsc::table::tables<decltype(chart)>;
template <class S>
constexpr bsc::table::state_id id = static_cast<bsc::table::state_id>(tables::state_of<S>);
template <class E>
constexpr bsc::table::event_id event_id = static_cast<bsc::table::event_id>(tables::event_of<E>);

// Whether a function pointer column is set. Checked at run time: GCC does not fold the
// comparison of a function's address with null in a constant expression under sanitizers.
template <class P>
bool set(P p) {
    return p != nullptr;
}
}  // namespace tbl::mcs_like

TEST_CASE("table: the topology table of the MCS holds the rows of Figure 12") {
    using namespace tbl::mcs_like;
    using bsc::table::history_kind;
    using bsc::table::no_state;
    using bsc::table::state_kind;
    constexpr auto const& st = tables::states;
    static_assert(st.size() == tables::state_count && tables::state_count == 10);
    // Row 0 is the implicit top: the ancestor of the root, as 0 is MCS's ancestor in Figure 12.
    static_assert(st[0].status.kind == state_kind::top && st[0].first_child == id<MCS>);
    // { MCS, Off, 0, 0, _noHist, Show, Show }
    static_assert(id<MCS> == 1 && st[1].state == 1);
    static_assert(st[id<MCS>].first_child == id<Off> && st[id<MCS>].next_sibling == no_state &&
                  st[id<MCS>].parent == 0);
    static_assert(st[id<MCS>].status == bsc::table::state_status{state_kind::composite, history_kind::none});
    CHECK((set(st[id<MCS>].entry) && set(st[id<MCS>].exit)));
    // { Off, 0, Estop, MCS, _noHist, Show, Show }, { Estop, 0, On, MCS, _noHist, Show, Show }
    static_assert(st[id<Off>].first_child == no_state && st[id<Off>].next_sibling == id<Estop> &&
                  st[id<Off>].parent == id<MCS>);
    static_assert(st[id<Off>].status.kind == state_kind::basic);
    static_assert(st[id<Estop>].next_sibling == id<On> && st[id<On>].next_sibling == no_state);
    // { On, Auto, 0, MCS, _Hist, Show, Show }, { Auto, MEM, Manual, On, _noHist, Show, 0 }
    static_assert(st[id<On>].first_child == id<Auto> && st[id<On>].parent == id<MCS>);
    static_assert(st[id<On>].status == bsc::table::state_status{state_kind::composite, history_kind::deep});
    static_assert(st[id<Auto>].first_child == id<MEM> && st[id<Auto>].next_sibling == id<Manual>);
    CHECK((set(st[id<Auto>].entry) && !set(st[id<Auto>].exit)));
    static_assert(st[id<MEM>].parent == id<Auto>);
    CHECK((!set(st[id<MEM>].entry) && set(st[id<MEM>].exit)));
    // The Entry and Exit columns call Show.
    panel p;
    inside::queue_type<bsc::table::machine<decltype(chart)>> raise;
    inside::failure_sink const failures{};  // Show does not throw
    st[id<On>].entry(chart, p, raise, failures);
    st[id<MEM>].exit(chart, p, raise, failures);
    CHECK(p.shown == "+On-MEM");
    // The derived columns: initial children, configuration bytes, subtrees.
    static_assert(st[id<MCS>].initial == id<Off> && st[id<Manual>].initial == id<JOG>);
    static_assert(st[id<MCS>].slot == 0 && st[id<On>].slot == 1 && st[id<Off>].slot == -1);
    static_assert(st[id<Estop>].ordinal == 1 && st[id<On>].ordinal == 2);
    static_assert(tables::contains(id<On>, id<JOG>) && !tables::contains(id<On>, id<Estop>));
    static_assert(tables::initial_bytes[1] == 0);  // On starts in Auto
    CHECK(tables::names[id<Manual>] == "Manual");
}

TEST_CASE("table: the transition table of the MCS holds the rows of Figure 13") {
    using namespace tbl::mcs_like;
    using bsc::table::no_state;
    constexpr auto const& t = tables::transitions;
    static_assert(t.size() == 9);
    // { Off, On_P, On, 0, 0 }
    static_assert(t[0].from == id<Off> && t[0].event == event_id<on_p> && t[0].to == id<On>);
    static_assert(t[0].domain == id<MCS>);
    CHECK((!set(t[0].guard) && !set(t[0].action)));
    // { Estop, Reset_P, Estop, 0, Set_Error0 }
    static_assert(t[1].from == id<Estop> && t[1].to == id<Estop>);
    CHECK((!set(t[1].guard) && set(t[1].action)));
    // { Estop, Off_P, Off, cond, 0 }
    static_assert(t[2].from == id<Estop> && t[2].event == event_id<off_p>);
    CHECK((set(t[2].guard) && !set(t[2].action)));
    // { On, Off_P, Off, 0, 0 }, { On, EStop_P, EStop, 0, Set_Error1 }
    static_assert(t[3].from == id<On> && t[3].to == id<Off> && t[4].to == id<Estop>);
    CHECK(set(t[4].action));
    // The domain of a transition from a state to its parent's child is the parent.
    static_assert(t[5].domain == id<Auto> && t[7].domain == id<On>);
    // The pointers call the chart's guard and action with the context and the event.
    panel p;
    off_p const off{};
    reset_p const reset{};
    inside::queue_type<bsc::table::machine<decltype(chart)>> raise;
    p.error = 1;
    CHECK_FALSE(t[2].guard(chart, p, &off));
    t[1].action(chart, p, &reset, raise);
    CHECK(p.error == 0);
    CHECK(t[2].guard(chart, p, &off));
    // The transitions out of each state, threaded through the table in declaration order.
    static_assert(tables::first_out[id<Estop>] == 1 && tables::next_out[1] == 2 && tables::next_out[2] == -1);
    static_assert(tables::first_out[id<MCS>] == -1);
    static_assert(tables::event_count == 7 && !tables::has_eventless && tables::handles(event_id<jog_p>));
}

TEST_CASE("table: the MCS interpreted from its tables") {
    using namespace tbl::mcs_like;
    bsc::table::machine m{chart, panel{}};
    CHECK(m.context().shown == "+MCS+Off");
    m.dispatch(on_p{});
    m.dispatch(mdi_p{});
    CHECK(m.active_states().joined() == "MCS On Auto MDI");
    m.dispatch(estop_p{});
    CHECK(m.context().error == 1);
    CHECK(m.dispatch(off_p{}) == bsc::outcome::ignored);  // cond: the error is still set
    m.dispatch(reset_p{});
    m.dispatch(off_p{});
    m.dispatch(on_p{});  // deep history: back in MDI
    CHECK(m.active_states().joined() == "MCS On Auto MDI");
}

TEST_CASE("table: an internal transition has no destination; an eventless one has event -1") {
    static constexpr auto chart = bsc::make_chart<ctx>(
        bsc::composite<Root>(bsc::initial<A>, bsc::state<B>),
        bsc::state<A>[([](ctx const& c) { return c.flag; })] = bsc::state<B>,
        bsc::state<B> + bsc::event<go> / log("go"), bsc::state<B> + bsc::event<back> = bsc::state<A>);
    using tables = bsc::table::tables<decltype(chart)>;
    using tbl::mcs_like::set;
    static_assert(tables::transitions[0].event == bsc::table::eventless_id);
    CHECK(set(tables::transitions[0].guard));
    static_assert(tables::transitions[1].to == bsc::table::no_state);
    CHECK(set(tables::transitions[1].action));
    static_assert(tables::first_out[2] == 0 && tables::first_out[3] == 1 && tables::next_out[1] == 2);
    static_assert(tables::next_out[2] == -1);
}

// ---- timeout rows and the components of a cycle -------------------------------------------------

namespace tbl::timed {
struct Top;
struct Par;
struct Left;
struct L1;
struct L2;
struct Right;
struct Wait;
struct Idle;
struct data {
    bsc::input<bool> go;
};
using namespace std::chrono_literals;
inline constexpr auto chart = [] {
    using bsc::state, bsc::after;
    return bsc::make_chart<data>(
        bsc::composite<Top>(bsc::initial<Par>,
                            bsc::parallel<Par>(bsc::composite<Left>(bsc::initial<L1>, state<L2>), state<Right>),
                            state<Wait>, state<Idle>),
        state<L1> + after(250ms) = state<L2>, state<L2>[([](data const& d) { return d.go.get(); })] = state<L1>,
        state<Right> + after(2s)[([](data const& d) { return d.go.get(); })] = state<Wait>,
        state<Wait> + after(1500us)[([](data const& d) { return d.go.get(); })] = state<Idle>,
        state<Wait> + after(3s) = state<Par>,  // the shorter one is guarded: unguarded, it would make this one dead
        state<Idle> + bsc::event<go> = state<Par>);
}();
using tables = bsc::table::tables<decltype(chart)>;
template <class S>
constexpr bsc::table::state_id id = static_cast<bsc::table::state_id>(tables::state_of<S>);
}  // namespace tbl::timed

TEST_CASE("table: timeout rows read their delay from the chart; their origins keep an entry time; the components") {
    using namespace tbl::timed;
    using bsc::table::timeout_id;
    constexpr auto const& t = tables::transitions;
    static_assert(t[0].event == timeout_id && t[1].event == bsc::table::eventless_id && t[5].event >= 0);
    CHECK(t[0].delay(chart) == 250ms);
    CHECK(t[2].delay(chart) == 2s);
    CHECK(t[3].delay(chart) == 1500us);
    CHECK(t[4].delay(chart) == 3s);
    CHECK((tbl::mcs_like::set(t[2].guard) && !tbl::mcs_like::set(t[0].guard)));
    CHECK((!tbl::mcs_like::set(t[1].delay) && !tbl::mcs_like::set(t[5].delay)));
    // One slot per timeout row, numbered by origin in document order, then by row: a state's
    // slots are contiguous, and its entry arms them all.
    static_assert(tables::timeout_slots == 4);
    static_assert(tables::states[id<L1>].timeout_slot == 0 && tables::states[id<Right>].timeout_slot == 1);
    static_assert(tables::states[id<Wait>].timeout_slot == 2 && tables::states[id<Wait>].timeout_slots == 2);
    static_assert(tables::states[id<L2>].timeout_slot == -1 && tables::states[id<L2>].timeout_slots == 0);
    static_assert(t[0].timeout_slot == 0 && t[1].timeout_slot == -1 && t[2].timeout_slot == 1);
    static_assert(t[3].timeout_slot == 2 && t[4].timeout_slot == 3 && t[5].timeout_slot == -1);
    // The components of a cycle: the root and the regions of the parallel state, in document order.
    static_assert(tables::components.size() == 3);
    static_assert(tables::components[0] == id<Top> && tables::components[1] == id<Left> &&
                  tables::components[2] == id<Right>);
    static_assert(tables::has_conditions && !tbl::mcs_like::tables::has_conditions);

    bsc::table::machine m{chart, data{}};
    m.step(0ms);
    CHECK(m.step(250ms).transitions == 1);  // Left: L1's timeout
    CHECK(m.is<L2>());
    m.context().go.set(true);
    auto const r = m.step(2s);  // Left: L2 [go]; Right: its guarded timeout
    CHECK(r.transitions == 2);
    CHECK(m.is<Wait>());
    CHECK(m.now() == 2s);
    m.step(2s + 1ms);
    CHECK(m.is<Wait>());
    m.step(2s + 1500us);
    CHECK(m.is<Idle>());
}
