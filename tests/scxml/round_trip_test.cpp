// The round trip of every example chart (docs/scxml.md, "Round trip"): the chart exported as
// SCXML (bsc::to_scxml_annotated), compiled back by bsc-scxml --chart (round_trip.py), and the
// two machines driven side by side, as tests/unit/differential.hpp drives the two back ends:
// the same events, execution cycles at the same times and the same writes of the environment
// to the inputs, compared after every step (outcome, active states, configuration bytes, every
// is<S>(), halted(), the clock, the context and the observer's trace of entries, exits and
// transitions).

#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "round_trip_charts.hpp"
#include "differential.hpp"
#include "differential_examples.hpp"
#include "inside.hpp"

namespace {

// How the environment drives a chart: its policy, its first context, its writes to the inputs.
// Charts of events need none of it: the default.
template <auto const& Chart>
struct drive {
    using policy = bsc::default_policy;
    using context = typename std::remove_cvref_t<decltype(Chart)>::context_type;
    static context initial() { return {}; }
    static void perturb(context const&, std::uint32_t) {}
};

template <class T>
void flip(bsc::input<T> const& in, std::uint32_t r) {
    if constexpr (std::is_same_v<T, bool>)
        in.set(!in.pending());
    else
        in.set(static_cast<T>(r % 8));  // a sensor's few positions
}
// Writes one of the inputs, chosen by r.
template <class... Inputs>
void write_one(std::uint32_t r, Inputs const&... inputs) {
    std::uint32_t k = 0;
    std::uint32_t const chosen = r % sizeof...(Inputs);
    ((k++ == chosen ? flip(inputs, r >> 3) : void()), ...);
}

template <class Context>
struct scan_drive {
    using policy = bsc::scan_policy;
    using context = Context;
    static context initial() { return {}; }
};

template <>
struct drive<cell::chart> : scan_drive<cell::data> {
    static void perturb(cell::data const& d, std::uint32_t r) { write_one(r, d.IN, d.P1, d.P2, d.P3, d.P4, d.S1); }
};
template <>
struct drive<filling::controller_chart> : scan_drive<filling::io> {
    static void perturb(filling::io const& d, std::uint32_t r) { write_one(r, d.estop, d.bottle, d.full, d.reset); }
};
template <>
struct drive<pcell::feed_belt_chart> : scan_drive<pcell::feed_belt_ctl> {
    static void perturb(context const& d, std::uint32_t r) { write_one(r, d.on, d.sensor, d.table_ready); }
};
template <>
struct drive<pcell::table_chart> : scan_drive<pcell::table_ctl> {
    static void perturb(context const& d, std::uint32_t r) { write_one(r, d.on, d.height, d.angle, d.fed, d.taken); }
};
template <>
struct drive<pcell::robot_chart> : scan_drive<pcell::robot_ctl> {
    static void perturb(context const& d, std::uint32_t r) {
        write_one(r, d.on, d.angle, d.ext1, d.ext2, d.table_ready, d.press_load_ready, d.press_unload_ready,
                  d.belt_ready);
    }
};
template <>
struct drive<pcell::press_chart> : scan_drive<pcell::press_ctl> {
    static void perturb(context const& d, std::uint32_t r) {
        write_one(r, d.on, d.level, d.loaded, d.unloaded, d.arm1_ext, d.arm2_ext);
    }
};
template <>
struct drive<pcell::deposit_belt_chart> : scan_drive<pcell::deposit_belt_ctl> {
    static void perturb(context const& d, std::uint32_t r) { write_one(r, d.on, d.dropped); }
};
template <>
struct drive<elevator::flawed> {
    using policy = elevator::policy;
    using context = elevator::data;
    static context initial() { return {}; }
    static void perturb(context const&, std::uint32_t) {}
};
template <>
struct drive<elevator::fixed> : drive<elevator::flawed> {};
template <>
struct drive<elevator::deferring> : drive<elevator::flawed> {};

// The ECA cell's Main holds the other modules (machines) and the environment.
template <class Module>
bool same_module(Module const& a, Module const& b) {
    return a.active_configuration() == b.active_configuration() && a.halted() == b.halted();
}
inline bool same_environment(eca::environment const& a, eca::environment const& b) {
    auto const same_list = [](eca::output_list const& x, eca::output_list const& y) {
        return x.size == y.size && x.names == y.names;
    };
    return a.light == b.light && a.jobs == b.jobs && same_list(a.sent.get(), b.sent.get()) &&
           same_list(a.sent.pending(), b.sent.pending());
}

// Equal contexts: the fixtures of differential_examples.hpp where they compare, the modules and
// the environment of the ECA cell, else the bytes (every other example's context is trivially
// copyable and built without a constructor, so that both machines' copies agree byte for byte).
template <class Context>
bool same_context(Context const& a, Context const& b) {
    if constexpr (std::is_same_v<Context, eca::main_connections>) {
        return same_module(a.button, b.button) && same_module(a.robot, b.robot) && same_environment(a.env, b.env);
    } else if constexpr (std::is_same_v<Context, eca::extended_connections>) {
        return same_module(a.button, b.button) && same_module(a.robot, b.robot) && same_module(a.pause, b.pause) &&
               same_environment(a.env, b.env);
    } else if constexpr (std::is_same_v<Context, mcs::panel>) {
        return bsc_diff::mcs_fixture::same(a, b);
    } else if constexpr (std::is_same_v<Context, cell::data>) {
        return bsc_diff::cell_fixture::same(a, b);
    } else {
        static_assert(std::is_trivially_copyable_v<Context>, "give the round trip a comparison of this context");
        return std::memcmp(&a, &b, sizeof(Context)) == 0;
    }
}

// The trace without the rows' positions, which differ: the document groups the rows by state.
std::vector<bsc_diff::record> without_rows(std::vector<bsc_diff::record> const& trace) {
    std::vector<bsc_diff::record> out;
    for (auto const& r : trace)
        if (r.what != '#') out.push_back(r);
    return out;
}

template <auto const& Original, auto const& RoundTrip>
class round_trip_twin {
public:
    using drive_type = drive<Original>;
    using policy = typename drive_type::policy;
    using original_type = bsc::machine<bsc::chart_ref<Original>, policy, bsc_diff::recorder>;
    using round_trip_type = bsc::machine<bsc::chart_ref<RoundTrip>, policy, bsc_diff::recorder>;
    using events = inside::sendable_events<typename original_type::event_types>;
    using tags = typename inside::model<std::remove_cvref_t<decltype(Original)>>::tags;
    static_assert(
        std::is_same_v<typename original_type::configuration_type, typename round_trip_type::configuration_type>);

    std::string start() {
        // (new: a chart_ref machine is built from the chart itself, which emplace would forward.)
        original_.reset(new original_type{Original, drive_type::initial(), bsc_diff::recorder{&original_trace_}});
        round_trip_.reset(
            new round_trip_type{RoundTrip, drive_type::initial(), bsc_diff::recorder{&round_trip_trace_}});
        now_ = {};
        return compare("construction", original_->last_outcome(), round_trip_->last_outcome());
    }

    // One step: an event of the chart, a write of the environment, or an execution cycle.
    std::string step(std::uint32_t choice, std::uint32_t arg) {
        if (original_->halted() && round_trip_->halted()) return start();
        std::uint32_t const kinds = static_cast<std::uint32_t>(events::size) + 1;
        std::uint32_t const k = choice % (2 * kinds);
        if (k < events::size) return dispatch_at(k, static_cast<int>(arg % 4));
        if (k == events::size) {
            drive_type::perturb(inside::context(*original_), arg);
            drive_type::perturb(inside::context(*round_trip_), arg);
            return compare("environment write", original_->last_outcome(), round_trip_->last_outcome());
        }
        auto const [t, backwards] = bsc_diff::next_time(now_, arg);
        if (!backwards) now_ = t;
        auto const a = original_->step(t);
        auto const b = round_trip_->step(t);
        return compare("step", a.status, b.status,
                       a.transitions != b.transitions ? std::string(" transitions") : std::string());
    }

private:
    template <std::size_t I = 0>
    std::string dispatch_at(std::uint32_t choice, int n) {
        if constexpr (I < events::size) {
            if (choice != I) return dispatch_at<I + 1>(choice, n);
            using E = inside::at<I, events>;
            E e{};
            if constexpr (requires { e.floor; }) e.floor = n % 2;
            auto const a = original_->dispatch(e);
            auto const b = round_trip_->dispatch(e);
            return compare(bsc::name_of<E>, a, b);
        } else {
            return "no such event";
        }
    }

    template <class... Tags>
    bool same_is(inside::type_list<Tags...>) const {
        return ((original_->template is<Tags>() == round_trip_->template is<Tags>()) && ...);
    }

    std::string compare(std::string_view what, bsc::outcome a, bsc::outcome b, std::string differences = {}) {
        if (a != b) differences += " outcome";
        if (original_->active_states() != round_trip_->active_states()) differences += " active_states";
        if (!(original_->active_configuration() == round_trip_->active_configuration()))
            differences += " configuration";
        if (!same_is(tags{})) differences += " is<S>";
        if (original_->halted() != round_trip_->halted()) differences += " halted";
        if (original_->now() != round_trip_->now()) differences += " now";
        if (!same_context(original_->context(), round_trip_->context())) differences += " context";
        if (without_rows(original_trace_) != without_rows(round_trip_trace_)) differences += " trace";
        std::string report;
        if (!differences.empty())
            report = "after " + std::string(what) + ", differ:" + differences + "\n  original:   [" +
                     original_->active_states().joined() + "] " + bsc_diff::text(original_trace_) +
                     "\n  round trip: [" + round_trip_->active_states().joined() + "] " +
                     bsc_diff::text(round_trip_trace_);
        original_trace_.clear();
        round_trip_trace_.clear();
        return report;
    }

    std::vector<bsc_diff::record> original_trace_;
    std::vector<bsc_diff::record> round_trip_trace_;
    std::unique_ptr<original_type> original_;
    std::unique_ptr<round_trip_type> round_trip_;
    bsc::duration now_{};
};

template <auto const& Original, auto const& RoundTrip>
void check_round_trip(char const* name) {
    round_trip_twin<Original, RoundTrip> twin;
    std::mt19937 random(20261127);
    std::string difference = twin.start();
    for (int i = 0; i < 20000 && difference.empty(); ++i) difference = twin.step(random(), random());
    INFO(std::string(name));
    CHECK_MESSAGE(difference.empty(), difference);
}

}  // namespace

#define BSC_ROUND_TRIP_CASE(name, original, round_trip)                                           \
    TEST_CASE("round trip: " #name " exported as SCXML and compiled back runs as the original") { \
        check_round_trip<original, round_trip>(#name);                                            \
    }
BSC_ROUND_TRIP_CHARTS(BSC_ROUND_TRIP_CASE)
