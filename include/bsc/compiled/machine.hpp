#pragma once
// bsc::machine: the compiled back end. For an event type, dispatch is a nest of switches on
// the configuration bytes that visits only the states where a transition on that event can
// leave; at each basic state the candidate transitions, their exits, action and entries are
// straight-line code fixed at compile time. Parallel regions select first and fire after,
// as SCXML's microstep does.

#include <algorithm>
#include <array>
#include <boost/hana/at.hpp>
#include <cstddef>
#include <cstdint>
#include <utility>

#include <bsc/chart.hpp>
#include <bsc/checks/errors.hpp>
#include <bsc/compiled/plan.hpp>
#include <bsc/configuration.hpp>
#include <bsc/detail/context_data.hpp>
#include <bsc/detail/event_queue.hpp>
#include <bsc/detail/meta.hpp>
#include <bsc/detail/topology.hpp>
#include <bsc/detail/type_name.hpp>
#include <bsc/observer.hpp>
#include <bsc/outcome.hpp>

namespace bsc::detail {
// Read-write access to a machine's run-time state, for the state-space explorer only.
struct machine_access {
    template <class M>
    static constexpr auto& configuration(M& m) {
        return m.config_;
    }
    template <class M>
    static constexpr auto& clock(M& m) {
        return m.clock_;
    }
    template <class M>
    static constexpr auto& armed(M& m) {
        return m.armed_;
    }
    template <class M>
    static constexpr auto& last_outcome(M& m) {
        return m.last_;
    }
    template <class M>
    static constexpr auto longest_timeout(M const& m) {
        return m.longest_timeout();
    }
    template <class M>
    static constexpr auto canonical_configuration(M const& m) {
        return m.canonical_configuration();
    }
    template <class M>
    static constexpr bool timeout_armed(M const& m, std::size_t slot) {
        return m.timeout_armed(slot);
    }
    template <class M>
    static constexpr auto active_flags(M const& m) {
        return m.active_flags();
    }
};
}  // namespace bsc::detail

namespace bsc::detail {
// Whether any action of the chart can raise an event; if none can, the machine has no queue.
template <class An, class Policy>
constexpr bool chart_may_raise() {
    using context = typename An::chart_context;
    using raise = event_queue<Policy::queue_capacity, typename An::events>;
    return []<class... Rows>(type_list<Rows...>) {
        // The event an action sees: the row's event, or bsc::eventless for condition-driven
        // rows (entry and exit rows see none; may_raise ignores it for them).
        return (may_raise<context, std::conditional_t<std::is_void_v<typename trigger_event<Rows>::type>, eventless_trigger,
                                                      typename trigger_event<Rows>::type>,
                          raise>(
                    static_cast<decltype(Rows::action) const*>(nullptr)) ||
                ...);
    }(typename An::rows{});
}
}  // namespace bsc::detail

namespace bsc {

/// A running instance of a chart: its context, its active configuration and its internal
/// event queue. Construction enters the initial configuration; dispatch(e) processes one
/// event to completion; step(now) runs one BSC execution cycle. No heap, no virtual calls,
/// no RTTI, no exceptions.
///
/// Requirements: `Chart` comes from bsc::make_chart; `Policy` has the members of
/// bsc::default_policy; `Observer` implements any subset of the hooks in observer.hpp.
template <class Chart, class Policy = default_policy, class Observer = no_observer>
class machine {
    using an = detail::analysis<std::remove_cv_t<Chart>>;
    using plan = detail::plan<an>;
    static constexpr auto const& topo = an::topo;
    static constexpr auto const& table = an::table;
    static constexpr int root = 1;

public:
    using chart_type = std::remove_cv_t<Chart>;
    using context_type = typename chart_type::context_type;
    using configuration_type = configuration<static_cast<std::size_t>(topo.slots)>;
    using queue_type = std::conditional_t<detail::chart_may_raise<an, Policy>(), detail::event_queue<Policy::queue_capacity, typename an::events>,
                                          detail::no_event_queue<typename an::events>>;
    using event_types = typename an::events;

    /// Enters the initial configuration (entry actions run) and settles eventless transitions.
    constexpr explicit machine(Chart const& chart, context_type context = {}, Observer observer = {})
        : chart_(chart), context_(std::move(context)), observer_(std::move(observer)) {
        if constexpr (topo.slots > 0)
            config_.active = plan::template initial_bytes<topo.slots>();
        detail::latch_inputs(context_);
        enter_default<root>();
        last_ = finish(false);
        detail::commit_outputs(context_);
    }

    /// One BSC execution cycle at time `now` (seed 002): timers are updated, input channels
    /// latched; then each component (the root and every region of a parallel state), in
    /// document order, fires at most one eventless or timeout transition, its actions' writes
    /// visible at once to the components after it; events raised meanwhile are processed; output
    /// channels are committed. Components entered during the cycle first run in the next one.
    /// Time never runs backwards for the machine: an earlier `now` is reported and ignored.
    constexpr step_report step(duration now) {
        step_report report;
        if (halted()) {
            report.status = last_ = outcome::halted;
            return report;
        }
        if (now < clock_)
            report.clock_went_backwards = true;
        else
            clock_ = now;
        detail::update_timers(context_, clock_);
        detail::latch_inputs(context_);
        constexpr auto const& comps = plan::components;
        std::array<bool, comps.size()> active_at_start{};
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            ((active_at_start[I] = active_on_path<comps[I]>()), ...);
            ((report.transitions += active_at_start[I] && active_on_path<comps[I]>() &&
                                    component_step<comps[I], comps[I]>()),
             ...);
        }(std::make_index_sequence<comps.size()>{});
        report.status = last_ = drain_queue(report.transitions > 0);
        detail::commit_outputs(context_);
        return report;
    }

    /// The time of the last cycle (the machine's clock).
    constexpr duration now() const { return clock_; }

    /// Processes e to completion: the transitions it enables, then eventless transitions and
    /// raised events until none remain. Fails to compile if no transition handles E.
    template <class E>
    constexpr outcome dispatch(E const& e) {
        constexpr int trigger = an::template trigger_of<E>;
        if constexpr (trigger < 0) {
            static_assert(error::unhandled_event<E>::value);
            return outcome::ignored;
        } else {
            return process<trigger>(e);
        }
    }

    /// As dispatch(e), but an event type that no transition handles is accepted and ignored.
    template <class E>
    constexpr outcome dispatch(E const& e, allow_unhandled_t) {
        constexpr int trigger = an::template trigger_of<E>;
        if constexpr (trigger < 0)
            return last_ = outcome::ignored;
        else
            return process<trigger>(e);
    }

    /// True if state S is active.
    template <class S>
    constexpr bool is() const {
        constexpr int s = an::template index_of_state<S>;
        if constexpr (s < 0) {
            static_assert(error::state_not_in_chart<S>::value);
            return false;
        } else {
            return active_on_path<s>();
        }
    }

    /// True once a final child of the root is active: the machine processes nothing more.
    constexpr bool halted() const {
        if constexpr (has_final_root_child) {
            bool result = false;
            detail::visit_index<topo.child_count[root]>(active_child<root>(), [&](auto i) {
                result = topo.kinds[static_cast<std::size_t>(plan::template children<root>[decltype(i)::value])] ==
                         detail::kind::final_state;
            });
            return result;
        } else {
            return false;
        }
    }

    /// The names of the active states, outermost first, in document order.
    constexpr auto active_states() const {
        state_names<static_cast<std::size_t>(an::N)> names;
        auto const active = active_flags();
        for (std::size_t s = 1; s < static_cast<std::size_t>(an::N); ++s)
            if (active[s]) names.push_back(state_name_table[s]);
        return names;
    }

    /// The outcome of the last dispatch (or of construction).
    constexpr outcome last_outcome() const { return last_; }

    constexpr context_type& context() { return context_; }
    constexpr context_type const& context() const { return context_; }
    constexpr configuration_type const& active_configuration() const { return config_; }
    constexpr Observer& observer() { return observer_; }
    constexpr Observer const& observer() const { return observer_; }
    constexpr queue_type const& queue() const { return queue_; }

private:
    // ---- state access ------------------------------------------------------------------
    constexpr std::uint8_t config_byte(int slot) const {
        if constexpr (topo.slots > 0)
            return config_.active[static_cast<std::size_t>(slot)];
        else
            return 0;
    }
    template <int S>
    constexpr int active_child() const {
        if constexpr (topo.slot[S] >= 0)
            return config_.active[static_cast<std::size_t>(topo.slot[S])];
        else
            return 0;  // the top has one child
    }
    template <int S>
    constexpr void set_active_child(int ordinal) {
        if constexpr (topo.slot[S] >= 0)
            config_.active[static_cast<std::size_t>(topo.slot[S])] = static_cast<std::uint8_t>(ordinal);
    }
    template <int S>
    constexpr bool active_on_path() const {
        if constexpr (S <= root) {
            return true;
        } else {
            constexpr int p = topo.parent[S];
            if constexpr (topo.slot[p] >= 0)
                return active_child<p>() == topo.ordinal[S] && active_on_path<p>();
            else
                return active_on_path<p>();
        }
    }

    static constexpr bool has_final_root_child = [] {
        if (topo.kinds[root] != detail::kind::composite)
            return false;
        for (int c : plan::template children<root>)
            if (topo.kinds[static_cast<std::size_t>(c)] == detail::kind::final_state)
                return true;
        return false;
    }();

    static constexpr auto state_name_table = []<class... Tags>(detail::type_list<Tags...>) {
        return std::array<std::string_view, sizeof...(Tags)>{name_of<Tags>...};
    }(typename an::tags{});

    template <int Row>
    constexpr auto const& row() const {
        return boost::hana::at_c<static_cast<std::size_t>(Row)>(chart_.rows);
    }

    // ---- entry and exit ----------------------------------------------------------------
    template <int S>
    constexpr void run_entry() {
        constexpr auto const& rows = plan::template state_rows<detail::row_kind::entry, S>;
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            (row<rows[I]>().action(context_, queue_), ...);
        }
        (std::make_index_sequence<rows.size()>{});
        if constexpr (plan::timeout_slot[S] >= 0)
            armed_[static_cast<std::size_t>(plan::timeout_slot[S])] = clock_;
        using tag = state_tag<typename an::template tag_at<S>>;
        if constexpr (detail::observes_entry<Observer, tag>)
            observer_.on_entry(tag{});
    }

    template <int S>
    constexpr void run_exit() {
        constexpr auto const& rows = plan::template state_rows<detail::row_kind::exit, S>;
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            (row<rows[I]>().action(context_, queue_), ...);
        }
        (std::make_index_sequence<rows.size()>{});
        using tag = state_tag<typename an::template tag_at<S>>;
        if constexpr (detail::observes_exit<Observer, tag>)
            observer_.on_exit(tag{});
    }

    template <int S, class F>
    static constexpr void for_each_child(F&& f) {
        constexpr auto const& kids = plan::template children<S>;
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            (f(detail::int_c<kids[I]>{}), ...);
        }
        (std::make_index_sequence<kids.size()>{});
    }

    // Calls f(child) for the active child of composite S if it is one of the children the
    // trigger makes relevant; returns false (without calling f) otherwise.
    template <int Trigger, int S, class F>
    constexpr bool with_relevant_active_child(F&& f) const {
        constexpr auto const& kids = plan::template relevant_children<Trigger, S>;
        int const active = active_child<S>();
        return [&]<std::size_t... I>(std::index_sequence<I...>) {
            return ((active == topo.ordinal[kids[I]] ? (f(detail::int_c<kids[I]>{}), true) : false) || ...);
        }(std::make_index_sequence<kids.size()>{});
    }

    template <int S, class F>
    constexpr void with_active_child(F&& f) const {
        constexpr auto const& kids = plan::template children<S>;
        detail::visit_index<static_cast<int>(kids.size())>(
            active_child<S>(), [&](auto i) { f(detail::int_c<kids[decltype(i)::value]>{}); });
    }

    // Enters S and its default (or history) completion.
    template <int S>
    constexpr void enter_default() {
        run_entry<S>();
        enter_content<S>();
    }

    template <int S>
    constexpr void enter_content() {
        constexpr auto k = topo.kinds[S];
        if constexpr (k == detail::kind::composite) {
            constexpr auto h = topo.hist[S];
            if constexpr (h == detail::history::none) {
                constexpr int init = topo.initial[S];
                set_active_child<S>(topo.ordinal[init]);
                enter_default<init>();
            } else if constexpr (h == detail::history::shallow) {
                with_active_child<S>([&](auto c) { enter_default<decltype(c)::value>(); });
            } else {
                with_active_child<S>([&](auto c) { enter_restore<decltype(c)::value>(); });
            }
        } else if constexpr (k == detail::kind::parallel) {
            for_each_child<S>([&](auto c) { enter_default<decltype(c)::value>(); });
        }
    }

    // Deep history: re-enters S and the sub-configuration its bytes remember.
    template <int S>
    constexpr void enter_restore() {
        run_entry<S>();
        constexpr auto k = topo.kinds[S];
        if constexpr (k == detail::kind::composite)
            with_active_child<S>([&](auto c) { enter_restore<decltype(c)::value>(); });
        else if constexpr (k == detail::kind::parallel)
            for_each_child<S>([&](auto c) { enter_restore<decltype(c)::value>(); });
    }

    // Enters, below the active state D, the path to Target (and parallel siblings on the way).
    template <int D, int Target>
    constexpr void enter_toward() {
        constexpr int c = topo.child_toward(D, Target);
        if constexpr (topo.kinds[D] == detail::kind::parallel) {
            for_each_child<D>([&](auto k) {
                if constexpr (decltype(k)::value == c)
                    enter_path_node<c, Target>();
                else
                    enter_default<decltype(k)::value>();
            });
        } else {
            set_active_child<D>(topo.ordinal[c]);
            enter_path_node<c, Target>();
        }
    }
    template <int C, int Target>
    constexpr void enter_path_node() {
        run_entry<C>();
        if constexpr (C == Target)
            enter_content<C>();
        else
            enter_toward<C, Target>();
    }

    // Exits the active descendants of S, innermost first, in reverse document order.
    template <int S>
    constexpr void exit_below() {
        constexpr auto k = topo.kinds[S];
        if constexpr (k == detail::kind::composite || k == detail::kind::top) {
            with_active_child<S>([&](auto c) {
                exit_below<decltype(c)::value>();
                run_exit<decltype(c)::value>();
            });
        } else if constexpr (k == detail::kind::parallel) {
            constexpr auto const& kids = plan::template children<S>;
            [&]<std::size_t... I>(std::index_sequence<I...>) {
                ((exit_below<kids[kids.size() - 1 - I]>(), run_exit<kids[kids.size() - 1 - I]>()), ...);
            }
            (std::make_index_sequence<kids.size()>{});
        }
    }

    // Exits the known path from basic state X up to, not including, D.
    template <int X, int D>
    constexpr void exit_up() {
        if constexpr (X != D) {
            run_exit<X>();
            exit_up<topo.parent[X], D>();
        }
    }

    // ---- transitions -------------------------------------------------------------------
    template <int Row, class E>
    constexpr bool guard_holds(E const& e) const {
        if constexpr (table.guarded[Row])
            return row<Row>().guard(context_, e);
        else
            return true;
    }

    template <int Row, class E>
    constexpr void run_action(E const& e) {
        using R = typename an::template row_at<Row>;
        using src = state_tag<typename R::source>;
        using dst = std::conditional_t<std::is_same_v<typename R::target, detail::no_target>, state_tag<internal>,
                                       state_tag<typename R::target>>;
        if constexpr (detail::observes_transition<Observer, src, dst, E>)
            observer_.on_transition(src{}, dst{}, e);
        if constexpr (detail::observes_rows<Observer>)
            observer_.on_row(Row);
        row<Row>().action(context_, e, queue_);
    }

    template <int Row>
    constexpr void run_entries() {
        constexpr int d = table.domain[Row];
        if constexpr (d >= 0)
            enter_toward<d, table.target[Row]>();
    }

    // Fires a transition selected at basic state Leaf, which no parallel state contains:
    // the exit path is known, so exits, action and entries are straight-line code.
    template <int Leaf, int Row, class E>
    constexpr void fire_from(E const& e) {
        constexpr int d = table.domain[Row];
        if constexpr (d >= 0)
            exit_up<Leaf, d>();
        run_action<Row>(e);
        run_entries<Row>();
    }

    // The transitions selected in parallel regions, fired together after selection.
    struct no_selection {};  // for charts without parallel states
    struct selection {
        std::array<std::uint16_t, static_cast<std::size_t>(plan::max_active_leaves(root))> rows{};
        std::size_t size = 0;
        constexpr void add(int position) {
            for (std::size_t i = 0; i < size; ++i)
                if (rows[i] == position)
                    return;
            rows[size++] = static_cast<std::uint16_t>(position);
        }
    };

    // A region-local trigger's selection: per zone, 0 or 1 + the row's index in its zone_rows.
    struct zone_selection {
        std::array<std::uint8_t, plan::components.size()> chosen{};
    };

    // Transitions of such a trigger fire where they are selected, as outside parallel states,
    // when no observer could see the order of exits and entries change.
    template <int Trigger>
    static constexpr bool fires_at_selection =
        plan::template fires_at_selection<Trigger> && std::is_same_v<Observer, no_observer>;

    template <int Trigger>
    using selection_for = std::conditional_t<
        !plan::has_parallel || fires_at_selection<Trigger>, no_selection,
        std::conditional_t<plan::template region_local<Trigger>, zone_selection, selection>>;

    template <int Leaf, int Trigger, int Row, class E, class Sel>
    constexpr bool try_row(E const& e, Sel& sel) {
        if (!guard_holds<Row>(e))
            return false;
        if constexpr (!topo.under_parallel(Leaf) || fires_at_selection<Trigger>)
            fire_from<Leaf, Row>(e);
        else if constexpr (plan::template region_local<Trigger>)
            sel.chosen[static_cast<std::size_t>(plan::zone[Leaf])] = static_cast<std::uint8_t>(plan::template zone_code<Trigger, Row>);
        else
            sel.add(plan::template position_of<Trigger>(Row));
        return true;
    }

    template <int Leaf, int Trigger, class E, class Sel>
    constexpr bool try_leaf(E const& e, Sel& sel) {
        constexpr auto const& cands = plan::template candidates<Leaf, Trigger>;
        return [&]<std::size_t... I>(std::index_sequence<I...>) {
            return (try_row<Leaf, Trigger, cands[I]>(e, sel) || ...);
        }
        (std::make_index_sequence<cands.size()>{});
    }

    // Walks the active configuration below S, visiting only states relevant to the trigger.
    template <int S, int Trigger, class E, class Sel>
    constexpr bool select(E const& e, Sel& sel) {
        constexpr auto k = topo.kinds[S];
        if constexpr (!plan::template relevant<Trigger>[S]) {
            return false;
        } else if constexpr (k == detail::kind::basic || k == detail::kind::final_state) {
            return try_leaf<S, Trigger>(e, sel);
        } else if constexpr (k == detail::kind::parallel) {
            bool any = false;
            for_each_child<S>([&](auto c) { any = select<decltype(c)::value, Trigger>(e, sel) || any; });
            return any;
        } else {
            bool any = false;
            with_relevant_active_child<Trigger, S>([&](auto c) { any = select<decltype(c)::value, Trigger>(e, sel); });
            return any;
        }
    }

    template <int Trigger, class F>
    static constexpr void with_transition(int position, F&& f) {
        constexpr auto const& rows = plan::template transitions<Trigger>;
        detail::visit_index<static_cast<int>(rows.size())>(
            position, [&](auto i) { f(detail::int_c<rows[decltype(i)::value]>{}); });
    }

    // SCXML: drop transitions whose exit sets meet an earlier one's, unless the later one's
    // source is a descendant of the earlier one's (then it preempts it); then exit all,
    // run the actions in order, enter all.
    template <int Trigger, class E>
    constexpr void fire_selected(E const& e, selection const& sel) {
        constexpr auto const& rows = plan::template transitions<Trigger>;
        selection kept;
        for (std::size_t i = 0; i < sel.size; ++i) {
            int const t1 = rows[sel.rows[i]];
            bool preempted = false;
            selection survivors;
            for (std::size_t j = 0; j < kept.size; ++j) {
                int const t2 = rows[kept.rows[j]];
                if (!plan::conflict(t1, t2)) {
                    survivors.add(kept.rows[j]);
                } else if (topo.is_proper_ancestor(table.source[static_cast<std::size_t>(t2)],
                                                   table.source[static_cast<std::size_t>(t1)])) {
                    continue;  // t1 preempts t2
                } else {
                    preempted = true;
                    break;
                }
            }
            if (!preempted) {
                survivors.add(sel.rows[i]);
                kept = survivors;
            }
        }
        for (std::size_t i = kept.size; i-- > 0;)
            with_transition<Trigger>(kept.rows[i], [&](auto r) {
                constexpr int d = table.domain[decltype(r)::value];
                if constexpr (d >= 0)
                    exit_below<d>();
            });
        for (std::size_t i = 0; i < kept.size; ++i)
            with_transition<Trigger>(kept.rows[i], [&](auto r) { run_action<decltype(r)::value>(e); });
        for (std::size_t i = 0; i < kept.size; ++i)
            with_transition<Trigger>(kept.rows[i], [&](auto r) { run_entries<decltype(r)::value>(); });
    }

    // Calls f(row) for the row chosen in zone Z, if any.
    template <int Trigger, int Z, class F>
    static constexpr void with_chosen(std::uint8_t code, F&& f) {
        constexpr auto const& rows = plan::template zone_rows<Trigger, Z>;
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            (void)((code == I + 1 ? (f(detail::int_c<rows[I]>{}), true) : false) || ...);
        }(std::make_index_sequence<rows.size()>{});
    }

    // A region-local trigger's transitions: none conflicts with another, so all fire; the zones
    // are disjoint and visited in document order, which is the order SCXML fires them in.
    template <int Trigger, class E>
    constexpr void fire_zones(E const& e, zone_selection const& sel) {
        constexpr auto const& zones = plan::template selecting_zones<Trigger>;
        constexpr std::size_t n = zones.size();
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            (with_chosen<Trigger, zones[n - 1 - I]>(sel.chosen[static_cast<std::size_t>(zones[n - 1 - I])], [&](auto r) {
                 constexpr int d = table.domain[decltype(r)::value];
                 if constexpr (d >= 0)
                     exit_below<d>();
             }),
             ...);
            (with_chosen<Trigger, zones[I]>(sel.chosen[static_cast<std::size_t>(zones[I])],
                                            [&](auto r) { run_action<decltype(r)::value>(e); }),
             ...);
            (with_chosen<Trigger, zones[I]>(sel.chosen[static_cast<std::size_t>(zones[I])],
                                            [&](auto r) { run_entries<decltype(r)::value>(); }),
             ...);
        }(std::make_index_sequence<n>{});
    }

    // One microstep on a trigger; true if a transition fired.
    template <int Trigger, class E>
    constexpr bool microstep(E const& e) {
        if constexpr (!plan::has_trigger(Trigger)) {
            return false;
        } else {
            using sel_type = selection_for<Trigger>;
            sel_type sel;
            bool const any = select<0, Trigger>(e, sel);
            if constexpr (std::is_same_v<sel_type, zone_selection>) {
                if (any)
                    fire_zones<Trigger>(e, sel);
            } else if constexpr (std::is_same_v<sel_type, selection>) {
                if (sel.size > 0)
                    fire_selected<Trigger>(e, sel);
            }
            return any;
        }
    }

    template <int Trigger, class E>
    constexpr outcome process(E const& e) {
        if (halted())
            return last_ = outcome::halted;
        detail::latch_inputs(context_);
        last_ = finish(microstep<Trigger>(e));
        detail::commit_outputs(context_);
        return last_;
    }

    // ---- the BSC cycle -----------------------------------------------------------------
    template <int Row>
    constexpr bool condition_holds() const {
        if constexpr (table.trigger[Row] <= detail::timeout_trigger_id(0)) {
            constexpr int slot = plan::timeout_slot[table.source[Row]];
            if (clock_ - armed_[static_cast<std::size_t>(slot)] < row<Row>().trigger_value.delay)
                return false;
        }
        return guard_holds<Row>(eventless{});
    }

    template <int Row>
    constexpr void fire_condition() {
        constexpr int d = table.domain[Row];
        if constexpr (d >= 0)
            exit_below<d>();
        run_action<Row>(eventless{});
        run_entries<Row>();
    }

    template <int Frontier, int Component>
    constexpr bool try_component_candidates() {
        constexpr auto const& cands = plan::template component_candidates<Frontier, Component>;
        return [&]<std::size_t... I>(std::index_sequence<I...>) {
            return ((condition_holds<cands[I]>() && (fire_condition<cands[I]>(), true)) || ...);
        }(std::make_index_sequence<cands.size()>{});
    }

    // Walks a component from S down to its active frontier and fires its first enabled
    // condition-driven transition, if any.
    template <int S, int Component>
    constexpr bool component_step() {
        constexpr auto k = topo.kinds[S];
        if constexpr (!plan::template relevant<detail::any_condition>[S]) {
            return false;
        } else if constexpr (k == detail::kind::composite) {
            // An irrelevant child has no condition-driven transition on it or above it.
            bool fired = false;
            with_relevant_active_child<detail::any_condition, S>(
                [&](auto c) { fired = component_step<decltype(c)::value, Component>(); });
            return fired;
        } else {
            return try_component_candidates<S, Component>();
        }
    }

    // Which states are active, by index (outermost first, so one pass suffices).
    constexpr std::array<bool, static_cast<std::size_t>(an::N)> active_flags() const {
        std::array<bool, static_cast<std::size_t>(an::N)> active{};
        active[0] = true;
        for (std::size_t s = 1; s < static_cast<std::size_t>(an::N); ++s) {
            auto const p = static_cast<std::size_t>(topo.parent[s]);
            active[s] = active[p] && (topo.slot[p] < 0 ||
                                      config_byte(topo.slot[p]) == static_cast<std::uint8_t>(topo.ordinal[s]));
        }
        return active;
    }

    // The configuration with every byte that can never matter again reset to its initial
    // child: the byte of an inactive composite that neither has history nor lies below a
    // deep history. Two machines with equal canonical configurations behave the same.
    constexpr configuration_type canonical_configuration() const {
        configuration_type c = config_;
        if constexpr (topo.slots > 0) {
            auto const active = active_flags();
            for (std::size_t s = 1; s < static_cast<std::size_t>(an::N); ++s) {
                if (topo.slot[s] < 0 || active[s]) continue;
                bool remembered = topo.hist[s] != detail::history::none;
                for (int a = topo.parent[s]; a > 0 && !remembered; a = topo.parent[static_cast<std::size_t>(a)])
                    remembered = topo.hist[static_cast<std::size_t>(a)] == detail::history::deep;
                if (!remembered)
                    c.active[static_cast<std::size_t>(topo.slot[s])] = static_cast<std::uint8_t>(
                        topo.ordinal[static_cast<std::size_t>(topo.initial[s])]);
            }
        }
        return c;
    }

    // A timeout slot's age matters only while its state is active.
    constexpr bool timeout_armed(std::size_t slot) const {
        auto const active = active_flags();
        for (std::size_t s = 0; s < static_cast<std::size_t>(an::N); ++s)
            if (plan::timeout_slot[s] == static_cast<int>(slot)) return active[s];
        return false;
    }

    // The longest delay of any timeout row: past it, a state's age no longer matters.
    constexpr duration longest_timeout() const {
        duration longest{};
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            (
                [&] {
                    if constexpr (table.trigger[I] <= detail::timeout_trigger_id(0))
                        longest = std::max(longest, row<static_cast<int>(I)>().trigger_value.delay);
                }(),
                ...);
        }(std::make_index_sequence<static_cast<std::size_t>(an::R)>{});
        return longest;
    }

    // Raised events of a cycle: each one microstep, no eventless settling (one transition
    // per component per cycle).
    constexpr outcome drain_queue(bool consumed) {
        for (std::size_t n = 0; !queue_.empty() && !halted();) {
            if (++n > Policy::max_internal_events)
                return abandon();
            queue_.pop([&](auto const& ev) { microstep<an::template trigger_of<std::decay_t<decltype(ev)>>>(ev); });
        }
        if (queue_.overflowed()) {
            queue_.clear_overflow();
            return outcome::queue_overflow;
        }
        return consumed ? outcome::consumed : outcome::ignored;
    }

    // Settles the machine after a microstep: eventless transitions until none is enabled,
    // then the raised events one by one, each followed by its eventless transitions.
    constexpr outcome finish(bool consumed) {
        if constexpr (!Policy::settle_eventless)
            return drain_queue(consumed);
        // The common case, kept inline: nothing raised, and no eventless transition to try.
        if constexpr (!plan::has_trigger(detail::eventless_id))
            if (queue_.empty() && !queue_.overflowed())
                return consumed ? outcome::consumed : outcome::ignored;
        return settle(consumed);
    }

    constexpr outcome settle(bool consumed) {
        std::size_t internal_events = 0;
        for (;;) {
            if constexpr (plan::has_trigger(detail::eventless_id)) {
                // Up to max_eventless_steps transitions settle; one more means the chart cycles.
                for (std::size_t steps = 0; !halted() && microstep<detail::eventless_id>(eventless{});)
                    if (++steps > Policy::max_eventless_steps)
                        return abandon();
            }
            if (queue_.empty() || halted())
                break;
            if (++internal_events > Policy::max_internal_events)
                return abandon();
            queue_.pop([&](auto const& ev) { microstep<an::template trigger_of<std::decay_t<decltype(ev)>>>(ev); });
        }
        if (queue_.overflowed()) {
            queue_.clear_overflow();
            return outcome::queue_overflow;
        }
        return consumed ? outcome::consumed : outcome::ignored;
    }

    constexpr outcome abandon() {
        queue_.clear();
        queue_.clear_overflow();
        return outcome::livelock;
    }

    friend struct detail::machine_access;

    [[no_unique_address]] chart_type chart_;
    context_type context_;
    configuration_type config_{};
    [[no_unique_address]] queue_type queue_{};
    duration clock_{};
    std::array<duration, static_cast<std::size_t>(plan::timeout_slots)> armed_{};  // entry times
    outcome last_ = outcome::ignored;
    [[no_unique_address]] Observer observer_;
};

// Charts are declared `constexpr`, so `machine{chart, ...}` and `machine<decltype(chart)>` name
// the same type.
template <class C, class Ctx>
machine(C const&, Ctx) -> machine<C const>;
template <class C>
machine(C const&) -> machine<C const>;
template <class C, class Ctx, class O>
machine(C const&, Ctx, O) -> machine<C const, default_policy, O>;

}  // namespace bsc
