#pragma once
// The model of a chart: its state tree and its rows flattened into constexpr arrays, from
// which everything else is computed. The static checks, both back ends, the exports and the
// explorer read these arrays; only lookups by type use templates.

#include <array>
#include <cstdint>
#include <string_view>
#include <type_traits>

#include <bsc/detail/meta.hpp>
#include <bsc/detail/type_name.hpp>
#include <bsc/dsl/row.hpp>
#include <bsc/dsl/tree.hpp>
#include <bsc/priority.hpp>
#include <bsc/detail/model/event_families.hpp>

namespace bsc {
template <auto const& Chart>
struct chart_ref;
}  // namespace bsc

namespace bsc::detail {

// The implicit top of every chart: the compound state above the user's root, so that a
// transition may leave and re-enter the root (SCXML's <scxml> element plays this part).
struct top_tag {};
template <class Root>
struct top_node : node_base {
    using tag = top_tag;
    static constexpr kind node_kind = kind::top;
    static constexpr history hist = history::none;
    static constexpr bool implicit = false;
    using initials = type_list<typename Root::tag>;
    using children = type_list<Root>;
};

template <class Node>
constexpr auto flatten();
template <class... C>
constexpr auto flatten_all(type_list<C...>) {
    return concat_t<decltype(flatten<C>())...>{};
}
template <class Node>
constexpr auto flatten() {
    return concat_t<type_list<Node>, decltype(flatten_all(typename Node::children{}))>{};
}

template <class List>
struct tags_of;
template <class... Nodes>
struct tags_of<type_list<Nodes...>> {
    using type = type_list<typename Nodes::tag...>;
};

enum class row_kind : std::uint8_t { transition, entry, exit, initial };

inline constexpr int eventless_id = -1;
// Every timeout row has a trigger of its own, so two timeouts on one state never "conflict".
constexpr int timeout_trigger_id(int row) { return -2 - row; }
// Eventless and timeout transitions are condition-driven: the ones a BSC cycle considers.
inline constexpr int any_condition = -1'000'000;
inline constexpr int no_state = -1;
inline constexpr int unknown_state = -2;

template <std::size_t N>
struct topology {
    std::array<kind, N> kinds{};
    std::array<history, N> hist{};
    std::array<int, N> parent{};
    std::array<int, N> first_child{};
    std::array<int, N> next_sibling{};
    std::array<int, N> child_count{};
    std::array<int, N> ordinal{};                      // position among siblings
    std::array<int, N> initial{};                      // state index of the initial child, or -1
    std::array<int, N> initial_target{};               // the initial state: the initial child, or a deeper descendant
    std::array<std::array<int, 3>, N> more_initial{};  // initial states after the first (initial<A, B>), else -1

    // State s's initial states: its initial state, then the others (initial<A, B>), -1 after.
    constexpr std::array<int, 4> initial_states(std::size_t s) const {
        return {initial_target[s], more_initial[s][0], more_initial[s][1], more_initial[s][2]};
    }
    std::array<int, N> initial_count{};  // number of initial markers
    std::array<int, N> depth{};
    std::array<int, N> end{};   // one past the last descendant: d is below s iff s < d < end[s]
    std::array<int, N> slot{};  // byte of the active configuration, composites only, else -1
    std::array<bool, N> implicit{};
    int slots = 0;

    // The most children any composite has: the configuration keeps each composite's active
    // child in a byte up to 255 of them, in two bytes above (chart_model::ordinal_type).
    constexpr int most_children() const {
        int most = 0;
        for (std::size_t s = 0; s < N; ++s)
            if (slot[s] >= 0 && child_count[s] > most) most = child_count[s];
        return most;
    }

    // States are numbered by int (negative numbers mean "none"); the arrays by size_t.
    static constexpr std::size_t at(int s) { return static_cast<std::size_t>(s); }

    constexpr bool is_leaf(int s) const { return kinds[at(s)] == kind::basic || kinds[at(s)] == kind::final_state; }
    constexpr bool is_compound(int s) const { return kinds[at(s)] == kind::composite || kinds[at(s)] == kind::top; }
    // a is an ancestor of d, or d itself
    constexpr bool contains(int a, int d) const { return a <= d && d < end[at(a)]; }
    constexpr bool is_proper_ancestor(int a, int d) const { return a < d && d < end[at(a)]; }
    constexpr int lca(int a, int b) const {
        while (!contains(a, b)) a = parent[at(a)];
        return a;
    }
    // The child of `a` on the way down to its descendant d.
    constexpr int child_toward(int a, int d) const {
        int c = d;
        while (parent[at(c)] != a) c = parent[at(c)];
        return c;
    }
    constexpr bool under_parallel(int s) const {
        for (int a = parent[at(s)]; a >= 0; a = parent[at(a)])
            if (kinds[at(a)] == kind::parallel) return true;
        return false;
    }
};

// Whether one of a node's children is a history state.
template <class... C>
constexpr bool has_history_child(type_list<C...>) {
    return any_true({(C::node_kind == kind::history)...});
}

// Links the next child of node i into the sibling chain.
template <std::size_t N>
constexpr void link_child(topology<N>& t, std::size_t i, int& previous, int child) {
    if (previous < 0)
        t.first_child[i] = child;
    else
        t.next_sibling[static_cast<std::size_t>(previous)] = child;
    previous = child;
}

// (The walk over a node's children is a fold over plain calls, with no lambda per child: a
// lambda's symbol spells its enclosing function's arguments, here the node with all its
// children, and building those names for every child of a large composite was a quadratic part
// of a chart's compile time.)
template <class Node, std::size_t N>
constexpr int fill_topology(topology<N>& t, int index, int parent, int ordinal, int depth) {
    t.kinds[static_cast<std::size_t>(index)] = Node::node_kind;
    auto const i = static_cast<std::size_t>(index);
    t.hist[i] = Node::hist;
    t.parent[i] = parent;
    t.ordinal[i] = ordinal;
    t.depth[i] = depth;
    t.implicit[i] = Node::implicit;
    t.first_child[i] = -1;
    t.next_sibling[i] = -1;
    t.initial[i] = -1;
    t.initial_target[i] = -1;
    for (int& m : t.more_initial[i]) m = -1;
    t.initial_count[i] = static_cast<int>(Node::initials::size);
    t.slot[i] = -1;
    if (Node::node_kind == kind::composite) t.slot[i] = t.slots++;
    int next = index + 1;
    int count = 0;
    int previous = -1;
    // clang-format off
    [&]<class... C>(type_list<C...>) {
        // (An array's initializers, evaluated in order, and not a fold expression: see count_true.)
        [[maybe_unused]] int const linked[] = {
            (link_child(t, i, previous, next), next = fill_topology<C>(t, next, index, count++, depth + 1))..., 0};
        if constexpr (Node::initials::size == 1) {
            using initial_tag = at<0, typename Node::initials>;
            constexpr int pos = position_in<initial_tag, type_list<typename C::tag...>>::value;
            if constexpr (pos >= 0) {
                int c = t.first_child[i];
                for (int k = 0; k < pos; ++k) c = t.next_sibling[static_cast<std::size_t>(c)];
                t.initial[i] = c;
                t.initial_target[i] = c;
            } else {
                // A deep initial: a descendant further down, numbered in document order below Node.
                constexpr int offset = position_in<initial_tag, typename tags_of<decltype(flatten<Node>())>::type>::value;
                if (offset > 0) {
                    t.initial_target[i] = index + offset;
                    t.initial[i] = t.child_toward(index, index + offset);
                }
            }
        }
    }(typename Node::children{});
    // clang-format on
    t.child_count[i] = count;
    t.end[i] = next;
    // Its initial states after the first, below it (unknown_state if not declared there).
    if constexpr (requires {
                      requires Node::more_initials::size >
                      0;
                  })
        // clang-format off
        [&]<class... More>(type_list<More...>) {
            using tags = typename tags_of<decltype(flatten<Node>())>::type;
            std::size_t k = 0;
            ((t.more_initial[i][k++] = position_in<More, tags>::value > 0 ? index + position_in<More, tags>::value : unknown_state), ...);
        }(typename Node::more_initials{});
    // clang-format on
    // The defaults of its history states, which lie anywhere below Node (-1 if not found).
    if constexpr (Node::node_kind == kind::composite && has_history_child(typename Node::children{}))
        // clang-format off
        [&]<class... C>(type_list<C...>) {
            [[maybe_unused]] int const placed[] = {(  // (a list: max_fold)
                [&] {
                    if constexpr (C::node_kind == kind::history) {
                        using tags = typename tags_of<decltype(flatten<Node>())>::type;
                        constexpr int h = position_in<typename C::tag, tags>::value;
                        constexpr int offset = position_in<typename C::default_state, tags>::value;
                        if (offset > 0 && index + offset != index + h) {
                            t.initial_target[static_cast<std::size_t>(index + h)] = index + offset;
                            t.initial[static_cast<std::size_t>(index + h)] = t.child_toward(index, index + offset);
                        }
                    }
                }(),
                0)...};
        }(typename Node::children{});
    // clang-format on
    return next;
}

template <std::size_t R>
struct row_table {
    std::array<row_kind, R> kinds{};
    std::array<int, R> source{};
    std::array<int, R> target{};   // no_state for internal transitions and entry/exit rows
    std::array<int, R> trigger{};  // eventless_id, or the event's position in the chart's event list
    std::array<bool, R> guarded{};
    std::array<int, R> domain{};   // the transition domain (SCXML), no_state if internal
    std::array<bool, R> local{};   // declared local (bsc::local): its domain is its source
    std::array<bool, R> defers{};  // defers its event (/ bsc::defer)
    // A transition with several targets (bsc::targets): `target` is the first, these the others
    // (no_state where there are fewer).
    static constexpr std::size_t max_more_targets = 3;
    std::array<std::array<int, max_more_targets>, R> more_targets{};
    // Whether row r has several targets.
    constexpr bool several(std::size_t r) const { return more_targets[r][0] >= 0; }
    // Row r's targets: its target, then the others (bsc::targets), no_state after.
    constexpr std::array<int, 1 + max_more_targets> targets_of(std::size_t r) const {
        return {target[r], more_targets[r][0], more_targets[r][1], more_targets[r][2]};
    }
    // By event position (there are no more events than rows): the event's nearest family among
    // the chart's events (-1: none, -2: not a chain). All -1 in a chart without families.
    std::array<int, R> event_family{};

    // Whether a row on trigger `row_trigger` takes trigger `taken`: the same trigger, or an
    // event position whose chain of families holds row_trigger.
    constexpr bool takes(int row_trigger, int taken) const {
        if (row_trigger == taken) return true;
        if (row_trigger < 0) return false;
        for (int t = taken; t >= 0; t = event_family[static_cast<std::size_t>(t)])
            if (t == row_trigger) return true;
        return false;
    }
};

template <class Row>
constexpr row_kind kind_of_row() {
    if constexpr (is_entry_row<Row>)
        return row_kind::entry;
    else if constexpr (is_exit_row<Row>)
        return row_kind::exit;
    else if constexpr (is_initial_row<Row>)
        return row_kind::initial;
    else
        return row_kind::transition;
}

template <class Row>
struct trigger_event {
    using type = void;
};
template <class S, class E, class G, class A, class T>
struct trigger_event<transition_row<S, event_trigger<E>, G, A, T>> {
    using type = E;
};

// The event a row's guard and action are called with: its trigger event, or bsc::eventless for
// a condition-driven row (entry and exit actions see no event).
template <class Row>
using row_event_t = std::conditional_t<std::is_void_v<typename trigger_event<Row>::type>, eventless_trigger,
                                       typename trigger_event<Row>::type>;

// The events of the rows, each once, in order of first appearance.
template <class List>
struct event_list;
template <class... Rows>
struct event_list<type_list<Rows...>> {
    using with_repeats = type_list<typename trigger_event<Rows>::type...>;
    template <std::size_t... I>
    static auto first_occurrences(std::index_sequence<I...>) -> concat_t<
        std::conditional_t<position_in<typename trigger_event<Rows>::type, with_repeats>::value == static_cast<int>(I),
                           type_list<typename trigger_event<Rows>::type>, type_list<>>...>;
    using all = decltype(first_occurrences(std::index_sequence_for<Rows...>{}));
};
template <class List>
struct drop_void;
template <class... Es>
struct drop_void<type_list<Es...>> {
    using type = concat_t<std::conditional_t<std::is_void_v<Es>, type_list<>, type_list<Es>>...>;
};

// The index of state Tag among Tags: no_state for no target, unknown_state if not there. A
// class, not a function: a function's symbol would spell the chart's states, once per row.
template <class Tag, class Tags>
struct state_index {
    enum : int { value = position_in<Tag, Tags>::value < 0 ? unknown_state : position_in<Tag, Tags>::value };
};
template <class Tags>
struct state_index<no_target, Tags> {
    enum : int { value = no_state };
};

// What the row table holds of a row, found from its type alone: classes whose enumerators are
// the values, which make no symbol. (A function or variable per row, named with the chart's
// states and events, would be one, and a large chart's names then took quadratic time.)
template <class Row, int K, class Tags, bool = (K < static_cast<int>(Row::targets::size))>
struct nth_target {
    enum : int { value = no_state };
};
template <class Row, int K, class Tags>
struct nth_target<Row, K, Tags, true> {
    enum : int { value = state_index<at<static_cast<std::size_t>(K), typename Row::targets>, Tags>::value };
};
template <class E, class Events>
struct trigger_position {
    enum : int { value = position_in<E, Events>::value };
};
template <class Events>
struct trigger_position<void, Events> {
    enum : int { value = eventless_id };
};
template <class Row, class Tags, class Events, bool = is_transition_row<Row>>
struct row_facts {  // an entry, exit or initial row
    enum : int {
        source = state_index<typename Row::source, Tags>::value,
        target = no_state,
        trigger = eventless_id,
        timeout = 0,
        guarded = 0,
        local = 0,
        defers = 0,
        more0 = no_state,
        more1 = no_state,
        more2 = no_state
    };
};
template <class Row, class Tags, class Events>
struct row_facts<Row, Tags, Events, true> {
    enum : int {
        source = state_index<typename Row::source, Tags>::value,
        target = state_index<typename Row::target, Tags>::value,
        trigger = trigger_position<typename trigger_event<Row>::type, Events>::value,
        timeout = is_timeout_row<Row> ? 1 : 0,
        guarded = Row::guarded ? 1 : 0,
        local = Row::local ? 1 : 0,
        defers = Row::defers ? 1 : 0,
        more0 = nth_target<Row, 1, Tags>::value,
        more1 = nth_target<Row, 2, Tags>::value,
        more2 = nth_target<Row, 3, Tags>::value
    };
};

template <std::size_t N, std::size_t M = 0>
constexpr int transition_domain(topology<N> const& t, int source, int target, bool local = false,
                                std::array<int, M> const& more = {}) {
    if (target < 0) return no_state;
    // SCXML's type="internal": a compound source that contains the target stays active.
    if (local && t.kinds[static_cast<std::size_t>(source)] == kind::composite && t.is_proper_ancestor(source, target))
        return source;
    // SCXML: the nearest compound proper ancestor of the source that is a proper ancestor of
    // every target.
    for (int a = t.parent[static_cast<std::size_t>(source)]; a >= 0; a = t.parent[static_cast<std::size_t>(a)]) {
        bool above_all = t.is_compound(a) && t.is_proper_ancestor(a, target);
        for (int m : more)
            if (m >= 0) above_all = above_all && t.is_proper_ancestor(a, m);
        if (above_all) return a;
    }
    return 0;
}

template <class Chart>
struct chart_model {
    using root = typename Chart::root_type;
    using nodes = decltype(flatten<top_node<root>>());
    using tags = typename tags_of<nodes>::type;
    using row_types = typename Chart::row_types;
    using chart_context = typename Chart::context_type;
    using events = typename drop_void<typename event_list<row_types>::all>::type;

    static constexpr int N = static_cast<int>(nodes::size);
    static constexpr int R = static_cast<int>(row_types::size);
    // Which of a state's candidate rows are tried first: its own or its ancestors'.
    static constexpr priority order = Chart::order;

    static constexpr topology<nodes::size> tree = [] {
        topology<nodes::size> t{};
        fill_topology<top_node<root>>(t, 0, -1, 0, 0);
        return t;
    }();
    // The type of a composite's entry in the configuration (bsc::configuration::active).
    using ordinal_type = std::conditional_t<(tree.most_children() > 255), std::uint16_t, std::uint8_t>;

    // clang-format off
    static constexpr row_table<row_types::size> rows = []<class... Rs>(type_list<Rs...>) {
        row_table<row_types::size> r{};
        for (int& f : r.event_family) f = -1;
        std::size_t e = 0;
        for (int f : event_families<events>::nearest) r.event_family[e++] = f;
        if constexpr (sizeof...(Rs) > 0) {
            // One list per column, each entry read from the row's facts (row_facts).
            row_kind const kinds[] = {kind_of_row<Rs>()...};
            int const facts[][10] = {{row_facts<Rs, tags, events>::source, row_facts<Rs, tags, events>::target,
                                      row_facts<Rs, tags, events>::trigger, row_facts<Rs, tags, events>::timeout,
                                      row_facts<Rs, tags, events>::guarded, row_facts<Rs, tags, events>::local,
                                      row_facts<Rs, tags, events>::defers, row_facts<Rs, tags, events>::more0,
                                      row_facts<Rs, tags, events>::more1, row_facts<Rs, tags, events>::more2}...};
            for (std::size_t i = 0; i < sizeof...(Rs); ++i) {
                auto const& f = facts[i];
                r.kinds[i] = kinds[i];
                r.source[i] = f[0];
                r.target[i] = f[1];
                r.trigger[i] = f[3] != 0 ? timeout_trigger_id(static_cast<int>(i)) : f[2];
                r.guarded[i] = f[4] != 0;
                r.local[i] = f[5] != 0;
                r.defers[i] = f[6] != 0;
                r.more_targets[i] = {f[7], f[8], f[9]};
                r.domain[i] = no_state;
                if (r.source[i] >= 0 && r.target[i] >= 0)
                    r.domain[i] = transition_domain(tree, r.source[i], r.target[i], r.local[i], r.more_targets[i]);
            }
        }
        return r;
    }(row_types{});
    // clang-format on

    template <int I>
    using tag_at = at<static_cast<std::size_t>(I), tags>;
    template <int I>
    using row_at = at<static_cast<std::size_t>(I), row_types>;
    // (The lookups by type are classes, which make no symbol: a variable or function per state
    // or event would be one, named by spelling the whole chart, and a large chart's symbols
    // then took time quadratic in its size.)
    template <class S>
    using index_of_state = std::integral_constant<int, position_in<S, tags>::value>;
    // Whether some event of the chart has a family (a base class among the chart's events, or
    // bsc::any_event): only then can an event take rows of another type.
    static constexpr bool has_families = event_families<events>::any;
    // Whether a row defers its event: only then does a machine keep deferred events.
    static constexpr bool has_deferral = [] {
        for (bool d : rows.defers)
            if (d) return true;
        return false;
    }();
    // The trigger of event E: its position among the chart's events, or, for an event the chart
    // does not name, its nearest family's (-1: none; -2: its families are not a chain).
    template <class E>
    using trigger_of = std::integral_constant<int, trigger_in<E, events>::value>;
};

// The model of bsc::chart_ref<chart> is the model of the chart itself: the same tables,
// computed once for the chart's checks (make_chart) and its machine, under a type whose name is
// short, so that what a machine instantiates per event or state from its model (the compiled
// plan's lists) has a short name too.
template <auto const& Chart>
struct chart_model<chart_ref<Chart>> : chart_model<std::remove_cvref_t<decltype(Chart)>> {};

// The unqualified names of a model's states, by index (0: the implicit top). A variable of
// its own, so that only what shows names (active_states, the tables, reports) instantiates it.
template <class Model>
// clang-format off
inline constexpr auto state_names_of = []<class... Tags>(type_list<Tags...>) {
    return std::array<std::string_view, sizeof...(Tags)>{name_of<Tags>...};
}(typename Model::tags{});
// clang-format on

}  // namespace bsc::detail
