#pragma once
// bsc::machine: the compiled back end. For an event type, dispatch is a nest of switches on
// the configuration bytes that visits only the states where a transition on that event can
// leave; at each basic state the candidate transitions, their exits, action and entries are
// straight-line code fixed at compile time. Parallel regions select first and fire after,
// as SCXML's microstep does. The public interface and the run to completion are the shared
// driver's (detail/runtime/driver.hpp); this file selects and fires.

#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include <bsc/chart.hpp>
#include <bsc/detail/compiled/plan.hpp>
#include <bsc/detail/config.hpp>
#include <bsc/detail/meta.hpp>
#include <bsc/detail/model/configuration_view.hpp>
#include <bsc/observer.hpp>
#include <bsc/outcome.hpp>
#include <bsc/policies.hpp>
#include <bsc/statechart.hpp>
#include <bsc/detail/runtime/driver.hpp>
#include <bsc/detail/runtime/queue_for.hpp>
#include <bsc/detail/runtime/rejected.hpp>
#include <bsc/detail/runtime/notify.hpp>
#include <bsc/detail/runtime/selection.hpp>


namespace bsc {

/// A running instance of a chart: its context, its active configuration and its internal
/// event queue. Construction enters the initial configuration; dispatch(e) processes one
/// event to completion; step(now) runs one BSC execution cycle. No heap, no virtual calls,
/// no RTTI, no exceptions; usable in constant expressions.
///
/// Requirements: `Chart` is a bsc::statechart (the type of a chart from bsc::make_chart, or
/// bsc::chart_ref); `Policy` is a bsc::machine_policy (bsc::default_policy, or a class derived from
/// it); `Observer` implements any subset of the hooks in observer.hpp.
template <statechart Chart, machine_policy Policy = default_policy, class Observer = no_observer>
class machine : public detail::driver<machine<Chart, Policy, Observer>, Chart, Policy, Observer,
                                      detail::queue_for<Chart, Policy>> {
    using base = detail::driver<machine, Chart, Policy, Observer, detail::queue_for<Chart, Policy>>;
    friend base;
    // The driver's layers that call the hooks (detail/runtime/backend.hpp), and backend_hooks,
    // through which the driver checks them.
    friend detail::backend_hooks;
    template <class, class, class, class, class>
    friend class detail::settling;
    template <class, class, class, class, class>
    friend class detail::deferral;
    template <class, class, class, class, class>
    friend class detail::done_raising;
    // A dispatch marks the machine running only where a guard or a transition is about to run
    // (guard_holds, fire_from), or, in a chart with parallel states, at each microstep: an
    // ignored event in a chart without parallel states writes nothing. (What a run takes after
    // its dispatched event, raised, deferred and eventless, is marked before its walk: fire().)
    static constexpr bool marks_running_lazily = true;
    using typename base::model;
    using plan = detail::plan<model>;
    static constexpr auto const& tree = model::tree;
    static constexpr auto const& rows = model::rows;
    static constexpr int root = plan::root;
    using base::context_;
    using base::config_;
    using base::queue_;
    using base::observer_;
    using notify = detail::notify<model, Observer>;
    using base::observed;

public:
    using typename base::context_type;
    /// Enters the initial configuration (entry actions run) and settles eventless transitions.
    /// (The chart parameter's type_identity leaves deduction to the guides below.)
    constexpr explicit machine(std::type_identity_t<Chart> const& chart, context_type context = {},
                               Observer observer = {})
        : base(chart, std::move(context), std::move(observer)) {
        this->start();
    }

private:
    // ---- the configuration -----------------------------------------------------------------
    template <int S>
    constexpr int active_child() const {
        if constexpr (tree.slot[S] >= 0) {
            return config_.active[static_cast<std::size_t>(tree.slot[S])];
        } else {
            return 0;  // the top has one child
        }
    }
    template <int S>
    constexpr void set_active_child(int ordinal) {
        if constexpr (tree.slot[S] >= 0)
            config_.active[static_cast<std::size_t>(tree.slot[S])] = static_cast<typename model::ordinal_type>(ordinal);
    }
    template <int S>
    constexpr bool is_active() const {
        if constexpr (S <= root) {
            return true;
        } else {
            constexpr int p = tree.parent[S];
            if constexpr (tree.slot[p] >= 0)
                return active_child<p>() == tree.ordinal[S] && is_active<p>();
            else
                return is_active<p>();
        }
    }

    // The event e as row Row sees it: its own event type, a family of it, or bsc::any_event.
    // (Where E is the row's own event, e is passed as it is: most rows of most charts, and no
    // conversion to instantiate.)
    template <int Row, class E>
    static constexpr bool sees_itself = BSC_DETAIL_IS_SAME(E,
                                                           detail::row_event_t<typename model::template row_at<Row>>);
    template <int Row, class E>
    static constexpr decltype(auto) seen_by(E const& e) {
        return detail::event_as<detail::row_event_t<typename model::template row_at<Row>>>(e);
    }

    constexpr void enter_initial() { enter_default<root>(); }
    // When the machine halts: every active state's exit actions, innermost first.
    constexpr void exit_all() { exit_below<0>(); }

    // ---- entry and exit ----------------------------------------------------------------
    // Whether entering (exiting) state s does anything: entry (exit) actions, the observer's
    // hook, and on entry a final state's record or the arming of its timeouts. Most states of
    // most charts do nothing, and are then not called at all: each call instantiates a function
    // per state and per path, which is most of what a chart costs to compile.
    static constexpr bool acts_on_entry(int s) {
        return observed || plan::count_rows(detail::row_kind::entry, s) > 0 ||
               tree.kinds[static_cast<std::size_t>(s)] == detail::kind::final_state ||
               plan::timeout_slot_count[static_cast<std::size_t>(s)] > 0;
    }
    static constexpr bool acts_on_exit(int s) { return observed || plan::count_rows(detail::row_kind::exit, s) > 0; }
    // Whether exiting the path from x up to, not including, d does anything.
    static constexpr bool acts_on_exit_up(int x, int d) {
        for (; x != d; x = tree.parent[static_cast<std::size_t>(x)])
            if (acts_on_exit(x)) return true;
        return false;
    }

    // The entry (or exit) actions of state S, in declaration order.
    template <detail::row_kind K, int S>
    constexpr void run_state_actions() {
        constexpr auto const& actions = plan::template rows_of<K, S>;
        // clang-format off
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            (this->run(this->template row<actions[I]>().action, context_.value, queue_), ...);
        }(std::make_index_sequence<actions.size()>{});
        // clang-format on
    }

    template <int S>
    constexpr void run_entry() {
        if constexpr (plan::count_rows(detail::row_kind::entry, S) > 0) run_state_actions<detail::row_kind::entry, S>();
        if constexpr (tree.kinds[S] == detail::kind::final_state) this->entered_final(S);
        if constexpr (plan::timeout_slot_count[S] > 0)
            this->arm_timeouts(plan::timeout_slot[S], plan::timeout_slot_count[S]);
        if constexpr (observed) notify::template entered<S>(observer_.value);
    }

    template <int S>
    constexpr void run_exit() {
        if constexpr (plan::count_rows(detail::row_kind::exit, S) > 0) run_state_actions<detail::row_kind::exit, S>();
        if constexpr (observed) notify::template exited<S>(observer_.value);
    }

    template <int S, class F>
    static constexpr void for_each_child(F&& f) {
        constexpr auto const& children = plan::template children<S>;
        // clang-format off
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            // (In order, as a list: a composite may have more children than a fold takes,
            // detail::max_fold.)
            [[maybe_unused]] int const visited[] = {((void)f(detail::int_c<children[I]>{}), 0)..., 0};
        }(std::make_index_sequence<children.size()>{});
        // clang-format on
    }

    // Calls f(child) for the active child of composite S if it is one of the children the
    // trigger makes relevant; returns false (without calling f) otherwise.
    template <int Trigger, int S, class F>
    BSC_DETAIL_WALK_INLINE constexpr bool with_relevant_active_child(F&& f) const {
        constexpr auto const& children = plan::template relevant_children<Trigger, S>;
        int const active = active_child<S>();
        // Where every child is relevant, the last needs no test: the byte always names a child.
        // The compiler then builds a jump table without a range check, and where the children
        // all do the same (a reaction every state of a flat chart has) finds nothing to test.
        // (Not below four children: GCC then turns three tests into a lookup of the next byte,
        // which an unconditional last arm prevents.)
        constexpr std::size_t n = children.size();
        constexpr bool every_child = n >= 4 && static_cast<int>(n) == tree.child_count[S];
        // clang-format off
        return [&]<std::size_t... I>(std::index_sequence<I...>) BSC_DETAIL_WALK_INLINE {
            if constexpr (n <= detail::max_fold) {
                return ((active == tree.ordinal[children[I]] || (every_child && I + 1 == n) ? (f(detail::int_c<children[I]>{}), true)
                                                                                              : false) ||
                        ...);
            } else {  // more children than a fold takes: a list of tests, one of which holds
                bool found = false;
                [[maybe_unused]] bool const tested[] = {
                    (active == tree.ordinal[children[I]] ? (f(detail::int_c<children[I]>{}), found = true) : false)...};
                return found;
            }
        }(std::make_index_sequence<n>{});
        // clang-format on
    }

    template <int S, class F>
    constexpr void with_active_child(F&& f) const {
        constexpr auto const& children = plan::template children<S>;
        detail::visit_index<static_cast<int>(children.size())>(
            active_child<S>(), [&](auto i) { f(detail::int_c<children[decltype(i)::value]>{}); });
    }

    // Enters S and its default (or history) completion.
    template <int S>
    constexpr void enter_default() {
        if constexpr (acts_on_entry(S)) run_entry<S>();
        if constexpr (has_content(S)) enter_content<S>();
    }

    // Whether entering S goes on below it (a basic or final state has nothing more to enter);
    // whether entering S by default does anything at all.
    static constexpr bool has_content(int s) {
        return tree.kinds[static_cast<std::size_t>(s)] == detail::kind::composite ||
               tree.kinds[static_cast<std::size_t>(s)] == detail::kind::parallel;
    }
    static constexpr bool acts_on_default_entry(int s) { return acts_on_entry(s) || has_content(s); }

    template <int S>
    constexpr void enter_content() {
        constexpr auto k = tree.kinds[S];
        if constexpr (k == detail::kind::composite) {
            constexpr auto h = tree.hist[S];
            if constexpr (h == detail::history::none) {
                // The initial transition: its actions, then its target, a child or deeper.
                constexpr int init = tree.initial[S];
                run_state_actions<detail::row_kind::initial, S>();
                if constexpr (tree.kinds[init] == detail::kind::history) {
                    enter_history<init>();
                } else if constexpr (tree.more_initial[S][0] >= 0) {
                    enter_toward_all<S, -1 - S>();  // initial<A, B>: one state in each region
                } else if constexpr (tree.initial_target[S] == init) {
                    set_active_child<S>(tree.ordinal[init]);
                    if constexpr (acts_on_default_entry(init)) enter_default<init>();
                } else {
                    enter_toward<S, tree.initial_target[S]>();
                }
            } else if constexpr (h == detail::history::shallow) {
                with_active_child<S>([&](auto c) { enter_default<decltype(c)::value>(); });
            } else {
                with_active_child<S>([&](auto c) { enter_restore<decltype(c)::value>(); });
            }
        } else if constexpr (k == detail::kind::parallel) {
            this->regions_entering(S);
            for_each_child<S>([&](auto c) { enter_default<decltype(c)::value>(); });
            this->regions_entered(S);
        }
    }

    // Enters history state H of composite P: P's remembered child (shallow) or remembered
    // sub-configuration (deep), or, if P has never been active, H's default transition.
    template <int H>
    constexpr void enter_history() {
        constexpr int p = tree.parent[H];
        if (plan::template never_active_byte<p>(active_child<p>())) {
            run_state_actions<detail::row_kind::initial, H>();
            constexpr int c = tree.initial[H];
            if constexpr (tree.initial_target[H] == c) {
                set_active_child<p>(tree.ordinal[c]);
                enter_default<c>();
            } else {
                enter_toward<p, tree.initial_target[H]>();
            }
        } else if constexpr (tree.hist[H] == detail::history::shallow) {
            with_active_child<p>([&](auto c) { enter_default<decltype(c)::value>(); });
        } else {
            with_active_child<p>([&](auto c) { enter_restore<decltype(c)::value>(); });
        }
    }

    // Deep history: re-enters S and the sub-configuration its bytes remember.
    template <int S>
    constexpr void enter_restore() {
        if constexpr (acts_on_entry(S)) run_entry<S>();
        constexpr auto k = tree.kinds[S];
        if constexpr (k == detail::kind::composite)
            with_active_child<S>([&](auto c) { enter_restore<decltype(c)::value>(); });
        else if constexpr (k == detail::kind::parallel) {
            this->regions_entering(S);
            for_each_child<S>([&](auto c) { enter_restore<decltype(c)::value>(); });
            this->regions_entered(S);
        }
    }

    // Enters, below the active state D, the path to Target (and parallel siblings on the way).
    template <int D, int Target>
    constexpr void enter_toward() {
        constexpr int c = tree.child_toward(D, Target);
        if constexpr (tree.kinds[D] == detail::kind::parallel) {
            // (A parallel D is never a transition's domain: it has just been entered.)
            this->regions_entering(D);
            for_each_child<D>([&](auto k) {
                if constexpr (decltype(k)::value == c)
                    enter_path_node<c, Target>();
                else
                    enter_default<decltype(k)::value>();
            });
            this->regions_entered(D);
        } else if constexpr (tree.kinds[c] == detail::kind::history) {
            enter_history<c>();  // D, its composite, has been entered: now its history
        } else {
            set_active_child<D>(tree.ordinal[c]);
            if constexpr (c != Target || acts_on_default_entry(c)) enter_path_node<c, Target>();
        }
    }
    template <int C, int Target>
    constexpr void enter_path_node() {
        if constexpr (acts_on_entry(C)) run_entry<C>();
        if constexpr (C == Target) {
            if constexpr (has_content(C)) enter_content<C>();
        } else {
            enter_toward<C, Target>();
        }
    }

    // Exits the active descendants of S, innermost first, in reverse document order.
    template <int S>
    constexpr void exit_below() {
        constexpr auto k = tree.kinds[S];
        if constexpr (k == detail::kind::composite || k == detail::kind::top) {
            with_active_child<S>([&](auto c) { exit_subtree<decltype(c)::value>(); });
        } else if constexpr (k == detail::kind::parallel) {
            constexpr auto const& children = plan::template children<S>;
            // clang-format off
            [&]<std::size_t... I>(std::index_sequence<I...>) {
                (exit_subtree<children[children.size() - 1 - I]>(), ...);
            }(std::make_index_sequence<children.size()>{});
            // clang-format on
        }
    }
    // Exits the active descendants of S, then S.
    template <int S>
    constexpr void exit_subtree() {
        if constexpr (has_content(S)) exit_below<S>();
        if constexpr (acts_on_exit(S)) run_exit<S>();
    }

    // Exits the known path from basic state X up to, not including, D.
    template <int X, int D>
    constexpr void exit_up() {
        if constexpr (X != D) {
            if constexpr (acts_on_exit(X)) run_exit<X>();
            if constexpr (acts_on_exit_up(tree.parent[X], D)) exit_up<tree.parent[X], D>();
        }
    }

    // ---- transitions -------------------------------------------------------------------
    // Whether the guard of row Row holds. (Called for guarded rows only: an unguarded row holds,
    // and a call would instantiate a function for nothing.)
    // A guard with bsc::in<S> is called with a view of the configuration bytes, whose tests are
    // resolved at compile time (detail/model/configuration_view.hpp: only the bytes between S
    // and its lowest common ancestor with the row's source, active while the guard is evaluated;
    // one compare for a child of another region); every other guard as g(context, event), as before.
    template <int Row, class E>
    constexpr bool guard_holds(E const& e) {
        static_assert(rows.guarded[Row]);
        if constexpr (!plan::has_parallel) this->mark_running();
        if constexpr (detail::tests_configuration<std::remove_cvref_t<decltype(this->template row<Row>().guard)>>)
            return guard_holds_in<Row>(e);
        else if constexpr (sees_itself<Row, E>)
            return this->test(this->template row<Row>().guard, std::as_const(context_.value), e);
        else
            return this->test(this->template row<Row>().guard, std::as_const(context_.value), seen_by<Row>(e));
    }
    template <int Row, class E>
    constexpr bool guard_holds_in(E const& e) {
        detail::configuration_view<model, rows.source[Row]> const active{configuration_bytes()};
        if constexpr (sees_itself<Row, E>)
            return this->test(this->template row<Row>().guard, std::as_const(context_.value), e, active);
        else
            return this->test(this->template row<Row>().guard, std::as_const(context_.value), seen_by<Row>(e), active);
    }
    constexpr typename model::ordinal_type const* configuration_bytes() const {
        if constexpr (tree.slots > 0)
            return config_.active.data();
        else
            return nullptr;  // no composite: no test reads a byte
    }

    template <int Row, class E>
    constexpr void run_action(E const& e) {
        if constexpr (rows.defers[Row]) {  // keeps the event (detail/runtime/deferral.hpp, fire_or_defer)
            if constexpr (observed)
                notify::template transition<Row>(observer_.value, this->template row<Row>(), seen_by<Row>(e));
            this->deferral_selected();
            return;
        } else if constexpr (base::defers) {
            this->transition_fired(rows.domain[Row] >= 0);
        }
        if constexpr (sees_itself<Row, E>) {
            if constexpr (observed) notify::template transition<Row>(observer_.value, this->template row<Row>(), e);
            if constexpr (!std::is_same_v<std::remove_cvref_t<decltype(this->template row<Row>().action)>,
                                          detail::no_action>)
                this->run(this->template row<Row>().action, context_.value, e, queue_);
        } else {
            if constexpr (observed)
                notify::template transition<Row>(observer_.value, this->template row<Row>(), seen_by<Row>(e));
            if constexpr (!std::is_same_v<std::remove_cvref_t<decltype(this->template row<Row>().action)>,
                                          detail::no_action>)
                this->run(this->template row<Row>().action, context_.value, seen_by<Row>(e), queue_);
        }
    }

    template <int Row>
    constexpr void run_entries() {
        constexpr int d = rows.domain[Row];
        if constexpr (d >= 0 && rows.several(Row))
            enter_toward_all<d, Row>();
        else if constexpr (d >= 0)
            enter_toward<d, rows.target[Row]>();
    }

    // ---- several targets: bsc::targets, bsc::initial<A, B> ------------------------------
    // A set of targets, by key: a row's (key >= 0), or the initial states of state s
    // (key -1 - s). Every target set is orthogonal (detail/checks/structure.hpp).
    static constexpr std::array<int, 4> target_set(int key) {
        return key >= 0 ? rows.targets_of(static_cast<std::size_t>(key))
                        : tree.initial_states(static_cast<std::size_t>(-1 - key));
    }
    // A target of the set below state s, -1 if none; whether s is one.
    static constexpr int target_below(int s, int key) {
        for (int t : target_set(key))
            if (t >= 0 && tree.contains(s, t)) return t;
        return -1;
    }
    static constexpr bool is_target(int s, int key) {
        for (int t : target_set(key))
            if (t == s) return true;
        return false;
    }
    // Enters, below the active state D, the paths to every target of the set: at a parallel
    // state, each region toward the targets it holds, the others by default.
    template <int D, int Key>
    constexpr void enter_toward_all() {
        if constexpr (tree.kinds[D] == detail::kind::parallel) {
            this->regions_entering(D);
            for_each_child<D>([&](auto k) {
                if constexpr (target_below(decltype(k)::value, Key) >= 0)
                    enter_path_all<decltype(k)::value, Key>();
                else
                    enter_default<decltype(k)::value>();
            });
            this->regions_entered(D);
        } else {
            constexpr int c = tree.child_toward(D, target_below(D, Key));
            if constexpr (tree.kinds[c] == detail::kind::history) {
                enter_history<c>();
            } else {
                set_active_child<D>(tree.ordinal[c]);
                enter_path_all<c, Key>();
            }
        }
    }
    template <int C, int Key>
    constexpr void enter_path_all() {
        if constexpr (acts_on_entry(C)) run_entry<C>();
        if constexpr (is_target(C, Key)) {
            if constexpr (has_content(C)) enter_content<C>();
        } else {
            enter_toward_all<C, Key>();
        }
    }

    // Fires a transition selected at basic state Leaf (or at a composite where the walk ends),
    // which no parallel state contains: the exit path is known, so exits, action and entries
    // are straight-line code.
    template <int Leaf, int Row, class E>
    constexpr void fire_from(E const& e) {
        if constexpr (!plan::has_parallel) this->mark_running();  // else select_and_fire has marked
        constexpr int d = rows.domain[Row];
        if constexpr (d >= 0 && acts_on_exit_up(Leaf, d)) exit_up<Leaf, d>();
        run_action<Row>(e);
        run_entries<Row>();
    }

    // The transitions selected in parallel regions, fired together after selection.
    struct no_selection {};  // for charts without parallel states
    using selection = detail::selection<static_cast<std::size_t>(plan::max_active_leaves())>;

    // A region-local trigger's selection: per component, 0 or 1 + the row's index in its
    // component_rows.
    struct component_selection {
        std::array<std::uint8_t, plan::components.size()> chosen{};
    };

    // Transitions of such a trigger fire where they are selected, as outside parallel states,
    // when no observer could see the order of exits and entries change.
    template <int Trigger>
    static constexpr bool fires_at_selection = plan::template fires_at_selection<Trigger> && !observed;

    template <int Trigger>
    using selection_for =
        std::conditional_t<!plan::has_parallel || fires_at_selection<Trigger>, no_selection,
                           std::conditional_t<plan::template region_local<Trigger>, component_selection, selection>>;

    template <int Leaf, int Trigger, int Row, class E, class Sel>
    BSC_DETAIL_WALK_INLINE constexpr bool try_row(E const& e, Sel& sel) {
        if constexpr (rows.guarded[Row])
            if (!guard_holds<Row>(e)) return false;
        if constexpr (!tree.under_parallel(Leaf) || fires_at_selection<Trigger>)
            fire_from<Leaf, Row>(e);
        else if constexpr (plan::template region_local<Trigger>)
            sel.chosen[static_cast<std::size_t>(plan::component_of[Leaf])] = static_cast<std::uint8_t>(
                plan::template component_code<Trigger, Row>);
        else
            sel.add(plan::template position_of<Trigger>(Row));
        return true;
    }

    // The candidates of basic state Leaf on the trigger, in order, until one is taken. (Leaf may
    // be a composite where the walk ends: walk_ends_at.)
    template <int Leaf, int Trigger, class E, class Sel>
    BSC_DETAIL_WALK_INLINE constexpr bool try_leaf(E const& e, Sel& sel) {
        constexpr auto const& candidates = plan::template candidates<Leaf, Trigger>;
        // clang-format off
        return [&]<std::size_t... I>(std::index_sequence<I...>) BSC_DETAIL_WALK_INLINE {
            return (try_row<Leaf, Trigger, candidates[I]>(e, sel) || ...);
        }(std::make_index_sequence<candidates.size()>{});
        // clang-format on
    }

    // Whether the states strictly below composite s can be left without a word: none is
    // parallel and none acts on exit.
    static constexpr bool quiet_below(int s) {
        for (int x = s + 1; tree.contains(s, x); ++x)
            if (tree.kinds[static_cast<std::size_t>(x)] == detail::kind::parallel || acts_on_exit(x)) return false;
        return true;
    }
    // Whether the walk for the trigger ends at composite s, as at a basic state: no state below
    // s takes the trigger by a row of its own, and leaving them does nothing, so which of them
    // is active does not matter (s's candidates are every basic state's below it, and firing
    // from s exits what acts). A dispatch then reads none of the bytes below s.
    template <int Trigger>
    static constexpr bool walk_ends_at(int s) {
        return tree.kinds[static_cast<std::size_t>(s)] == detail::kind::composite && !tree.under_parallel(s) &&
               plan::template no_source_below<Trigger>(s) && quiet_below(s);
    }

    // Walks the active configuration below S, visiting only states relevant to the trigger.
    // (A single candidate, or a single relevant child, the common cases, is reached without
    // the helper that expands several: a function less to instantiate for each.)
    template <int S, int Trigger, class E, class Sel>
    BSC_DETAIL_WALK_INLINE constexpr bool select(E const& e, Sel& sel) {
        constexpr auto k = tree.kinds[S];
        if constexpr (!plan::template relevant<Trigger>(S)) {
            return false;
        } else if constexpr (k == detail::kind::basic || k == detail::kind::final_state || walk_ends_at<Trigger>(S)) {
            constexpr auto const& candidates = plan::template candidates<S, Trigger>;
            if constexpr (candidates.size() == 1)
                return try_row<S, Trigger, candidates[0]>(e, sel);
            else
                return try_leaf<S, Trigger>(e, sel);
        } else if constexpr (k == detail::kind::parallel) {
            bool any = false;
            for_each_child<S>([&](auto c) { any = select<decltype(c)::value, Trigger>(e, sel) || any; });
            return any;
        } else if constexpr (constexpr auto const& children = plan::template relevant_children<Trigger, S>;
                             children.size() == 1) {
            if (active_child<S>() != tree.ordinal[children[0]]) return false;
            return select<children[0], Trigger>(e, sel);
        } else {
            bool any = false;
            with_relevant_active_child<Trigger, S>(
                [&](auto c) BSC_DETAIL_WALK_INLINE { any = select<decltype(c)::value, Trigger>(e, sel); });
            return any;
        }
    }

    template <int Trigger, class F>
    static constexpr void with_transition(int position, F&& f) {
        constexpr auto const& on_trigger = plan::template transitions<Trigger>;
        detail::visit_index<static_cast<int>(on_trigger.size())>(
            position, [&](auto i) { f(detail::int_c<on_trigger[decltype(i)::value]>{}); });
    }

    // SCXML: keep what conflict resolution keeps; then exit all, run the actions in order,
    // enter all.
    template <int Trigger, class E>
    constexpr void fire_selected(E const& e, selection const& sel) {
        constexpr auto const& on_trigger = plan::template transitions<Trigger>;
        selection const kept = detail::resolve_conflicts(
            sel,
            [](std::size_t later, std::size_t earlier) {
                return plan::conflict(on_trigger[later], on_trigger[earlier]);
            },
            [](std::size_t later, std::size_t earlier) {
                return plan::preempts(on_trigger[later], on_trigger[earlier]);
            });
        for (std::size_t i = kept.size; i-- > 0;)
            with_transition<Trigger>(kept.rows[i], [&](auto r) {
                constexpr int d = rows.domain[decltype(r)::value];
                if constexpr (d >= 0) exit_below<d>();
            });
        for (std::size_t i = 0; i < kept.size; ++i)
            with_transition<Trigger>(kept.rows[i], [&](auto r) { run_action<decltype(r)::value>(e); });
        for (std::size_t i = 0; i < kept.size; ++i)
            with_transition<Trigger>(kept.rows[i], [&](auto r) { run_entries<decltype(r)::value>(); });
    }

    // Calls f(row) for the row chosen in component C, if any.
    template <int Trigger, int C, class F>
    static constexpr void with_chosen(std::uint8_t code, F&& f) {
        constexpr auto const& chosen_from = plan::template component_rows<Trigger, C>;
        // clang-format off
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            (void)((code == I + 1 ? (f(detail::int_c<chosen_from[I]>{}), true) : false) || ...);
        }(std::make_index_sequence<chosen_from.size()>{});
        // clang-format on
    }

    // A region-local trigger's transitions: none conflicts with another, so all fire; the
    // components are disjoint and visited in document order, which is the order SCXML fires
    // them in.
    template <int Trigger, class E>
    constexpr void fire_components(E const& e, component_selection const& sel) {
        constexpr auto const& selecting = plan::template selecting_components<Trigger>;
        constexpr std::size_t n = selecting.size();
        // clang-format off
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            (with_chosen<Trigger, selecting[n - 1 - I]>(sel.chosen[static_cast<std::size_t>(selecting[n - 1 - I])], [&](auto r) {
                 constexpr int d = rows.domain[decltype(r)::value];
                 if constexpr (d >= 0)
                     exit_below<d>();
             }),
             ...);
            (with_chosen<Trigger, selecting[I]>(sel.chosen[static_cast<std::size_t>(selecting[I])],
                                            [&](auto r) { run_action<decltype(r)::value>(e); }),
             ...);
            (with_chosen<Trigger, selecting[I]>(sel.chosen[static_cast<std::size_t>(selecting[I])],
                                            [&](auto r) { run_entries<decltype(r)::value>(); }),
             ...);
        }(std::make_index_sequence<n>{});
        // clang-format on
    }

    // Selects and fires the transitions Trigger enables, without settling; true if a transition
    // fired. Flattened: the walk of the relevant states, the guards, exits, actions and entries
    // become one straight-line nest of switches for the trigger, whatever the compiler's
    // inlining budget for the function that dispatches (a dispatch of a parallel chart otherwise
    // ended up as calls of the walk's lambdas, which cost more than the walk).
    // (Marked running once, before the walk, where no parallel state marks each microstep: what
    // fire() takes, a raised, deferred or eventless event, comes within a run, where running
    // user code is likely; the walk's own marks (guard_holds, fire_from) then write what is
    // there. Marked only in each transition instead, the walk of a trigger that every state
    // takes alike, as fsm-benchmark's Large takes the event its exits raise, kept a switch on
    // the state for the mark alone: docs/performance.md, rule "Marked before a walk within a run".)
    template <int Trigger, class E>
    BSC_DETAIL_FLATTEN constexpr bool fire(E const& e) {
        if constexpr (!plan::has_parallel) this->mark_running();
        return select_and_fire<Trigger>(e);
    }
    // fire() for a dispatched event, marked only where a guard or transition runs: an ignored
    // event writes nothing.
    template <int Trigger, class E>
    BSC_DETAIL_FLATTEN constexpr bool fire_marking_lazily(E const& e) {
        return select_and_fire<Trigger>(e);
    }
    // fire() for a dispatched event. Where the dispatch has nothing to do after it but record
    // its outcome (no parallel states, nothing raised, no eventless transition or deferral to
    // settle, and a policy that records), it is flattened in line: the dispatch then records
    // the outcome where the transition ends and calls nothing (the call cost a frame, and a
    // mark of the running machine that the record overwrites). Elsewhere fire() is called: a
    // dispatch that records nothing ends in a jump to it, and one that settles, or a firing in
    // several regions, grows more in line than the call costs (docs/performance.md,
    // rule "Dispatched event fired in line where nothing follows").
    static constexpr bool dispatch_fires_in_line =
        !plan::has_parallel && (Policy::refuse_reentry || Policy::keep_last_outcome) &&
        std::is_same_v<detail::queue_for<Chart, Policy>, detail::no_event_queue> &&
        !plan::has_trigger(detail::eventless_id) && !base::defers;
    template <int Trigger, class E>
    BSC_DETAIL_WALK_INLINE constexpr bool fire_dispatched(E const& e) {
        if constexpr (dispatch_fires_in_line)
            return fire_in_line<Trigger>(e);
        else
            return fire_marking_lazily<Trigger>(e);
    }
    // (Flattened before it is put in line: GCC does not flatten what an always-inline function
    // brings into a flattened one, hence select_and_fire itself, not fire().)
    template <int Trigger, class E>
    BSC_DETAIL_FLATTEN BSC_DETAIL_ALWAYS_INLINE constexpr bool fire_in_line(E const& e) {
        return select_and_fire<Trigger>(e);
    }
    template <int Trigger, class E>
    constexpr bool select_and_fire(E const& e) {
        if constexpr (!plan::has_trigger(Trigger)) {
            return false;
        } else {
            // With parallel regions, several transitions may fire in one microstep: one mark
            // before them all costs less than one each.
            if constexpr (plan::has_parallel) this->mark_running();
            using sel_type = selection_for<Trigger>;
            sel_type sel;
            // From the root: the top above it has no byte and no transitions.
            bool const any = select<root, Trigger>(e, sel);
            if constexpr (std::is_same_v<sel_type, component_selection>) {
                if (any) fire_components<Trigger>(e, sel);
            } else if constexpr (std::is_same_v<sel_type, selection>) {
                if (sel.size > 0) fire_selected<Trigger>(e, sel);
            }
            return any;
        }
    }

    // ---- the BSC cycle -----------------------------------------------------------------
    template <int Row>
    constexpr bool condition_holds() {
        if constexpr (rows.trigger[Row] <= detail::timeout_trigger_id(0)) {
            if (!this->timeout_due(plan::row_timeout_slot[Row], this->template row<Row>().trigger_value.delay))
                return false;
        }
        if constexpr (rows.guarded[Row])
            return guard_holds<Row>(eventless{});
        else
            return true;
    }

    // Condition-driven row Row, whose condition holds, fires; a timeout that competes with
    // others of its state by due time (layout.hpp, competes_by_due_time) goes through
    // fire_first_due, every other row straight to fire_condition.
    template <int Row>
    constexpr void fire_candidate() {
        if constexpr (plan::competes_by_due_time(Row))
            fire_first_due<Row>();
        else
            fire_condition<Row>();
    }

    // Timeout row Row, due, fires; but if a timeout row of its source declared after it is due
    // too, came due first (plan.hpp, later_timeouts; detail::came_due_first) and its guard
    // holds, that one fires instead: of a state's timeouts due at once, the first to come due.
    template <int Row>
    constexpr void fire_first_due() {
        constexpr auto const& later = plan::template later_timeouts<Row>;
        if constexpr (later.size() == 0) {
            fire_condition<Row>();
        } else {
            std::size_t first = 0;  // 0: Row itself, k: later[k - 1]
            int slot = plan::row_timeout_slot[Row];
            duration delay = this->template row<Row>().trigger_value.delay;
            // clang-format off
            [&]<std::size_t... K>(std::index_sequence<K...>) {
                (
                    [&] {
                        constexpr int u = later[K];
                        constexpr int u_slot = plan::row_timeout_slot[u];
                        duration const u_delay = this->template row<u>().trigger_value.delay;
                        if (!this->timeout_due(u_slot, u_delay) || !this->came_due_before(u_slot, u_delay, slot, delay)) return;
                        if constexpr (rows.guarded[u])
                            if (!guard_holds<u>(eventless{})) return;
                        first = K + 1;
                        slot = u_slot;
                        delay = u_delay;
                    }(),
                    ...);
                if (first == 0)
                    fire_condition<Row>();
                else
                    (void)((first == K + 1 ? (fire_condition<later[K]>(), true) : false) || ...);
            }(std::make_index_sequence<later.size()>{});
            // clang-format on
        }
    }

    template <int Row>
    constexpr void fire_condition() {
        constexpr int d = rows.domain[Row];
        if constexpr (d >= 0) exit_below<d>();
        run_action<Row>(eventless{});
        run_entries<Row>();
        // A timeout that leaves its state active counts again from now (layout.hpp, rearms).
        if constexpr (plan::rearms(Row)) this->rearm_timeout(plan::row_timeout_slot[Row]);
    }

    template <int Frontier, int Component>
    constexpr bool try_component_candidates() {
        constexpr auto const& candidates = plan::template component_candidates<Frontier, Component>;
        // clang-format off
        return [&]<std::size_t... I>(std::index_sequence<I...>) {
            return ((condition_holds<candidates[I]>() && (fire_candidate<candidates[I]>(), true)) || ...);
        }(std::make_index_sequence<candidates.size()>{});
        // clang-format on
    }

    // Walks a component from S down to its active frontier and fires its first enabled
    // condition-driven transition, if any.
    template <int Component>
    constexpr bool component_step() {
        return component_walk<Component, Component>();
    }
    template <int S, int Component>
    constexpr bool component_walk() {
        constexpr auto k = tree.kinds[S];
        if constexpr (!plan::template relevant<detail::any_condition>(S)) {
            return false;
        } else if constexpr (k == detail::kind::composite) {
            // An irrelevant child has no condition-driven transition on it or above it.
            bool fired = false;
            with_relevant_active_child<detail::any_condition, S>(
                [&](auto c) { fired = component_walk<decltype(c)::value, Component>(); });
            return fired;
        } else {
            return try_component_candidates<S, Component>();
        }
    }
};

// Charts are declared `constexpr`, so `machine{chart, ...}` and `machine<decltype(chart)>` name
// the same type.
// A machine of a chart that failed its checks does nothing (detail/runtime/rejected.hpp).
template <statechart Chart, machine_policy Policy, class Observer>
    requires detail::rejected<Chart>
class machine<Chart, Policy, Observer> : public detail::inert_machine<Chart> {
public:
    using detail::inert_machine<Chart>::inert_machine;
};

template <class C, class... A>
machine(C const&, A...) -> machine<C const, default_policy, detail::observer_argument_t<A...>>;

}  // namespace bsc
