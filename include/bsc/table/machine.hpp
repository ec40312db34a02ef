#pragma once
// bsc::table::machine: the table-driven back end. A generic engine (the machine-tool paper
// [MCS] in docs/references.md, section 3.3.2) interprets the two tables of
// bsc/detail/table/tables.hpp: it knows states and transitions only by their numbers, and reaches the
// chart's guards and actions through the tables' function pointers. Its public interface and
// run to completion are the shared driver's (detail/runtime/driver.hpp), so a program changes back end
// by changing one type.
//
// The paper's engine and this one:
//
//   StartStEng(st, qtStates, tm, qtTrans)   the constructor: enter_initial()
//   stEng(event)                            dispatch(e): one microstep per event taken from
//                                           the environment or the queue
//   deActivPath(from, to, inclusive)        deactivate_path(domain)
//   activPath(from, to, hist)               activate_path(domain, target)
//   StopStEng()                             the destructor (the engine owns no resource)
//
// and the five steps of its Figure 9 are those of select_and_fire(). step(now) adds the BSC execution
// cycle of the Basic Statechart paper [BSC] (one condition-driven transition per component)
// with the same tables.

#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include <bsc/detail/config.hpp>
#include <bsc/observer.hpp>
#include <bsc/outcome.hpp>
#include <bsc/policies.hpp>
#include <bsc/statechart.hpp>
#include <bsc/detail/runtime/driver.hpp>
#include <bsc/detail/runtime/notify.hpp>
#include <bsc/detail/runtime/rejected.hpp>
#include <bsc/detail/runtime/selection.hpp>
#include <bsc/detail/table/tables.hpp>

namespace bsc::table {

/// The observer's hooks as data: one function pointer per state for on_entry and on_exit and
/// one per transition for on_transition and on_row, each null where the observer lacks the
/// hook. They turn the engine's numbers back into the calls of bsc::detail::notify.
template <class Chart, class Policy, class Observer>
struct observer_hooks {
    using state_hook = void (*)(Observer& observer);
    using transition_hook = void (*)(Observer& observer, Chart const& chart, void const* event);

private:
    using model = bsc::detail::chart_model<std::remove_cv_t<Chart>>;
    using notify = bsc::detail::notify<model, Observer>;
    using tables_type = tables<Chart, Policy>;

    template <int Row>
    using event_type = bsc::detail::row_event_t<typename model::template row_at<Row>>;

    template <int Row>
    static void transition(Observer& o, Chart const& chart, void const* event) {
        notify::template transition<Row>(o, bsc::detail::row_at<static_cast<std::size_t>(Row)>(chart.rows),
                                         *static_cast<event_type<Row> const*>(event));
    }

    template <std::size_t S>
    static constexpr state_hook entry_hook() {
        if constexpr (notify::template observes_entry_of<static_cast<int>(S)>)
            return &notify::template entered<static_cast<int>(S)>;
        else
            return nullptr;
    }
    template <std::size_t S>
    static constexpr state_hook exit_hook() {
        if constexpr (notify::template observes_exit_of<static_cast<int>(S)>)
            return &notify::template exited<static_cast<int>(S)>;
        else
            return nullptr;
    }
    template <std::size_t K>
    static constexpr transition_hook transition_hook_of() {
        constexpr int r = tables_type::transition_chart_row[K];
        if constexpr (notify::template observes_row<r, event_type<r>>)
            return &transition<r>;
        else
            return nullptr;
    }

    template <class Hook, std::size_t N, class Make>
    static constexpr std::array<Hook, N> make(Make make_one) {
        // clang-format off
        return [&]<std::size_t... I>(std::index_sequence<I...>) {
            return std::array<Hook, N>{make_one(std::integral_constant<std::size_t, I>{})...};
        }(std::make_index_sequence<N>{});
        // clang-format on
    }

public:
    static constexpr auto on_entry = make<state_hook, tables_type::state_count>(
        [](auto s) { return entry_hook<decltype(s)::value>(); });
    static constexpr auto on_exit = make<state_hook, tables_type::state_count>(
        [](auto s) { return exit_hook<decltype(s)::value>(); });
    static constexpr auto on_transition = make<transition_hook, tables_type::transition_rows>(
        [](auto t) { return transition_hook_of<decltype(t)::value>(); });
};

/// The observer hooks of an observer without hooks: no table at all.
template <class Chart, class Policy>
struct observer_hooks<Chart, Policy, no_observer> {};

/// A running instance of a chart, interpreted from its tables: its context, its active
/// configuration and its internal event queue. Same interface and same behaviour as
/// bsc::machine; no heap, no virtual calls, no RTTI, no exceptions. Unlike bsc::machine it
/// cannot run in constant expressions (its function pointers take the event as `void const*`).
///
/// Requirements: `Chart` is a bsc::statechart (the type of a chart from bsc::make_chart, or
/// bsc::chart_ref); `Policy` is a bsc::machine_policy (bsc::default_policy, or a class derived from
/// it); `Observer` implements any subset of the hooks in observer.hpp.
template <statechart Chart, machine_policy Policy = default_policy, class Observer = no_observer>
class machine : public bsc::detail::driver<machine<Chart, Policy, Observer>, Chart, Policy, Observer,
                                           typename tables<Chart, Policy>::raise_type> {
    using base = bsc::detail::driver<machine, Chart, Policy, Observer, typename tables<Chart, Policy>::raise_type>;
    friend base;
    // The driver's layers that call the hooks (detail/runtime/backend.hpp), and backend_hooks,
    // through which the driver checks them.
    friend bsc::detail::backend_hooks;
    template <class, class, class, class, class>
    friend class bsc::detail::settling;
    template <class, class, class, class, class>
    friend class bsc::detail::deferral;
    template <class, class, class, class, class>
    friend class bsc::detail::done_raising;
    static constexpr bool marks_running_lazily = false;  // a dispatch is marked running throughout
    using hooks = observer_hooks<Chart, Policy, Observer>;
    using base::observed;

public:
    using typename base::context_type;
    /// The operation rules this machine interprets.
    using tables_type = tables<Chart, Policy>;

    /// Enters the initial configuration (entry actions run) and settles eventless transitions.
    /// (The chart parameter's type_identity leaves deduction to the guides below.)
    explicit machine(std::type_identity_t<Chart> const& chart, context_type context = {}, Observer observer = {})
        : base(chart, std::move(context), std::move(observer)) {
        this->start();
    }

private:
    static constexpr std::size_t N = tables_type::state_count;
    static constexpr auto const& states = tables_type::states;
    static constexpr auto const& transitions = tables_type::transitions;
    using transition_row_type = typename tables_type::transition_row_type;

    // ---- the configuration ----------------------------------------------------------------
    int byte(std::int16_t slot) const {
        if constexpr (tables_type::slots > 0)
            return this->config_.active[static_cast<std::size_t>(slot)];
        else
            return 0;
    }
    void set_byte(std::int16_t slot, int value) {
        if constexpr (tables_type::slots > 0)
            this->config_.active[static_cast<std::size_t>(slot)] =
                static_cast<typename base::configuration_type::ordinal_type>(value);
    }
    // The child of a composite (or of the top) that its byte selects.
    state_id active_child(state_id s) const {
        state_id c = states[s].first_child;
        if (states[s].slot >= 0)
            for (int k = byte(states[s].slot); k > 0; --k) c = states[c].next_sibling;
        return c;
    }
    // s is active if its parent is: a composite parent selects it, a parallel parent or the
    // top always does.
    bool selected(state_id s) const {
        auto const slot = states[states[s].parent].slot;
        return slot < 0 || byte(slot) == states[s].ordinal;
    }
    bool active(state_id s) const {
        for (; s > tables_type::root; s = states[s].parent)
            if (!selected(s)) return false;
        return true;
    }
    template <int S>
    bool is_active() const {
        return active(static_cast<state_id>(S));
    }
    static bool is_leaf(state_id s) { return states[s].first_child == no_state; }

    // ---- entry and exit -------------------------------------------------------------------
    void run_entry(state_id s) {
        if (auto const f = states[s].entry) f(this->chart(), this->context_.value, this->queue_, this->sink());
        if constexpr (base::completion::raises)
            if (states[s].status.kind == state_kind::final_state) this->entered_final(s);
        // A state's timeouts count from its entry, at the time of the last cycle.
        if constexpr (tables_type::timeout_slots > 0)
            this->arm_timeouts(states[s].timeout_slot, states[s].timeout_slots);
        if constexpr (observed)
            if (auto const h = hooks::on_entry[s]) h(this->observer_.value);
    }
    void run_exit(state_id s) {
        if (auto const f = states[s].exit) f(this->chart(), this->context_.value, this->queue_, this->sink());
        if constexpr (observed)
            if (auto const h = hooks::on_exit[s]) h(this->observer_.value);
    }

    // The paper's StartStEng: the initial configuration, entered from the root down.
    void enter_initial() { enter_default(tables_type::root); }
    // When the machine halts: every active state's exit actions, innermost first.
    void exit_all() { deactivate_path(no_state); }

    // Enters s and its default completion: the initial child of a composite, or the child its
    // history remembers; every child of a parallel state.
    void enter_default(state_id s) {
        run_entry(s);
        enter_content(s);
    }
    void enter_content(state_id s) {
        auto const& row = states[s];
        if (row.status.kind == state_kind::composite) {
            switch (row.status.history) {
                case history_kind::none:
                    // The initial transition: its actions, then its target, a child or deeper.
                    if (auto const f = row.initial_action)
                        f(this->chart(), this->context_.value, this->queue_, this->sink());
                    if (states[row.initial].status.kind == state_kind::history) {
                        enter_history(row.initial);
                    } else if (row.more_initial[0] != no_state) {  // initial<A, B>: one state in each region
                        activate_all(s, target_set{row.initial_target, row.more_initial[0], row.more_initial[1],
                                                   row.more_initial[2]});
                    } else if (row.initial_target != row.initial) {
                        activate_path(s, row.initial_target);
                    } else {
                        set_byte(row.slot, states[row.initial].ordinal);
                        enter_default(row.initial);
                    }
                    break;
                case history_kind::shallow: enter_default(active_child(s)); break;
                case history_kind::deep: enter_restore(active_child(s)); break;
            }
        } else if (row.status.kind == state_kind::parallel) {
            this->regions_entering(s);
            for (state_id c = row.first_child; c != no_state; c = states[c].next_sibling) enter_default(c);
            this->regions_entered(s);
        }
    }
    // Enters history state h of composite p: p's remembered child (shallow) or remembered
    // sub-configuration (deep), or, if p has never been active (its byte selects a history
    // state), h's default transition.
    void enter_history(state_id h) {
        state_id const p = states[h].parent;
        state_id const remembered = active_child(p);
        if (states[remembered].status.kind == state_kind::history) {
            if (auto const f = states[h].initial_action)
                f(this->chart(), this->context_.value, this->queue_, this->sink());
            if (states[h].initial_target != states[h].initial) {
                activate_path(p, states[h].initial_target);
            } else {
                set_byte(states[p].slot, states[states[h].initial].ordinal);
                enter_default(states[h].initial);
            }
        } else if (states[h].status.history == history_kind::shallow) {
            enter_default(remembered);
        } else {
            enter_restore(remembered);
        }
    }

    // Deep history: re-enters s and the whole sub-configuration the bytes remember.
    void enter_restore(state_id s) {
        run_entry(s);
        auto const& row = states[s];
        if (row.status.kind == state_kind::composite)
            enter_restore(active_child(s));
        else if (row.status.kind == state_kind::parallel) {
            this->regions_entering(s);
            for (state_id c = row.first_child; c != no_state; c = states[c].next_sibling) enter_restore(c);
            this->regions_entered(s);
        }
    }

    // The paper's activPath: enters, below the active state `domain`, the states on the path
    // down to `target` (and, at every parallel state on the way, its other children by
    // default), then the target's default completion, which follows its history. Entries run
    // outermost first, in document order.
    void activate_path(state_id domain, state_id target) {
        state_id c = target;
        while (states[c].parent != domain) c = states[c].parent;
        if (states[domain].status.kind == state_kind::parallel) {
            // (A parallel `domain` here has just been entered: no transition's domain is parallel.)
            this->regions_entering(domain);
            for (state_id k = states[domain].first_child; k != no_state; k = states[k].next_sibling) {
                if (k == c)
                    enter_path_node(c, target);
                else
                    enter_default(k);
            }
            this->regions_entered(domain);
        } else if (states[c].status.kind == state_kind::history) {
            enter_history(c);  // `domain`, its composite, has been entered: now its history
        } else {
            if (states[domain].slot >= 0) set_byte(states[domain].slot, states[c].ordinal);
            enter_path_node(c, target);
        }
    }
    // Several targets (bsc::targets, bsc::initial<A, B>): the paths down to each of them, the
    // regions of a parallel state on the way that hold none entered by default. A set holds up
    // to four states, no_state where it has fewer.
    using target_set = std::array<state_id, 4>;
    static bool holds_target(state_id s, target_set const& targets) {
        for (state_id t : targets)
            if (t != no_state && tables_type::contains(s, t)) return true;
        return false;
    }
    static bool is_target(state_id s, target_set const& targets) {
        for (state_id t : targets)
            if (t != no_state && s == t) return true;
        return false;
    }
    void activate_all(state_id domain, target_set const& targets) {
        if (states[domain].status.kind == state_kind::parallel) {
            this->regions_entering(domain);
            for (state_id k = states[domain].first_child; k != no_state; k = states[k].next_sibling) {
                if (holds_target(k, targets))
                    enter_path_all(k, targets);
                else
                    enter_default(k);
            }
            this->regions_entered(domain);
        } else {
            // The child of `domain` toward the targets it holds (they lie below one child).
            state_id c = no_state;
            for (state_id t : targets)
                if (t != no_state && c == no_state && tables_type::contains(domain, t) && t != domain) c = t;
            while (states[c].parent != domain) c = states[c].parent;
            if (states[c].status.kind == state_kind::history) {
                enter_history(c);
            } else {
                if (states[domain].slot >= 0) set_byte(states[domain].slot, states[c].ordinal);
                enter_path_all(c, targets);
            }
        }
    }
    void enter_path_all(state_id s, target_set const& targets) {
        run_entry(s);
        if (is_target(s, targets))
            enter_content(s);
        else
            activate_all(s, targets);
    }
    // Step 5 for one transition: the entries of its target, or of its targets.
    void enter_targets(transition_row_type const& row) {
        if (row.to == no_state) return;
        if (row.more_to[0] != no_state)
            activate_all(row.domain, target_set{row.to, row.more_to[0], row.more_to[1], row.more_to[2]});
        else
            activate_path(row.domain, row.to);
    }

    void enter_path_node(state_id s, state_id target) {
        run_entry(s);
        if (s == target)
            enter_content(s);
        else
            activate_path(s, target);
    }

    // The paper's deActivPath: exits every active descendant of `domain`, innermost first and
    // in reverse document order, running exit actions. The bytes are left as they are: they
    // are the history of the states left.
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
    using selection = bsc::detail::selection<tables_type::max_active_leaves>;

    // (In a chart with bsc::in<S>, every guard receives the configuration bytes as well:
    // tables.hpp, guards_read_configuration.)
    bool guard_holds(std::int16_t t, void const* e) {
        auto const g = transitions[static_cast<std::size_t>(t)].guard;
        if constexpr (transition_row_type::guards_read_configuration)
            return g == nullptr || this->test(g, this->chart(), this->context_.value, e, configuration_bytes());
        else
            return g == nullptr || this->test(g, this->chart(), this->context_.value, e);
    }
    typename base::configuration_type::ordinal_type const* configuration_bytes() const {
        if constexpr (tables_type::slots > 0)
            return this->config_.active.data();
        else
            return nullptr;  // no composite: no test reads a byte
    }

    // The event a microstep processes, as the thunks of a transition receive it. Without
    // families, every transition on it takes it as it is.
    struct plain_event {
        void const* event;
        void const* as(event_id) const { return event; }
    };
    // With families, a transition on a family of the event receives the event as that family
    // (a base class subobject, or bsc::any_event): one pointer per event of the chart.
    struct family_event {
        std::array<void const*, tables_type::event_count> seen{};
        void const* as(event_id row_event) const { return seen[static_cast<std::size_t>(row_event)]; }
    };
    template <class E>
    static family_event as_families(E const& e) {
        family_event view;
        // clang-format off
        [&]<class... Us>(bsc::detail::type_list<Us...>) {
            std::size_t u = 0;
            ((view.seen[u++] = address_as<Us>(e)), ...);
        }(typename base::event_types{});
        // clang-format on
        return view;
    }
    template <class U, class E>
    static void const* address_as(E const& e) {
        if constexpr (std::is_same_v<U, E>)
            return &e;
        else if constexpr (std::is_same_v<U, bsc::any_event>)
            return &any_event_value;
        else if constexpr (BSC_DETAIL_IS_BASE_OF(U, E))
            return static_cast<U const*>(&e);
        else
            return nullptr;  // not a family of E: no transition on U takes E
    }
    static constexpr bsc::any_event any_event_value{};

    // Step 2 for one active basic state: its candidates are the transitions on the event (or on
    // a family of it) from the state itself and from each of its ancestors up to the root, in
    // the chart's priority order (tables::order: the state first, or the root first); among
    // those of one origin, declaration order. The first whose guard holds is selected.
    template <class Event>
    bool select_from(state_id leaf, event_id event, Event const& e, selection& sel) {
        return for_each_tried(leaf, tables_type::root, [&](state_id a) {
            for (std::int16_t t = tables_type::first_out[a]; t >= 0;
                 t = tables_type::next_out[static_cast<std::size_t>(t)]) {
                auto const on = transitions[static_cast<std::size_t>(t)].event;
                if (tables_type::takes(on, event) && guard_holds(t, e.as(on))) {
                    sel.add(static_cast<std::size_t>(t));
                    return true;
                }
            }
            return false;
        });
    }

    // Calls try_state(a) for each state a from `from` up to `top` (an ancestor of it, or
    // itself) in the chart's priority order, until one returns true; returns whether one did.
    template <class F>
    static bool for_each_tried(state_id from, state_id top, F&& try_state) {
        if constexpr (tables_type::order == bsc::priority::child_first) {
            for (state_id a = from;; a = states[a].parent) {
                if (try_state(a)) return true;
                if (a == top) return false;
            }
        } else {
            std::array<state_id, tables_type::levels> path{};
            std::size_t n = 0;
            for (state_id a = from;; a = states[a].parent) {
                path[n++] = a;
                if (a == top) break;
            }
            while (n > 0)
                if (try_state(path[--n])) return true;
            return false;
        }
    }

    void run_action(std::int16_t t, void const* e) {
        if constexpr (observed)
            if (auto const h = hooks::on_transition[static_cast<std::size_t>(t)])
                h(this->observer_.value, this->chart(), e);
        if constexpr (base::defers) {
            if (transitions[static_cast<std::size_t>(t)].defers) {  // keeps the event (driver's fire_or_defer)
                this->deferral_selected();
                return;
            }
            this->transition_fired(transitions[static_cast<std::size_t>(t)].to != no_state);
        }
        if (auto const action = transitions[static_cast<std::size_t>(t)].action)
            this->run(action, this->chart(), this->context_.value, e, this->queue_);
    }

    // fire() for a dispatched event: the same as for any other here (the compiled back end puts
    // it in line in the dispatch).
    template <int Trigger, class E>
    bool fire_dispatched(E const& e) {
        return fire<Trigger>(e);
    }
    // Selects and fires the transitions Trigger enables, without settling; true if a
    // transition was selected.
    template <int Trigger, class E>
    bool fire(E const& e) {
        if constexpr (Trigger >= 0 && base::model::has_families)
            return select_and_fire(static_cast<event_id>(Trigger), as_families(e));
        else if constexpr (Trigger >= 0)  // E, or an event the chart does not name, as the trigger's type
            return select_and_fire(
                static_cast<event_id>(Trigger),
                plain_event{
                    address_as<bsc::detail::at<static_cast<std::size_t>(Trigger), typename base::event_types>>(e)});
        else
            return select_and_fire(static_cast<event_id>(Trigger), plain_event{&e});
    }

    // The five steps of the paper's Figure 9 for an event; true if a transition was selected.
    template <class Event>
    bool select_and_fire(event_id event, Event const& e) {
        // 1. Sense the event: an event no transition is triggered by changes nothing.
        if (!tables_type::handles(event)) return false;

        // 2. Determine the transitions: every active basic state, in document order, selects
        //    its first enabled candidate (the event is broadcast to all parallel regions), and
        //    SCXML's conflict resolution keeps some of them.
        selection sel;
        bool any = false;
        for (state_id s = tables_type::root; s < N;) {
            if (!selected(s)) {
                s = states[s].end;
                continue;
            }
            if (is_leaf(s) && select_from(s, event, e, sel)) any = true;
            ++s;
        }
        if (sel.size == 0) return any;
        constexpr auto const& chart_row = tables_type::transition_chart_row;
        using shared_layout = typename base::layout;
        selection const fired = bsc::detail::resolve_conflicts(
            sel,
            [](std::size_t later, std::size_t earlier) {
                return shared_layout::conflict(chart_row[later], chart_row[earlier]);
            },
            [](std::size_t later, std::size_t earlier) {
                return shared_layout::preempts(chart_row[later], chart_row[earlier]);
            });

        // 3. Deactivate the states the transitions leave, running their exit actions.
        for (std::size_t i = fired.size; i-- > 0;) {
            auto const& row = transitions[fired.rows[i]];
            if (row.to != no_state) deactivate_path(row.domain);
        }
        // 4. Perform the transition actions, in selection order.
        for (std::size_t i = 0; i < fired.size; ++i)
            run_action(static_cast<std::int16_t>(fired.rows[i]), e.as(transitions[fired.rows[i]].event));
        // 5. Activate the states they enter, running entry actions, defaults and history.
        for (std::size_t i = 0; i < fired.size; ++i) enter_targets(transitions[fired.rows[i]]);
        return any;
    }

    // ---- the BSC cycle ----------------------------------------------------------------------
    template <int Component>
    bool component_step() {
        return run_component(static_cast<state_id>(Component));
    }

    // One component's turn: from its active frontier (the active basic state below it, or a
    // parallel state whose regions are components of their own) up to the component itself,
    // in the chart's priority order and table order among one origin's, the first
    // condition-driven transition whose condition holds fires.
    bool run_component(state_id component) {
        state_id frontier = component;
        while (states[frontier].status.kind == state_kind::composite) frontier = active_child(frontier);
        return for_each_tried(frontier, component, [&](state_id a) {
            for (std::int16_t t = tables_type::first_out[a]; t >= 0;
                 t = tables_type::next_out[static_cast<std::size_t>(t)])
                if (is_condition(transitions[static_cast<std::size_t>(t)].event) && condition_holds(t)) {
                    fire_condition(first_due(t));
                    return true;
                }
            return false;
        });
    }

    // A timeout's condition: its origin has been active for its delay (the origin is active: it
    // is on the component's active path). Then the guard, which receives bsc::eventless.
    bool condition_holds(std::int16_t t) {
        auto const& row = transitions[static_cast<std::size_t>(t)];
        if constexpr (tables_type::timeout_slots > 0)
            if (row.event == timeout_id && !this->timeout_due(row.timeout_slot, row.delay(this->chart()))) return false;
        return guard_holds(t, &no_event);
    }

    // The transition that fires when condition-driven transition t's condition holds: t, unless
    // it is a timeout and a timeout of the same origin declared after it is due too, came due
    // first (detail::came_due_first) and its guard holds; then the first of those to come due.
    // (The timeouts declared before t did not hold, or t would not be tried.) Only a chart with
    // a state of several timeout rows looks, and only at such a state's timeouts.
    std::int16_t first_due(std::int16_t t) {
        if constexpr (tables_type::competing_timeouts) {
            auto const& row = transitions[static_cast<std::size_t>(t)];
            if (row.event == timeout_id && states[row.from].timeout_slots > 1) {
                std::int16_t first = t;
                int slot = row.timeout_slot;
                duration delay = row.delay(this->chart());
                for (std::int16_t u = tables_type::next_out[static_cast<std::size_t>(t)]; u >= 0;
                     u = tables_type::next_out[static_cast<std::size_t>(u)]) {
                    auto const& other = transitions[static_cast<std::size_t>(u)];
                    if (other.event != timeout_id) continue;
                    duration const u_delay = other.delay(this->chart());
                    if (this->timeout_due(other.timeout_slot, u_delay) &&
                        this->came_due_before(other.timeout_slot, u_delay, slot, delay) && guard_holds(u, &no_event)) {
                        first = u;
                        slot = other.timeout_slot;
                        delay = u_delay;
                    }
                }
                return first;
            }
        }
        return t;
    }

    // Steps 3 to 5 of a microstep for one transition: a component's transition fires alone.
    void fire_condition(std::int16_t t) {
        auto const& row = transitions[static_cast<std::size_t>(t)];
        if (row.to != no_state) deactivate_path(row.domain);
        run_action(t, &no_event);
        enter_targets(row);
        // A timeout that leaves its state active counts again from now (layout.hpp, rearms).
        if constexpr (tables_type::timeout_slots > 0)
            if (row.rearms) this->rearm_timeout(row.timeout_slot);
    }

    // The event that eventless and timeout transitions receive.
    static constexpr bsc::eventless no_event{};
};

// As for bsc::machine: `machine{chart, ...}` and `machine<decltype(chart)>` name the same type.
// A machine of a chart that failed its checks does nothing (detail/runtime/rejected.hpp).
template <statechart Chart, machine_policy Policy, class Observer>
    requires bsc::detail::rejected<Chart>
class machine<Chart, Policy, Observer> : public bsc::detail::inert_machine<Chart> {
public:
    using bsc::detail::inert_machine<Chart>::inert_machine;
};

template <class C, class... A>
machine(C const&, A...) -> machine<C const, default_policy, bsc::detail::observer_argument_t<A...>>;

}  // namespace bsc::table
