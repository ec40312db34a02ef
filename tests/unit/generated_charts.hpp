#pragma once
// Random charts built at compile time: gen::chart<Seed> is a bsc chart whose state tree and
// rows are computed by constexpr functions from Seed. States are the types gen::S<Seed, I>,
// events gen::ev<Seed, K>; guards and actions are small function objects whose behaviour is
// also drawn from the seed. Rows are triggered by events, by nothing (eventless) or by a
// timeout; guards and actions use variables, an input and an output channel and a BSC timer.
// The generator only produces charts that pass bsc's static checks:
//   - a transition never joins two regions of a parallel state (targets are redrawn);
//   - no two unguarded transitions share a source and a trigger, and no guarded one follows an
//     unguarded one (later rows are dropped);
//   - every eventless transition is guarded (no eventless livelock can be built);
//   - every state is reachable (an unreachable one gets a transition from a reachable state);
//   - every basic state has a way out (one is added where missing);
//   - no row is dead: none leaves a final child of the root, no row on a state with children
//     is taken first below it in every leaf (a covering row is guarded), and no timeout
//     follows a shorter unguarded one with a target (that one is guarded);
//   - a seed with gen::parent_first_bit set draws a chart with parent-first priority
//     (bsc/priority.hpp), whose dead rows are the other way round: there an unguarded row on an
//     event hides every row on it below its source (that row is guarded).
// gen::generated<Seed> wraps a chart as a fixture for differential.hpp, gen::generated_scan<Seed>
// the same chart under a scan policy. gen::skeleton<K> is a chart whose rows are drawn again at
// run time by gen::draw (see "skeletons" below): one compiled chart that stands for many.

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <utility>

#include <bsc/bsc.hpp>

namespace gen {

inline constexpr int max_states = 16;
inline constexpr int max_rows = 80;
inline constexpr int max_events = 5;

enum class node_kind : std::uint8_t { basic, final_state, composite, parallel };
enum class row_kind : std::uint8_t { transition, entry, exit };

struct node {
    int parent = -1;
    node_kind kind = node_kind::basic;
    int history = 0;  // 0 none, 1 shallow, 2 deep
    int initial = -1;
};

struct row {
    row_kind kind = row_kind::transition;
    int from = 0;
    int event = -1;  // -1: eventless, -2: a timeout
    int to = -1;     // -1: internal
    bool guarded = false;
    bool acts = false;  // has an action
    int delay = 0;      // a timeout's delay, in milliseconds
};

inline constexpr int eventless = -1;
inline constexpr int timeout = -2;

struct spec {
    bool parent_first = false;  // the chart's priority (bsc::parent_first, or the default)
    int n = 0;
    std::array<node, max_states> nodes{};
    int events = 0;
    int r = 0;
    std::array<row, max_rows> rows{};

    constexpr int child_count(int s) const {
        int c = 0;
        for (int i = 0; i < n; ++i) c += nodes[static_cast<std::size_t>(i)].parent == s;
        return c;
    }
    constexpr int child_at(int s, int k) const {
        for (int i = 0; i < n; ++i)
            if (nodes[static_cast<std::size_t>(i)].parent == s && k-- == 0) return i;
        return -1;
    }
    constexpr bool contains(int a, int d) const {
        for (; d >= 0; d = nodes[static_cast<std::size_t>(d)].parent)
            if (d == a) return true;
        return false;
    }
    constexpr int lca(int a, int b) const {
        while (!contains(a, b)) a = nodes[static_cast<std::size_t>(a)].parent;
        return a;
    }
    constexpr node_kind kind(int s) const { return nodes[static_cast<std::size_t>(s)].kind; }
    constexpr bool orthogonal(int from, int to) const {
        int const l = lca(from, to);
        return kind(l) == node_kind::parallel && l != from && l != to;
    }
    // The domain (SCXML) of from -> to: the nearest composite proper ancestor of `from` that
    // is a proper ancestor of `to`; -1 stands for the implicit top.
    constexpr int domain(int from, int to) const {
        for (int a = nodes[static_cast<std::size_t>(from)].parent; a >= 0;
             a = nodes[static_cast<std::size_t>(a)].parent)
            if (kind(a) == node_kind::composite && a != to && contains(a, to)) return a;
        return -1;
    }
    // Adding a row on (from, event) with this guardedness keeps the chart deterministic. Each
    // timeout is a trigger of its own.
    constexpr bool may_add(int from, int event, bool guarded) const {
        if (event == timeout) return true;
        for (int i = 0; i < r; ++i) {
            auto const& x = rows[static_cast<std::size_t>(i)];
            if (x.kind == row_kind::transition && x.from == from && x.event == event && !x.guarded) return false;
        }
        return guarded || event >= 0;
    }
    constexpr void add(row x) { rows[static_cast<std::size_t>(r++)] = x; }

    // bsc's dead transitions (detail/checks/dead_transitions.hpp). A row leaving a final child of a
    // composite root never fires (the machine halts there); a row on an event leaving a state
    // with children never fires when every leaf below takes the event first with an unguarded
    // row of its own or of an ancestor below that state.
    constexpr bool final_root_child(int x) const {
        return nodes[static_cast<std::size_t>(x)].parent == 0 && kind(x) == node_kind::final_state &&
               kind(0) == node_kind::composite;
    }
    constexpr int covering_row(int leaf, int above, int event) const {
        for (int b = leaf; b != above; b = nodes[static_cast<std::size_t>(b)].parent)
            for (int i = 0; i < r; ++i) {
                auto const& x = rows[static_cast<std::size_t>(i)];
                if (x.kind == row_kind::transition && x.from == b && x.event == event && !x.guarded) return i;
            }
        return -1;
    }
    // Drops the rows of the first kind and guards one covering row of each of the second, so
    // that no row is dead; says whether it changed anything.
    constexpr bool fix_dead_rows() {
        bool changed = false;
        int kept = 0;
        for (int i = 0; i < r; ++i) {
            auto const x = rows[static_cast<std::size_t>(i)];
            if (x.kind == row_kind::transition && final_root_child(x.from)) {
                changed = true;
                continue;
            }
            rows[static_cast<std::size_t>(kept++)] = x;
        }
        r = kept;
        // Parent first: an unguarded outer row on x's event hides x; child first: the rows below
        // a state that take its event first in every leaf hide its row.
        int const hidden_by_outer = parent_first ? r : 0;
        int const hidden_by_inner = parent_first ? 0 : r;
        for (int i = 0; i < hidden_by_outer; ++i) {
            auto const x = rows[static_cast<std::size_t>(i)];
            if (x.kind != row_kind::transition || x.event < 0) continue;
            for (int j = 0; j < r; ++j) {
                auto& y = rows[static_cast<std::size_t>(j)];
                if (y.kind == row_kind::transition && y.event == x.event && !y.guarded && y.from != x.from &&
                    contains(y.from, x.from)) {
                    y.guarded = true;
                    changed = true;
                }
            }
        }
        for (int i = 0; i < hidden_by_inner; ++i) {
            auto const x = rows[static_cast<std::size_t>(i)];
            if (x.kind != row_kind::transition || x.event < 0 || child_count(x.from) == 0) continue;
            int cover = -1;
            bool all = true;
            for (int a = 0; a < n && all; ++a) {
                if (a == x.from || !contains(x.from, a) || child_count(a) != 0) continue;
                int const c = covering_row(a, x.from, x.event);
                all = c >= 0;
                if (cover < 0) cover = c;
            }
            if (all && cover >= 0) {
                rows[static_cast<std::size_t>(cover)].guarded = true;
                changed = true;
            }
        }
        // A timeout behind an unguarded one with a target and a shorter delay (or the same,
        // earlier) never fires when both are of one state; bsc also finds it when one state is
        // below the other, or the two lie in regions of one parallel state, and each is active
        // whenever the other is. Guard the shorter one in all these cases (more than bsc needs).
        for (int i = 0; i < r; ++i) {
            auto& x = rows[static_cast<std::size_t>(i)];
            if (x.kind != row_kind::transition || x.event != timeout || x.guarded || x.to < 0) continue;
            for (int j = 0; j < r; ++j) {
                auto const& y = rows[static_cast<std::size_t>(j)];
                bool const same = y.from == x.from;
                if (j != i && y.kind == row_kind::transition && y.event == timeout &&
                    (same ? (x.delay < y.delay || (x.delay == y.delay && i < j))
                          : x.delay <= y.delay && related(x.from, y.from))) {
                    x.guarded = true;
                    changed = true;
                    break;
                }
            }
        }
        return changed;
    }

    // Whether two different states can be active at once with clocks that start together: one
    // is below the other, or their nearest common ancestor is a parallel state.
    constexpr bool related(int a, int b) const {
        return contains(a, b) || contains(b, a) ||
               nodes[static_cast<std::size_t>(lca(a, b))].kind == node_kind::parallel;
    }

    // bsc's reachability (guards ignored): default entries, then the targets of transitions
    // whose source is reachable, with the default entries of parallel siblings on the way.
    constexpr void mark_default(std::array<bool, max_states>& m, int s) const {
        m[static_cast<std::size_t>(s)] = true;
        auto const& nd = nodes[static_cast<std::size_t>(s)];
        if (nd.kind == node_kind::composite)
            mark_default(m, nd.initial);
        else if (nd.kind == node_kind::parallel)
            for (int k = 0; k < child_count(s); ++k) mark_default(m, child_at(s, k));
    }
    constexpr void mark_entry(std::array<bool, max_states>& m, int target) const {
        for (int a = target; a >= 0; a = nodes[static_cast<std::size_t>(a)].parent) {
            m[static_cast<std::size_t>(a)] = true;
            int const p = nodes[static_cast<std::size_t>(a)].parent;
            if (p >= 0 && kind(p) == node_kind::parallel)
                for (int k = 0; k < child_count(p); ++k)
                    if (child_at(p, k) != a) mark_default(m, child_at(p, k));
        }
        mark_default(m, target);
    }
    constexpr std::array<bool, max_states> reachable() const {
        std::array<bool, max_states> m{};
        mark_default(m, 0);
        for (bool changed = true; changed;) {
            changed = false;
            for (int i = 0; i < r; ++i) {
                auto const& x = rows[static_cast<std::size_t>(i)];
                if (x.kind != row_kind::transition || x.to < 0 || !m[static_cast<std::size_t>(x.from)] ||
                    m[static_cast<std::size_t>(x.to)])
                    continue;
                mark_entry(m, x.to);
                changed = true;
            }
        }
        return m;
    }
    constexpr int child_toward(int a, int d) const {
        while (nodes[static_cast<std::size_t>(d)].parent != a) d = nodes[static_cast<std::size_t>(d)].parent;
        return d;
    }
    // Entering `target` necessarily enters x again: x itself, or an ancestor whose initial
    // children (or history, which remembers x) lead back down to x.
    constexpr bool reenters(int target, int x) const {
        if (target == x) return true;
        if (!contains(target, x)) return false;
        for (int c = target; c != x;) {
            auto const& nd = nodes[static_cast<std::size_t>(c)];
            int const toward = child_toward(c, x);
            if (nd.kind == node_kind::composite) {
                if (nd.history == 2) return true;
                if (nd.history == 0 && nd.initial != toward) return false;
            }
            c = toward;
        }
        return true;
    }
    // a is a proper ancestor of d; -1, the implicit top, is above everything.
    constexpr bool above(int a, int d) const { return a < 0 || (a != d && contains(a, d)); }
    // bsc's dead-end rule: some transition with a target that does not necessarily enter x
    // again can fire while x is active and exits x: its source is x or above x (and its domain
    // above x), or in another region of a parallel state above x (and its domain above that).
    constexpr bool can_leave(int x) const {
        for (int i = 0; i < r; ++i) {
            auto const& t = rows[static_cast<std::size_t>(i)];
            if (t.kind != row_kind::transition || t.to < 0 || reenters(t.to, x)) continue;
            int const d = domain(t.from, t.to);
            if (contains(t.from, x)) {
                if (above(d, x)) return true;
            } else if (int const l = lca(t.from, x); kind(l) == node_kind::parallel && above(d, l)) {
                return true;
            }
        }
        return false;
    }
};

struct rng {
    std::uint64_t state;
    constexpr std::uint64_t next() {
        state += 0x9e3779b97f4a7c15ull;
        std::uint64_t z = state;
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    constexpr int below(int n) { return static_cast<int>(next() % static_cast<std::uint64_t>(n)); }
    constexpr bool chance(int percent) { return below(100) < percent; }
};

// A skeleton (see drawn_charts below) draws the same tree and rows from its seed, but every
// transition row has a guard and an action and every entry and exit row is there; the draws
// that would have left them out are still made, so the random sequence is the same.
/// Seeds with this bit draw parent-first charts (their rows drawn afresh, like any other seed's).
inline constexpr std::uint64_t parent_first_bit = std::uint64_t{1} << 30;

constexpr spec make_spec(std::uint64_t seed, bool skeleton = false) {
    rng g{seed * 0x2545f4914f6cdd1dull + 17};
    spec s{};
    s.parent_first = (seed & parent_first_bit) != 0;
    s.n = 8 + g.below(max_states - 8 + 1);
    s.events = 3 + g.below(max_events - 3 + 1);

    // The tree: each state hangs below an earlier one, at most four levels deep.
    std::array<int, max_states> depth{};
    s.nodes[0].kind = g.chance(25) ? node_kind::parallel : node_kind::composite;
    for (int i = 1; i < s.n; ++i) {
        int p = 0;
        do {
            p = g.chance(50) ? g.below(i) : i - 1 - g.below(i < 3 ? i : 3);
        } while (depth[static_cast<std::size_t>(p)] >= 3);
        s.nodes[static_cast<std::size_t>(i)].parent = p;
        depth[static_cast<std::size_t>(i)] = depth[static_cast<std::size_t>(p)] + 1;
    }
    for (int i = 0; i < s.n; ++i)
        if (s.child_count(i) == 0)
            s.nodes[static_cast<std::size_t>(i)].kind = g.chance(8) ? node_kind::final_state : node_kind::basic;
    for (int i = 0; i < s.n; ++i) {
        auto& nd = s.nodes[static_cast<std::size_t>(i)];
        if (s.child_count(i) == 0) continue;
        if (i > 0) nd.kind = g.chance(22) ? node_kind::parallel : node_kind::composite;
        if (nd.kind == node_kind::composite) {
            int const h = g.below(10);
            nd.history = h < 6 ? 0 : h < 8 ? 1 : 2;
            // The initial child is never final: the machine would halt or stop at once.
            int const k = g.below(s.child_count(i));
            int const c = s.child_at(i, k);
            if (s.kind(c) == node_kind::final_state) s.nodes[static_cast<std::size_t>(c)].kind = node_kind::basic;
            nd.initial = c;
        }
    }

    auto pick_source = [&] {
        // Mostly basic states, sometimes any state.
        for (int tries = 0; tries < 8; ++tries) {
            int const x = g.below(s.n);
            if (s.child_count(x) == 0 || g.chance(30)) return x;
        }
        return g.below(s.n);
    };
    auto pick_target = [&](int from) {
        for (int tries = 0; tries < 6; ++tries) {
            int const t = g.below(s.n);
            if (!s.orthogonal(from, t)) return t;
        }
        return from;
    };

    // Random transitions.
    int const wanted = s.n * 2 + g.below(s.n);
    for (int i = 0; i < wanted && s.r < max_rows - 3 * max_states + 4; ++i) {
        row x{};
        x.from = pick_source();
        int const trigger = g.below(100);
        x.event = trigger < 8 ? eventless : trigger < 22 ? timeout : g.below(s.events);
        bool const guarded = x.event == eventless || g.chance(50);
        x.guarded = skeleton || guarded;
        // An eventless internal transition would fire again at once: eventless ones have targets.
        // An internal timeout is never re-armed: it fires in every cycle once due.
        x.to = x.event != eventless && g.chance(12) ? -1 : pick_target(x.from);
        bool const acts = x.event == eventless || g.chance(65);
        x.acts = skeleton || acts;
        if (x.event == timeout) x.delay = 5 * (1 + g.below(12));
        if (s.may_add(x.from, x.event, x.guarded)) s.add(x);
    }
    // No dead row, every state reachable, every basic state a way out; each repair may undo
    // another (a state made final strands its rows), so repeat until none changes anything.
    for (int round = 0; round < 8; ++round) {
        int const rows_before = s.r;
        bool became_final = false;
        bool const fixed = s.fix_dead_rows();
        // Every event triggers something, so that actions may raise any of them.
        for (int e = 0; e < s.events; ++e) {
            bool used = false;
            for (int i = 0; i < s.r; ++i) used = used || s.rows[static_cast<std::size_t>(i)].event == e;
            if (!used) s.add(row{row_kind::transition, 0, e, -1, true, true});
        }
        // Every state reachable.
        for (auto m = s.reachable();; m = s.reachable()) {
            int t = -1;
            for (int i = 0; i < s.n && t < 0; ++i)
                if (!m[static_cast<std::size_t>(i)]) t = i;
            if (t < 0) break;
            int from = 0;
            for (int tries = 0; tries < 12; ++tries) {
                int const c = g.below(s.n);
                if (m[static_cast<std::size_t>(c)] && !s.orthogonal(c, t) && !s.final_root_child(c)) {
                    from = c;
                    break;
                }
            }
            int event = -1;
            for (int e = 0; e < s.events; ++e)
                if (s.may_add(from, e, true)) event = e;
            bool const acts = event < 0 || g.chance(50);
            s.add(row{row_kind::transition, from, event, t, true, skeleton || acts});
        }
        // Every basic state has a way out: a transition to a state that does not lead back to it
        // (or, failing that, the state becomes final).
        for (int x = 0; x < s.n; ++x) {
            if (s.kind(x) != node_kind::basic || s.can_leave(x)) continue;
            // A timeout (one time in three), else an event, else an eventless transition.
            int event = g.chance(33) ? timeout : eventless;
            for (int e = 0; e < s.events && event != timeout; ++e)
                if (s.may_add(x, e, false)) event = e;
            int to = -1;
            for (int tries = 0; tries < 24 && to < 0; ++tries) {
                int const c = g.below(s.n);
                if (!s.orthogonal(x, c) && !s.reenters(c, x)) to = c;
            }
            if (to < 0) {
                s.nodes[static_cast<std::size_t>(x)].kind = node_kind::final_state;
                became_final = true;
            } else {
                bool const guarded = event == eventless || g.chance(40);
                bool const acts = event == eventless || g.chance(50);
                s.add(row{row_kind::transition, x, event, to, skeleton || guarded, skeleton || acts,
                          event == timeout ? 5 * (1 + g.below(12)) : 0});
            }
        }
        if (!fixed && !became_final && s.r == rows_before) break;
    }
    // Entry and exit actions.
    for (int x = 0; x < s.n && s.r < max_rows - 1; ++x) {
        if (g.chance(45) || skeleton) s.add(row{row_kind::entry, x, -1, -1, false, true});
        if ((g.chance(45) || skeleton) && s.r < max_rows) s.add(row{row_kind::exit, x, -1, -1, false, true});
    }
    return s;
}

/// Seeds from here on are skeletons.
inline constexpr std::uint64_t first_skeleton = std::uint64_t{1} << 32;
constexpr bool is_skeleton(std::uint64_t seed) { return seed >= first_skeleton; }

template <std::uint64_t Seed>
inline constexpr spec spec_of = make_spec(Seed, is_skeleton(Seed));

// What a guard or an action does, drawn from the seed and the row.
struct behaviour {
    int var = 0;
    int mod = 2;
    int rem = 0;
    int add = 1;
    bool use_event = false;
    int raise = -1;
};
// Variables: v[0] and v[1] are written by entry and exit actions and by transitions on
// events or timeouts; v[2] only by eventless transitions, which read it alone, and each of
// which makes its own guard false, so that an eventless run settles unless several of them
// cycle. Variable 3 is the channels (a guard reads the latched input, an action writes the
// output), variable 4 the timer (a guard reads tm(), an action starts or resets it).
inline constexpr int channel_var = 3;
inline constexpr int timer_var = 4;
constexpr behaviour behaviour_of(std::uint64_t seed, row const& x, int index, int events) {
    rng g{seed * 1000003ull + static_cast<std::uint64_t>(index) * 7919ull + 5};
    behaviour b{};
    if (x.kind == row_kind::transition)
        b.var = x.event == eventless ? 2 : g.below(5);
    else
        b.var = g.below(4) < 2 ? g.below(2) : 3 + g.below(2);  // never v[2]
    b.mod = 2 + g.below(3);
    b.rem = g.below(b.mod);
    b.add = 1 + g.below(5);
    if (b.add % b.mod == 0)  // an eventless transition's action falsifies its own guard
        ++b.add;
    b.use_event = x.event >= 0 && g.chance(40);
    // Entry and exit actions raise nothing.
    b.raise = x.kind == row_kind::transition && g.chance(9) ? g.below(events) : -1;
    return b;
}


// ---- the chart's types ---------------------------------------------------------------------------

/// The context: three small variables, an input and an output channel and a timer that the
/// guards read and the actions write (see behaviour_of), and the log of every action, entry
/// and exit, in order.
struct gctx {
    std::array<int, 3> v{};
    bsc::input<int> in;
    bsc::output<int> out;
    bsc::timer t{std::chrono::milliseconds{35}};
    std::uint32_t log = 0;
    // Channels have no == of their own: compared by the value read and the value written.
    friend constexpr bool operator==(gctx const& x, gctx const& y) {
        return x.v == y.v && x.in.get() == y.in.get() && x.in.pending() == y.in.pending() &&
               x.out.get() == y.out.get() && x.out.pending() == y.out.pending() && x.t == y.t && x.log == y.log;
    }
};

template <std::uint64_t Seed, int I>
struct S {};
template <std::uint64_t Seed, int K>
struct ev {
    int n = 0;
};

template <class E>
constexpr int payload(E const& e) {
    if constexpr (requires { e.n; })
        return e.n;
    else
        return 0;
}

template <std::uint64_t Seed, int Row>
inline constexpr behaviour behaviour_at = behaviour_of(Seed, spec_of<Seed>.rows[static_cast<std::size_t>(Row)], Row,
                                                       spec_of<Seed>.events);

// What a guard reads: the variable, the latched input or the timer that b names.
constexpr int read_var(behaviour const& b, gctx const& c) {
    if (b.var == channel_var) return c.in.get();
    if (b.var == timer_var) return c.t.tm() ? 1 : 0;
    return c.v[static_cast<std::size_t>(b.var)];
}

constexpr bool holds(behaviour const& b, gctx const& c, int data) {
    return (read_var(b, c) + (b.use_event ? data : 0)) % b.mod == b.rem;
}

template <std::uint64_t Seed, int Row>
struct guard {
    template <class E>
    constexpr bool operator()(gctx const& c, E const& e) const {
        return holds(behaviour_at<Seed, Row>, c, payload(e));
    }
};

// What an action does to the context: logs its row, writes the variable, the output or the
// timer that b names; returns the value written (a raised event carries it).
constexpr int apply(behaviour const& b, int row, gctx& c, int data) {
    c.log = (c.log ^ static_cast<std::uint32_t>(row)) * 16777619u + 1u;
    if (b.var == channel_var) {
        int const written = (c.out.pending() + b.add + (b.use_event ? data : 0)) % 16;
        c.out.set(written);
        return written;
    }
    if (b.var == timer_var) {
        if (b.add % 2 == 1)
            c.t.start();
        else
            c.t.reset();
        return b.add;
    }
    auto& v = c.v[static_cast<std::size_t>(b.var)];
    return v = (v + b.add + (b.use_event ? data : 0)) % 16;
}

template <std::uint64_t Seed, int Row>
constexpr void act_on(gctx& c, int data, auto& raise) {
    constexpr behaviour b = behaviour_at<Seed, Row>;
    int const written = apply(b, Row, c, data);
    if constexpr (b.raise >= 0) raise(ev<Seed, b.raise>{written % 8});
}

template <std::uint64_t Seed, int Row>
struct action {
    template <class E, class Raise>
    constexpr void operator()(gctx& c, E const& e, Raise& raise) const {
        act_on<Seed, Row>(c, payload(e), raise);
    }
};

template <std::uint64_t Seed, int Row>
struct state_action {
    template <class Raise>
    constexpr void operator()(gctx& c, Raise& raise) const {
        act_on<Seed, Row>(c, 0, raise);
    }
};

// ---- skeletons: charts drawn at run time -----------------------------------------------------
// A compiled chart costs seconds of compile time, so a test over a thousand charts cannot
// compile a thousand. A skeleton's rows read what they are from `drawing<Seed>`, which
// draw<Seed>(d) fills from a second seed d: whether each row is live (a dead transition's guard
// is false, a dead entry or exit action does nothing), whether a live transition is guarded,
// whether it acts, and what its guard tests and its action writes and raises (behaviour_of).
// Each draw is a chart of its own on the skeleton's tree: its live rows, in the skeleton's
// order, behave as the rows of a chart with those rows only. The static checks see the
// skeleton, whose rows are all guarded, so they hold for every draw.

struct live_row {
    bool live = true;
    bool guarded = true;
    bool acts = true;
    behaviour what{};
};

template <std::uint64_t Seed>
inline std::array<live_row, max_rows> drawing{};

template <std::uint64_t Seed>
void draw(std::uint64_t d) {
    static_assert(is_skeleton(Seed));
    constexpr spec const& s = spec_of<Seed>;
    rng g{d * 0x9e3779b97f4a7c15ull + Seed};
    for (int i = 0; i < s.r; ++i) {
        auto const& x = s.rows[static_cast<std::size_t>(i)];
        auto& l = drawing<Seed>[static_cast<std::size_t>(i)];
        bool const transition = x.kind == row_kind::transition;
        // An eventless transition is always guarded, and its action falsifies its guard.
        bool const eventless_row = transition && x.event == eventless;
        l.live = g.chance(transition ? 75 : 50);
        l.guarded = eventless_row || g.chance(50);
        l.acts = eventless_row || g.chance(65);
        l.what = behaviour_of(d, x, i, s.events);
    }
}

template <std::uint64_t Seed, int Row>
struct drawn_guard {
    template <class E>
    bool operator()(gctx const& c, E const& e) const {
        auto const& l = drawing<Seed>[static_cast<std::size_t>(Row)];
        if (!l.live) return false;
        return !l.guarded || holds(l.what, c, payload(e));
    }
};

template <std::uint64_t Seed>
void drawn_act(gctx& c, int row, int data, auto& raise) {
    auto const& l = drawing<Seed>[static_cast<std::size_t>(row)];
    if (!l.live || !l.acts) return;
    auto const& b = l.what;
    int const written = apply(b, row, c, data);
    if (b.raise >= 0)
        // clang-format off
        [&]<int... K>(std::integer_sequence<int, K...>) {
            ((b.raise == K ? static_cast<void>(raise(ev<Seed, K>{written % 8})) : void()), ...);
        }(std::make_integer_sequence<int, spec_of<Seed>.events>{});
    // clang-format on
}

template <std::uint64_t Seed, int Row>
struct drawn_action {
    template <class E, class Raise>
    void operator()(gctx& c, E const& e, Raise& raise) const {
        drawn_act<Seed>(c, Row, payload(e), raise);
    }
};

template <std::uint64_t Seed, int Row>
struct drawn_state_action {
    template <class Raise>
    void operator()(gctx& c, Raise& raise) const {
        drawn_act<Seed>(c, Row, 0, raise);
    }
};

template <std::uint64_t Seed, int Row>
using guard_t = std::conditional_t<is_skeleton(Seed), drawn_guard<Seed, Row>, guard<Seed, Row>>;
template <std::uint64_t Seed, int Row>
using action_t = std::conditional_t<is_skeleton(Seed), drawn_action<Seed, Row>, action<Seed, Row>>;
template <std::uint64_t Seed, int Row>
using state_action_t = std::conditional_t<is_skeleton(Seed), drawn_state_action<Seed, Row>, state_action<Seed, Row>>;

// ---- the chart ------------------------------------------------------------------------------

template <std::uint64_t Seed, int I>
constexpr auto make_node() {
    constexpr node nd = spec_of<Seed>.nodes[static_cast<std::size_t>(I)];
    using self = S<Seed, I>;
    if constexpr (nd.kind == node_kind::basic) {
        return bsc::state<self>;
    } else if constexpr (nd.kind == node_kind::final_state) {
        return bsc::final_state<self>;
    } else {
        // clang-format off
        return []<std::size_t... K>(std::index_sequence<K...>) {
            constexpr node n = spec_of<Seed>.nodes[static_cast<std::size_t>(I)];
            using init = S<Seed, n.initial>;
            if constexpr (n.kind == node_kind::parallel)
                return bsc::parallel<self>(make_node<Seed, spec_of<Seed>.child_at(I, static_cast<int>(K))>()...);
            else if constexpr (n.history == 0)
                return bsc::composite<self>(bsc::initial<init>,
                                            make_node<Seed, spec_of<Seed>.child_at(I, static_cast<int>(K))>()...);
            else if constexpr (n.history == 1)
                return bsc::composite<self>(bsc::shallow_history, bsc::initial<init>,
                                            make_node<Seed, spec_of<Seed>.child_at(I, static_cast<int>(K))>()...);
            else
                return bsc::composite<self>(bsc::deep_history, bsc::initial<init>,
                                            make_node<Seed, spec_of<Seed>.child_at(I, static_cast<int>(K))>()...);
        }(std::make_index_sequence<static_cast<std::size_t>(spec_of<Seed>.child_count(I))>{});
        // clang-format on
    }
}

template <std::uint64_t Seed, int J>
inline constexpr row row_at = spec_of<Seed>.rows[static_cast<std::size_t>(J)];

template <std::uint64_t Seed, int J>
constexpr auto make_row() {
    constexpr row x = row_at<Seed, J>;
    using from = S<Seed, x.from>;
    if constexpr (x.kind == row_kind::entry) {
        return bsc::state<from> + bsc::on_entry / state_action_t<Seed, J>{};
    } else if constexpr (x.kind == row_kind::exit) {
        return bsc::state<from> + bsc::on_exit / state_action_t<Seed, J>{};
    } else {
        auto const triggered = [] {
            constexpr auto delay = std::chrono::milliseconds{row_at<Seed, J>.delay};
            if constexpr (row_at<Seed, J>.event == timeout && row_at<Seed, J>.guarded)
                return bsc::state<from> + bsc::after(delay)[guard_t<Seed, J>{}];
            else if constexpr (row_at<Seed, J>.event == timeout)
                return bsc::state<from> + bsc::after(delay);
            else if constexpr (row_at<Seed, J>.event == eventless)
                return bsc::state<from>[guard_t<Seed, J>{}];
            else if constexpr (row_at<Seed, J>.guarded)
                return bsc::state<from> + bsc::event<ev<Seed, row_at<Seed, J>.event>>[guard_t<Seed, J>{}];
            else
                return bsc::state<from> + bsc::event<ev<Seed, row_at<Seed, J>.event>>;
        }();
        auto const acted = [&] {
            if constexpr (row_at<Seed, J>.acts)
                return triggered / action_t<Seed, J>{};
            else
                return triggered;
        }();
        if constexpr (x.to >= 0)
            return acted = bsc::state<S<Seed, x.to>>;
        else
            return acted;
    }
}

template <std::uint64_t Seed>
// clang-format off
inline constexpr auto chart = []<std::size_t... J>(std::index_sequence<J...>) {
    constexpr auto order = spec_of<Seed>.parent_first ? bsc::parent_first : bsc::child_first;
    return bsc::make_chart<gctx, order>(make_node<Seed, 0>(), make_row<Seed, static_cast<int>(J)>()...);
}(std::make_index_sequence<static_cast<std::size_t>(spec_of<Seed>.r)>{});
// clang-format on

/// Low limits: a generated chart may well raise events in a cycle, and then each dispatch
/// runs up to the limit.
struct limits : bsc::default_policy {
    static constexpr std::size_t queue_capacity = 4;
    static constexpr std::size_t max_eventless_steps = 4;
    static constexpr std::size_t max_internal_events = 12;
};

/// The same limits under the BSC scan rules: eventless transitions only in cycles.
struct scan_limits : bsc::scan_policy {
    static constexpr std::size_t queue_capacity = 4;
    static constexpr std::size_t max_internal_events = 12;
};

/// A generated chart as a fixture of differential.hpp.
template <std::uint64_t Seed, class Policy = limits>
struct generated {
    using policy = Policy;
    static constexpr auto const& chart = gen::chart<Seed>;
    static gctx initial() { return {}; }
    static void perturb(gctx& c, std::uint32_t r) {
        if (r % 4 == 3)
            std::as_const(c.in).set(static_cast<int>((r >> 2) % 16));
        else
            c.v[r % 4] = static_cast<int>((r >> 2) % 16);
    }
};
template <std::uint64_t Seed>
using generated_scan = generated<Seed, scan_limits>;

/// The K-th skeleton.
template <std::uint64_t K, class Policy = limits>
using skeleton = generated<first_skeleton + K, Policy>;

/// The chart of seed K drawn with parent-first priority. (One parameter each, to be a template
/// template argument for Clang 14 too.)
template <std::uint64_t K>
using parent_first = generated<parent_first_bit + K>;
template <std::uint64_t K>
using parent_first_scan = generated<parent_first_bit + K, scan_limits>;

}  // namespace gen
