#pragma once
// bsc::table::machine: the table-driven back end. A generic engine (seed 000, section 3.3.2)
// interprets the two tables of bsc/table/tables.hpp: it knows states and transitions only by
// their numbers, and reaches the chart's guards and actions through the tables' function
// pointers. Its public interface and its behaviour are those of bsc::machine, so a program
// changes back end by changing one type.
//
// The paper's engine and this one:
//
//   StartStEng(st, qtStates, tm, qtTrans)   the constructor: start()
//   stEng(event)                            dispatch(e): process(event, e), one microstep per
//                                           event taken from the environment or the queue
//   deActivPath(from, to, inclusive)        deactivate_path(domain)
//   activPath(from, to, hist)               activate_path(domain, target)
//   StopStEng()                             the destructor (the engine owns no resource)
//
// and the five steps of its Figure 9 are those of microstep(). step(now) adds the BSC execution
// cycle of seed 002 (timers, latched inputs, one condition-driven transition per component,
// committed outputs) with the same tables.

#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include <bsc/checks/errors.hpp>
#include <bsc/configuration.hpp>
#include <bsc/detail/context_data.hpp>
#include <bsc/observer.hpp>
#include <bsc/outcome.hpp>
#include <bsc/table/tables.hpp>

namespace bsc::table {

/// The observer's hooks as data: one function pointer per state for on_entry and on_exit and
/// one per transition for on_transition, each null where the observer lacks the hook. They
/// turn the engine's state numbers back into the bsc::state_tag<S> the hooks expect.
template <class Chart, class Policy, class Observer>
struct observer_hooks {
    using rules = tables<Chart, Policy>;
    using analysis = typename rules::analysis;
    using state_hook = void (*)(Observer& observer);
    using transition_hook = void (*)(Observer& observer, void const* event);

private:
    template <std::size_t S>
    using tag = state_tag<typename analysis::template tag_at<static_cast<int>(S)>>;

    template <std::size_t S>
    static void entered(Observer& o) {
        o.on_entry(tag<S>{});
    }
    template <std::size_t S>
    static void exited(Observer& o) {
        o.on_exit(tag<S>{});
    }

    template <int Row>
    using row_type = typename analysis::template row_at<Row>;
    template <int Row>
    using source_tag = state_tag<typename row_type<Row>::source>;
    template <int Row>
    using target_tag =
        std::conditional_t<std::is_same_v<typename row_type<Row>::target, bsc::detail::no_target>,
                           state_tag<internal>, state_tag<typename row_type<Row>::target>>;
    template <int Row>
    using event_type = detail_tables::event_type_of<row_type<Row>>;

    template <int Row>
    static void transition(Observer& o, void const* event) {
        o.on_transition(source_tag<Row>{}, target_tag<Row>{}, *static_cast<event_type<Row> const*>(event));
    }

    template <std::size_t S>
    static constexpr state_hook entry_hook() {
        if constexpr (S > 0 && bsc::detail::observes_entry<Observer, tag<S>>)
            return &entered<S>;
        else
            return nullptr;
    }
    template <std::size_t S>
    static constexpr state_hook exit_hook() {
        if constexpr (S > 0 && bsc::detail::observes_exit<Observer, tag<S>>)
            return &exited<S>;
        else
            return nullptr;
    }

    template <std::size_t K>
    static constexpr transition_hook transition_hook_of() {
        constexpr int r = rules::transition_chart_row[K];
        if constexpr (bsc::detail::observes_transition<Observer, source_tag<r>, target_tag<r>, event_type<r>>)
            return &transition<r>;
        else
            return nullptr;
    }

public:
    static constexpr std::array<state_hook, rules::state_count> on_entry =
        []<std::size_t... S>(std::index_sequence<S...>) {
            return std::array<state_hook, rules::state_count>{entry_hook<S>()...};
        }(std::make_index_sequence<rules::state_count>{});
    static constexpr std::array<state_hook, rules::state_count> on_exit =
        []<std::size_t... S>(std::index_sequence<S...>) {
            return std::array<state_hook, rules::state_count>{exit_hook<S>()...};
        }(std::make_index_sequence<rules::state_count>{});
    static constexpr std::array<transition_hook, rules::transition_rows> on_transition =
        []<std::size_t... K>(std::index_sequence<K...>) {
            return std::array<transition_hook, rules::transition_rows>{transition_hook_of<K>()...};
        }(std::make_index_sequence<rules::transition_rows>{});
};

/// The observer hooks of an observer without hooks: no table at all.
template <class Chart, class Policy>
struct observer_hooks<Chart, Policy, no_observer> {};

/// A running instance of a chart, interpreted from its tables: its context, its active
/// configuration and its internal event queue. Same interface and same behaviour as
/// bsc::machine; no heap, no virtual calls, no RTTI, no exceptions. Unlike bsc::machine it
/// cannot run in constant expressions (its function pointers take the event as `void const*`).
///
/// Requirements: `Chart` comes from bsc::make_chart; `Policy` has the members of
/// bsc::default_policy; `Observer` implements any subset of the hooks in observer.hpp.
template <class Chart, class Policy = default_policy, class Observer = no_observer>
class machine {
    using rules = tables<Chart, Policy>;
    using analysis = typename rules::analysis;
    using hooks = observer_hooks<Chart, Policy, Observer>;
    static constexpr bool observed = !std::is_same_v<Observer, no_observer>;
    static constexpr std::size_t N = rules::state_count;
    static constexpr auto const& states = rules::states;
    static constexpr auto const& transitions = rules::transitions;

public:
    using chart_type = Chart;
    using context_type = typename Chart::context_type;
    using configuration_type = configuration<rules::slots>;
    using queue_type = typename rules::raise_type;
    using event_types = typename analysis::events;
    /// The operation rules this machine interprets.
    using tables_type = rules;

    /// Enters the initial configuration (entry actions run) and settles eventless transitions.
    explicit machine(Chart const& chart, context_type context = {}, Observer observer = {})
        : chart_(chart), context_(std::move(context)), observer_(std::move(observer)) {
        start();
    }

    /// Processes e to completion: the transitions it enables, then eventless transitions and
    /// raised events until none remain. Fails to compile if no transition handles E.
    template <class E>
    outcome dispatch(E const& e) {
        constexpr int trigger = analysis::template trigger_of<E>;
        if constexpr (trigger < 0) {
            static_assert(error::unhandled_event<E>::value);
            return outcome::ignored;
        } else {
            return process(static_cast<event_id>(trigger), &e);
        }
    }

    /// As dispatch(e), but an event type that no transition handles is accepted and ignored.
    template <class E>
    outcome dispatch(E const& e, allow_unhandled_t) {
        constexpr int trigger = analysis::template trigger_of<E>;
        if constexpr (trigger < 0)
            return last_ = outcome::ignored;
        else
            return process(static_cast<event_id>(trigger), &e);
    }

    /// One BSC execution cycle at time `now` (seed 002), as bsc::machine::step: timers are
    /// updated and inputs latched; each component (the root and every region of an AND state),
    /// in document order, fires at most one eventless or timeout transition, its actions' writes
    /// visible at once to the components after it; raised events are processed; outputs are
    /// committed. Components entered during the cycle first run in the next one. An earlier
    /// `now` than the last cycle's is reported and ignored.
    step_report step(duration now) {
        step_report report;
        if (halted()) {
            report.status = last_ = outcome::halted;
            return report;
        }
        if (now < clock_)
            report.clock_went_backwards = true;
        else
            clock_ = now;
        bsc::detail::update_timers(context_, clock_);
        latch();
        if constexpr (rules::has_conditions)
            report.transitions = run_components();
        report.status = last_ = drain_queue(report.transitions > 0);
        commit();
        return report;
    }

    /// The time of the last cycle (the machine's clock).
    duration now() const { return clock_; }

    /// True if state S is active.
    template <class S>
    bool is() const {
        constexpr int s = analysis::template index_of_state<S>;
        if constexpr (s < 0) {
            static_assert(error::state_not_in_chart<S>::value);
            return false;
        } else {
            return active(static_cast<state_id>(s));
        }
    }

    /// True once a final child of the root is active: the machine processes nothing more.
    bool halted() const {
        if constexpr (rules::can_halt)
            return states[active_child(rules::root)].status.kind == state_kind::final_state;
        else
            return false;
    }

    /// The names of the active states, outermost first, in document order.
    auto active_states() const {
        state_names<N> names;
        for (state_id s = rules::root; s < N;) {
            if (!selected(s)) {
                s = states[s].end;
                continue;
            }
            names.push_back(rules::names[s]);
            ++s;
        }
        return names;
    }

    /// The outcome of the last dispatch (or of construction).
    outcome last_outcome() const { return last_; }

    context_type& context() { return context_; }
    context_type const& context() const { return context_; }
    configuration_type const& active_configuration() const { return config_; }
    Observer& observer() { return observer_; }
    Observer const& observer() const { return observer_; }
    queue_type const& queue() const { return queue_; }

private:
    // ---- the configuration ----------------------------------------------------------------
    std::uint8_t byte(std::int16_t slot) const {
        if constexpr (rules::slots > 0)
            return config_.active[static_cast<std::size_t>(slot)];
        else
            return 0;
    }
    void set_byte(std::int16_t slot, std::uint8_t value) {
        if constexpr (rules::slots > 0)
            config_.active[static_cast<std::size_t>(slot)] = value;
    }
    // The child of an OR state (or of the top) that its byte selects.
    state_id active_child(state_id s) const {
        state_id c = states[s].descendant;
        if (states[s].slot >= 0)
            for (std::uint8_t k = byte(states[s].slot); k > 0; --k) c = states[c].sibling;
        return c;
    }
    // s is active if its parent is: an OR parent selects it, an AND parent or the top always does.
    bool selected(state_id s) const {
        auto const slot = states[states[s].ancestor].slot;
        return slot < 0 || byte(slot) == states[s].ordinal;
    }
    bool active(state_id s) const {
        for (; s > rules::root; s = states[s].ancestor)
            if (!selected(s))
                return false;
        return true;
    }
    static bool is_leaf(state_id s) { return states[s].descendant == none; }

    // ---- entry and exit -------------------------------------------------------------------
    void run_entry(state_id s) {
        if (auto const f = states[s].entry)
            f(chart_, context_, queue_);
        // A state's timeouts count from its entry, at the time of the last cycle.
        if constexpr (rules::timeout_slots > 0)
            if (states[s].timeout_slot >= 0)
                armed_[static_cast<std::size_t>(states[s].timeout_slot)] = clock_;
        if constexpr (observed)
            if (auto const h = hooks::on_entry[s])
                h(observer_);
    }
    void run_exit(state_id s) {
        if (auto const f = states[s].exit)
            f(chart_, context_, queue_);
        if constexpr (observed)
            if (auto const h = hooks::on_exit[s])
                h(observer_);
    }

    // Enters s and its default completion: the initial child of an OR state, or the child its
    // history remembers; every child of an AND state.
    void enter_default(state_id s) {
        run_entry(s);
        enter_content(s);
    }
    void enter_content(state_id s) {
        auto const& row = states[s];
        if (row.status.kind == state_kind::or_state) {
            switch (row.status.history) {
                case history_kind::none:
                    set_byte(row.slot, states[row.initial].ordinal);
                    enter_default(row.initial);
                    break;
                case history_kind::shallow: enter_default(active_child(s)); break;
                case history_kind::deep: enter_restore(active_child(s)); break;
            }
        } else if (row.status.kind == state_kind::and_state) {
            for (state_id c = row.descendant; c != none; c = states[c].sibling) enter_default(c);
        }
    }
    // Deep history: re-enters s and the whole sub-configuration the bytes remember.
    void enter_restore(state_id s) {
        run_entry(s);
        auto const& row = states[s];
        if (row.status.kind == state_kind::or_state)
            enter_restore(active_child(s));
        else if (row.status.kind == state_kind::and_state)
            for (state_id c = row.descendant; c != none; c = states[c].sibling) enter_restore(c);
    }

    // The paper's activPath: enters, below the active state `domain`, the states on the path
    // down to `target` (and, at every AND state on the way, its other children by default),
    // then the target's default completion, which follows its history. Entries run outermost
    // first, in document order.
    void activate_path(state_id domain, state_id target) {
        state_id c = target;
        while (states[c].ancestor != domain) c = states[c].ancestor;
        if (states[domain].status.kind == state_kind::and_state) {
            for (state_id k = states[domain].descendant; k != none; k = states[k].sibling) {
                if (k == c)
                    enter_path_node(c, target);
                else
                    enter_default(k);
            }
        } else {
            if (states[domain].slot >= 0)
                set_byte(states[domain].slot, states[c].ordinal);
            enter_path_node(c, target);
        }
    }
    void enter_path_node(state_id s, state_id target) {
        run_entry(s);
        if (s == target)
            enter_content(s);
        else
            activate_path(s, target);
    }

    // The paper's deActivPath: exits every active descendant of `domain`, innermost first and
    // in reverse document order (the reverse of their document order), running exit actions.
    // The bytes are left as they are: they are the history of the states left.
    void deactivate_path(state_id domain) {
        std::array<state_id, N> path{};
        std::size_t n = 0;
        for (state_id s = domain + 1; s < states[domain].end;) {
            if (!selected(s)) {
                s = states[s].end;
                continue;
            }
            path[n++] = s;
            ++s;
        }
        while (n > 0) run_exit(path[--n]);
    }

    // ---- transitions ----------------------------------------------------------------------
    struct selection {
        std::array<std::int16_t, rules::max_active_leaves> rows{};
        std::size_t size = 0;
        void add(std::int16_t t) {
            for (std::size_t i = 0; i < size; ++i)
                if (rows[i] == t)
                    return;
            rows[size++] = t;
        }
    };

    bool guard_holds(std::int16_t t, void const* e) const {
        auto const g = transitions[static_cast<std::size_t>(t)].guard;
        return g == nullptr || g(chart_, context_, e);
    }

    // Step 2 for one active basic state: its candidates are the transitions on the event from
    // the state itself, then from its parent, and so on up to the root (deepest first); among
    // those of one origin, declaration order. The first whose guard holds is selected.
    bool select_from(state_id leaf, event_id event, void const* e, selection& sel) const {
        for (state_id a = leaf; a != none; a = states[a].ancestor)
            for (std::int16_t t = rules::first_out[a]; t >= 0; t = rules::next_out[static_cast<std::size_t>(t)])
                if (transitions[static_cast<std::size_t>(t)].event == event && guard_holds(t, e)) {
                    sel.add(t);
                    return true;
                }
        return false;
    }

    // Two transitions conflict when their exit sets meet: when their domains nest.
    static bool conflict(std::int16_t t1, std::int16_t t2) {
        auto const& a = transitions[static_cast<std::size_t>(t1)];
        auto const& b = transitions[static_cast<std::size_t>(t2)];
        if (a.to == none || b.to == none)
            return false;
        return rules::contains(a.domain, b.domain) || rules::contains(b.domain, a.domain);
    }
    static bool proper_ancestor(state_id a, state_id d) { return a != d && rules::contains(a, d); }

    // SCXML's conflict resolution: walking the selection in order, a transition that conflicts
    // with one kept earlier replaces it if its origin lies below the earlier one's, and is
    // dropped otherwise.
    static selection resolve(selection const& sel) {
        selection kept;
        for (std::size_t i = 0; i < sel.size; ++i) {
            std::int16_t const t1 = sel.rows[i];
            bool preempted = false;
            selection survivors;
            for (std::size_t j = 0; j < kept.size; ++j) {
                std::int16_t const t2 = kept.rows[j];
                if (!conflict(t1, t2))
                    survivors.add(t2);
                else if (proper_ancestor(transitions[static_cast<std::size_t>(t2)].from,
                                         transitions[static_cast<std::size_t>(t1)].from))
                    continue;  // t1 preempts t2
                else {
                    preempted = true;
                    break;
                }
            }
            if (!preempted) {
                survivors.add(t1);
                kept = survivors;
            }
        }
        return kept;
    }

    void run_action(std::int16_t t, void const* e) {
        auto const& row = transitions[static_cast<std::size_t>(t)];
        if constexpr (observed)
            if (auto const h = hooks::on_transition[static_cast<std::size_t>(t)])
                h(observer_, e);
        if constexpr (bsc::detail::observes_rows<Observer>)
            observer_.on_row(rules::transition_chart_row[static_cast<std::size_t>(t)]);
        if (row.action)
            row.action(chart_, context_, e, queue_);
    }

    // One microstep for an event, the five steps of the paper's Figure 9; true if a
    // transition was selected.
    bool microstep(event_id event, void const* e) {
        // 1. Sense the event: an event no transition is triggered by changes nothing.
        if (!rules::handles(event))
            return false;

        // 2. Determine the transitions: every active basic state, in document order, selects
        //    its first enabled candidate (the event is broadcast to all parallel regions).
        selection sel;
        bool any = false;
        for (state_id s = rules::root; s < N;) {
            if (!selected(s)) {
                s = states[s].end;
                continue;
            }
            if (is_leaf(s) && select_from(s, event, e, sel))
                any = true;
            ++s;
        }
        if (sel.size == 0)
            return any;
        selection const fired = resolve(sel);

        // 3. Deactivate the states the transitions leave, running their exit actions.
        for (std::size_t i = fired.size; i-- > 0;) {
            auto const& row = transitions[static_cast<std::size_t>(fired.rows[i])];
            if (row.to != none)
                deactivate_path(row.domain);
        }
        // 4. Perform the transition actions, in selection order.
        for (std::size_t i = 0; i < fired.size; ++i) run_action(fired.rows[i], e);
        // 5. Activate the states they enter, running entry actions, defaults and history.
        for (std::size_t i = 0; i < fired.size; ++i) {
            auto const& row = transitions[static_cast<std::size_t>(fired.rows[i])];
            if (row.to != none)
                activate_path(row.domain, row.to);
        }
        return any;
    }

    // ---- running --------------------------------------------------------------------------
    // The paper's StartStEng: the initial configuration, entered from the root down.
    void start() {
        if constexpr (rules::slots > 0)
            config_.active = rules::initial_bytes;
        latch();
        enter_default(rules::root);
        last_ = finish(false);
        commit();
    }

    // The paper's stEng: one event from the environment, processed to completion.
    outcome process(event_id event, void const* e) {
        if (halted())
            return last_ = outcome::halted;
        latch();
        last_ = finish(microstep(event, e));
        commit();
        return last_;
    }

    // Settles the machine after a microstep: eventless transitions until none is enabled,
    // then the raised events one by one, each followed by its eventless transitions. Under a
    // scan policy eventless transitions are left to step(), and only raised events are processed.
    outcome finish(bool consumed) {
        if constexpr (!Policy::settle_eventless)
            return drain_queue(consumed);
        std::size_t internal_events = 0;
        for (;;) {
            if constexpr (rules::has_eventless) {
                // Up to max_eventless_steps transitions settle; one more means the chart cycles.
                for (std::size_t steps = 0; !halted() && microstep(eventless_id, &no_event);)
                    if (++steps > Policy::max_eventless_steps)
                        return abandon();
            }
            if (queue_.empty() || halted())
                break;
            if (++internal_events > Policy::max_internal_events)
                return abandon();
            queue_.pop([&](auto const& ev) {
                microstep(static_cast<event_id>(analysis::template trigger_of<std::decay_t<decltype(ev)>>), &ev);
            });
        }
        if (queue_.overflowed()) {
            queue_.clear_overflow();
            return outcome::queue_overflow;
        }
        return consumed ? outcome::consumed : outcome::ignored;
    }

    // The raised events, each one microstep and no eventless settling: in a cycle, so that no
    // component fires twice.
    outcome drain_queue(bool consumed) {
        for (std::size_t n = 0; !queue_.empty() && !halted();) {
            if (++n > Policy::max_internal_events)
                return abandon();
            queue_.pop([&](auto const& ev) {
                microstep(static_cast<event_id>(analysis::template trigger_of<std::decay_t<decltype(ev)>>), &ev);
            });
        }
        if (queue_.overflowed()) {
            queue_.clear_overflow();
            return outcome::queue_overflow;
        }
        return consumed ? outcome::consumed : outcome::ignored;
    }

    outcome abandon() {
        queue_.clear();
        queue_.clear_overflow();
        return outcome::livelock;
    }

    // ---- the BSC cycle ----------------------------------------------------------------------
    // The components' turns: a component takes its turn if it was active when the cycle began
    // and still is (an earlier component may have left it); one entered during the cycle waits
    // for the next. Returns the number of transitions fired.
    int run_components() {
        constexpr auto const& components = rules::components;
        std::array<bool, components.size()> active_at_start{};
        for (std::size_t i = 0; i < components.size(); ++i) active_at_start[i] = active(components[i]);
        int fired = 0;
        for (std::size_t i = 0; i < components.size(); ++i)
            if (active_at_start[i] && active(components[i]) && component_step(components[i]))
                ++fired;
        return fired;
    }

    // One component's turn: from its active frontier (the active basic state below it, or an
    // AND state whose regions are components of their own) up to the component itself, deepest
    // origin first and table order among one origin's, the first condition-driven transition
    // whose condition holds fires.
    bool component_step(state_id component) {
        state_id frontier = component;
        while (states[frontier].status.kind == state_kind::or_state) frontier = active_child(frontier);
        for (state_id a = frontier;; a = states[a].ancestor) {
            for (std::int16_t t = rules::first_out[a]; t >= 0; t = rules::next_out[static_cast<std::size_t>(t)])
                if (is_condition(transitions[static_cast<std::size_t>(t)].event) && condition_holds(t)) {
                    fire_condition(t);
                    return true;
                }
            if (a == component)
                return false;
        }
    }

    // A timeout's condition: its origin has been active for its delay (the origin is active: it
    // is on the component's active path). Then the guard, which receives bsc::eventless.
    bool condition_holds(std::int16_t t) const {
        auto const& row = transitions[static_cast<std::size_t>(t)];
        if constexpr (rules::timeout_slots > 0)
            if (row.event == timeout_id &&
                clock_ - armed_[static_cast<std::size_t>(states[row.from].timeout_slot)] < row.delay(chart_))
                return false;
        return guard_holds(t, &no_event);
    }

    // Steps 3 to 5 of a microstep for one transition: a component's transition fires alone.
    void fire_condition(std::int16_t t) {
        auto const& row = transitions[static_cast<std::size_t>(t)];
        if (row.to != none)
            deactivate_path(row.domain);
        run_action(t, &no_event);
        if (row.to != none)
            activate_path(row.domain, row.to);
    }

    // Input and output channels of the context, latched and committed around each dispatch
    // as bsc::machine does.
    void latch() { bsc::detail::latch_inputs(context_); }
    void commit() { bsc::detail::commit_outputs(context_); }

    // The event that eventless and timeout transitions receive.
    static constexpr bsc::eventless no_event{};

    [[no_unique_address]] Chart chart_;
    context_type context_;
    configuration_type config_{};
    queue_type queue_{};
    duration clock_{};
    std::array<duration, rules::timeout_slots> armed_{};  // entry times of the states with timeouts
    outcome last_ = outcome::ignored;
    [[no_unique_address]] Observer observer_;
};

template <class C, class Ctx>
machine(C const&, Ctx) -> machine<C>;
template <class C>
machine(C const&) -> machine<C>;
template <class C, class Ctx, class O>
machine(C const&, Ctx, O) -> machine<C, default_policy, O>;

}  // namespace bsc::table
