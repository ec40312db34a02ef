#pragma once
// A chart that uses every construct beyond the core formalism (docs/semantics.md, "Beyond the
// core"): a local transition, an event family, bsc::any_event, done events of a composite and
// of a parallel state, a final child of the root, an initial transition with an action and a
// deep target, a history state with a default action, several targets, a deferring row and a
// delayed event. export_diagrams --all writes it in every
// format, so that the exports.* tests check what the exporters make of these constructs.

#include <bsc/bsc.hpp>
#include <chrono>

namespace beyond_core {
struct error {
    static constexpr std::string_view name = "error";
};
struct error_send : error {
    static constexpr std::string_view name = "error.send";
};
struct start {};
struct next {};
struct restart {};
struct quit {};
struct Controller;
struct Idle;
struct Job;
struct Load;
struct Run;
struct Unloaded;
struct Check;
struct Left;
struct Right;
struct LeftOk;
struct RightOk;
struct LeftBusy;
struct RightBusy;
struct Fault;
struct Off;
struct Resume;
struct Setup;
struct Mount;
struct Align;
struct back {};
struct both {};
struct data {
    int jobs = 0;
};

inline constexpr auto chart = bsc::make_chart<data>(
    bsc::composite<Controller>(
        bsc::initial<Idle>, bsc::state<Idle>,
        bsc::composite<Job>(bsc::initial<Align>, bsc::shallow_history_state<Resume, Run>,
                            bsc::composite<Setup>(bsc::initial<Mount>, bsc::state<Mount>, bsc::state<Align>),
                            bsc::state<Load>, bsc::state<Run>, bsc::final_state<Unloaded>),
        bsc::parallel<Check>(
            bsc::composite<Left>(bsc::initial<LeftBusy>, bsc::state<LeftBusy>, bsc::final_state<LeftOk>),
            bsc::composite<Right>(bsc::initial<RightBusy>, bsc::state<RightBusy>, bsc::final_state<RightOk>)),
        bsc::state<Fault>, bsc::final_state<Off>),
    bsc::state<Idle> + bsc::event<start> = bsc::state<Job>, bsc::state<Idle> + bsc::event<quit> = bsc::state<Off>,
    bsc::state<Idle> + bsc::event<back> = bsc::state<Resume>,
    bsc::state<Job> + bsc::on_initial / [](data& d) { ++d.jobs; },
    bsc::state<Resume> + bsc::on_initial / [](data& d) { ++d.jobs; },
    bsc::state<Align> + bsc::event<next> = bsc::state<Load>, bsc::state<Mount> + bsc::event<next> = bsc::state<Align>,
    bsc::state<Load> + bsc::event<back> = bsc::state<Mount>,
    bsc::state<Idle> + bsc::event<both> = bsc::targets(bsc::state<LeftOk>, bsc::state<RightOk>),
    bsc::state<Run> + bsc::event<start> / bsc::defer,
    bsc::state<Fault> + bsc::on_entry / bsc::raise_after(std::chrono::seconds{5}, quit{}, 1),
    bsc::state<Load> + bsc::event<next> = bsc::state<Run>, bsc::state<Run> + bsc::event<next> = bsc::state<Unloaded>,
    bsc::state<Job> + bsc::event<restart> = bsc::local(bsc::state<Load>),
    bsc::state<Job> + bsc::event<error_send> = bsc::state<Idle>,
    bsc::state<Job> + bsc::event<error> = bsc::state<Fault>,
    bsc::state<Job> + bsc::event<bsc::done<Job>> = bsc::state<Check>,
    bsc::state<LeftBusy> + bsc::event<next> = bsc::state<LeftOk>,
    bsc::state<RightBusy> + bsc::event<next> = bsc::state<RightOk>,
    bsc::state<Check> + bsc::event<bsc::done<Check>> = bsc::state<Idle>,
    bsc::state<Fault> + bsc::event<bsc::any_event> = bsc::state<Idle>);
}  // namespace beyond_core
