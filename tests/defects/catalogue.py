#!/usr/bin/env python3
"""The catalogue of defects: every defect that bsc's static checks reject, once.

Each entry is a check: its name (the `bsc::error::` template that reports it, or for a defect
found by constant evaluation, a name of our own), the start of the message it must print (a
regex), and, for the checks of `make_chart`, the defect in the 200-state chart of
tests/error_size (the rows and states that make it, and its fix). Three kinds of test read it:

  tests/error_size/big_chart_error.py   the 200-state chart, with each defect, and with every
                                        defect fixed (the twin that must compile)
  tests/compile_fail/<name>.fail.cpp    `// EXPECT: defect=TYPE` on the first line
  docs/*.md, README.md                  `<!-- sample: fails defect=TYPE -->` before a block
                                        (tests/doc_samples/doc_samples.py)

so that a message, or a check's name, changes here only. The old forms, `// EXPECT: REGEX` and
`fails REGEX`, still take a regex of their own, for the diagnostics that are no check's message
(a note that points at a row, say).

A defect is written TYPE: the error type as the compiler prints it, a regex, without the
`bsc::error::` of bsc's error templates (those of this catalogue and at_row, in_row,
member_number, target_states, as_written), e.g. `dead_end_state<cf::Stuck>`,
`at_row<2, conflicting_transitions<cf::Idle, cf::go>`, or the check's name alone,
`dead_end_state` (any culprit). The diagnostic must contain the type and the check's message,
in either order: `(bsc::error::dead_end_state<cf::Stuck>.*MESSAGE|MESSAGE.*bsc::error::...)`, a
regex that CMake's PASS_REGULAR_EXPRESSION reads as Python's re.S does. A check found by
constant evaluation has no type: its TYPE is its name, and the diagnostic must name the function
that the failed evaluation calls.

    catalogue.py regex TYPE              the regex for TYPE
    catalogue.py expect OUT FILE...      OUT: set(bsc_expect_<name> [==[regex]==]) for each
                                         tests/compile_fail/<name>.fail.cpp (tests/CMakeLists.txt)
    catalogue.py big-chart               the defects of the 200-state chart, as a CMake list
                                         (tests/error_size.cmake)
    catalogue.py check ROOT              every check of ROOT/include/bsc/error.hpp is here with
                                         its message, every value check's function exists, and
                                         every defect has a test: a 200-state chart, or a
                                         compile-fail pair whose EXPECT names it (ctest
                                         defects.catalogue)
"""

import re
import sys
from dataclasses import dataclass
from pathlib import Path

# ---- the 200-state chart's part ------------------------------------------------------------------
#
# The chart of tests/error_size/big_chart_error.py: a root with the composites C0..C19, of 9 basic
# states each (S<i>_0..S<i>_8, S<i>_0 initial), a ring of rows inside each composite
# (S<i>_j + e<j> = S<i>_<j+1 mod 9>) and one from each composite to the next (C<i> + e9 =
# C<i+1 mod 20>); the context is `ctx`, the namespace `big`. Every defect adds items to it: rows,
# children of a composite (its number, or "top" for the root), a composite's initial marker,
# declarations. An item is in the chart with the defect and in the chart without it ("both"),
# in the first only ("defect") or in the second only ("fix"). The chart of a test holds every
# defect's items: its own defects' "defect" items and every other defect's "fix" items. So the
# chart with every defect fixed, compiled once (ctest error_size.defect_free), is the twin of
# every failing chart: each differs from it by its defect only. No two defects may touch the
# same state's rows on the same event, nor the same composite's initial marker, unless they are
# never tested together.


@dataclass(frozen=True)
class Item:
    kind: str            # "row", "child", "initial" (replaces the marker; "" removes it), "decl"
    text: str            # C++ text
    parent: object = None  # for "child" and "initial": the composite's number, or "top"
    only: str = "both"   # "both", "defect" or "fix"


def row(text, only="both"):
    return Item("row", text, None, only)


def child(parent, text, only="both"):
    return Item("child", text, parent, only)


def initial(parent, text, only="both"):
    return Item("initial", text, parent, only)


def decl(text, only="both"):
    return Item("decl", text, None, only)


GUARD = "[([](ctx const&) { return true; })]"


@dataclass(frozen=True)
class BigChart:
    error: str           # the error's TYPE in the chart (without at_row: the test adds the row's position)
    culprits: tuple      # names (regexes) of namespace big, named before the first error line
    row: str = None      # the reported row as bsc writes it, for a check that names its row
    items: tuple = ()


@dataclass(frozen=True)
class Defect:
    message: str         # a regex: the start of bsc's message, or the function a value check calls
    value: bool = False  # found by constant evaluation: no bsc::error type
    big_chart: BigChart = None


def s(name):
    return f"bsc::state<{name}>"


def ev(name):
    return f"bsc::event<{name}>"


DEFECTS = {
    # ---- make_chart (and composite/parallel), in the 200-state chart ----
    "unreachable_state": Defect(
        r"bsc: unreachable state",
        big_chart=BigChart("unreachable_state<big::Orphan>", ("Orphan",), items=(
            decl("struct Orphan;"),
            child(5, s("Orphan")),
            row(f"{s('Orphan')} + {ev('e1')} = {s('S5_0')}"),
            row(f"{s('S5_4')} + {ev('e6')} = {s('Orphan')}", "fix"),  # the way in
        ))),
    "dead_end_state": Defect(
        r"bsc: dead end",
        big_chart=BigChart("dead_end_state<big::Stuck>", ("Stuck",), items=(
            decl("struct Stuck;"),
            child("top", s("Stuck"), "defect"),
            child("top", "bsc::final_state<Stuck>", "fix"),  # an intended end
            row(f"{s('S5_3')} + {ev('e5')} = {s('Stuck')}"),
        ))),
    "conflicting_transitions": Defect(
        r"bsc: conflicting transitions",
        big_chart=BigChart("conflicting_transitions<big::S7_2, big::e4>", ("S7_2", "e4"), "S7_2 + e4 = S7_6", items=(
            row(f"{s('S7_2')} + {ev('e4')} = {s('S7_5')}", "defect"),
            row(f"{s('S7_2')} + {ev('e4')} {GUARD} = {s('S7_5')}", "fix"),  # the first one guarded
            row(f"{s('S7_2')} + {ev('e4')} = {s('S7_6')}"),
        ))),
    "shadowed_transition": Defect(
        r"bsc: shadowed transition",
        big_chart=BigChart("shadowed_transition<big::S10_6, big::e3, big::S10_1>", ("S10_6", "e3", "S10_1"),
                           "S10_6 + e3 [guard] = S10_1", items=(
            row(f"{s('S10_6')} + {ev('e3')} {GUARD} = {s('S10_1')}", "fix"),  # the guarded row first
            row(f"{s('S10_6')} + {ev('e3')} = {s('S10_0')}"),
            row(f"{s('S10_6')} + {ev('e3')} {GUARD} = {s('S10_1')}", "defect"),
        ))),
    "transition_between_orthogonal_regions": Defect(
        r"bsc: transition between orthogonal regions",
        big_chart=BigChart("transition_between_orthogonal_regions<big::A, big::B>", ("A", "B"), "A + e1 = B", items=(
            decl("struct Par; struct R1; struct R2; struct A; struct B;"),
            child("top", "bsc::parallel<Par>(bsc::composite<R1>(bsc::initial<A>), bsc::composite<R2>(bsc::initial<B>))"),
            row(f"{s('S3_4')} + {ev('e8')} = {s('Par')}"),
            row(f"{s('A')} + {ev('e1')} = {s('B')}", "defect"),
            row(f"{s('A')} + {ev('e1')} = {s('S3_0')}", "fix"),  # leave Par
            row(f"{s('B')} + {ev('e2')} = {s('S3_0')}"),
        ))),
    "state_not_in_chart": Defect(
        r"bsc: a row names a state that the state tree does not declare",
        big_chart=BigChart("state_not_in_chart<big::Ghost>", ("Ghost",), "S11_1 + e8 = Ghost", items=(
            decl("struct Ghost;"),
            row(f"{s('S11_1')} + {ev('e8')} = {s('Ghost')}", "defect"),
            row(f"{s('S11_1')} + {ev('e8')} = {s('S11_5')}", "fix"),
        ))),
    "duplicate_state": Defect(
        r"bsc: this state is declared twice in the state tree",
        big_chart=BigChart("duplicate_state<big::S3_3>", ("S3_3",), items=(
            child(4, s("S3_3"), "defect"),
        ))),
    "missing_initial_state": Defect(
        r"bsc: this composite state has no initial child",
        big_chart=BigChart("missing_initial_state<big::C7>", ("C7",), items=(
            initial(7, "", "defect"),
        ))),
    "multiple_initial_states": Defect(
        r"bsc: this composite state has more than one bsc::initial marker",
        big_chart=BigChart("multiple_initial_states<big::C7>", ("C7",), items=(
            initial(7, "bsc::initial<S7_0>, bsc::initial<S7_1>", "defect"),
        ))),
    "initial_not_a_child": Defect(
        r"bsc: the initial state named by this composite is declared elsewhere",
        big_chart=BigChart("initial_not_a_child<big::C7, big::S8_0>", ("C7", "S8_0"), items=(
            initial(7, "bsc::initial<S8_0>", "defect"),
        ))),
    "eventless_livelock": Defect(
        r"bsc: eventless livelock",
        big_chart=BigChart("eventless_livelock<big::S9_1>", ("S9_1",), items=(
            row(f"{s('S9_1')} = {s('S9_2')}"),
            row(f"{s('S9_2')} = {s('S9_1')}", "defect"),
            row(f"{s('S9_2')} + {ev('e5')} = {s('S9_1')}", "fix"),  # S9_2 waits for an event
        ))),
    "not_a_row": Defect(
        r"bsc: after the state tree, every argument of make_chart must be a row",
        big_chart=BigChart("not_a_row<bsc::detail::state_ref<big::S2_2> ?>", ("S2_2",), items=(
            row(s("S2_2"), "defect"),
            row(f"{s('S2_2')} + {ev('e5')} = {s('S2_7')}", "fix"),
        ))),
    "guard_signature_not_supported": Defect(
        r"bsc: a guard must be callable as",
        big_chart=BigChart("in_row<big::S6_6, big::e0, big::S6_1, guard_signature_not_supported<big::bad_guard> ?>",
                           ("bad_guard",), "S6_6 + e0 [guard] = S6_1", items=(
            decl("struct unrelated {};"),
            decl("struct bad_guard { bool operator()(unrelated const&) const { return true; } };", "defect"),
            decl("struct bad_guard { bool operator()(ctx const&) const { return true; } };", "fix"),
            row(f"{s('S6_6')} + {ev('e0')} [bad_guard{{}}] = {s('S6_1')}"),
        ))),
    "guard_is_a_bool_value": Defect(
        r"bsc: this row's guard is a bool value",
        big_chart=BigChart("in_row<big::S6_7, big::e0, big::S6_2, guard_is_a_bool_value<bool> ?>", (),
                           "S6_7 + e0 [guard] = S6_2", items=(
            decl("inline constexpr auto plain = [](ctx const&) { return true; };"),
            row(f"{s('S6_7')} + {ev('e0')} [(!plain)] = {s('S6_2')}", "defect"),
            row(f"{s('S6_7')} + {ev('e0')} [(!bsc::guard(plain))] = {s('S6_2')}", "fix"),
        ))),
    "action_signature_not_supported": Defect(
        r"bsc: an action must be callable as",
        big_chart=BigChart("in_row<big::S6_6, bsc::detail::exit_keyword, bsc::detail::no_target, "
                           "action_signature_not_supported<big::bad_action> ?>",
                           ("bad_action",), "S6_6 + on_exit / action", items=(
            decl("struct bad_action { void operator()(int&) const {} };", "defect"),
            decl("struct bad_action { void operator()(ctx&) const {} };", "fix"),
            row(f"{s('S6_6')} + bsc::on_exit / bad_action{{}}"),
        ))),
    "dead_transition": Defect(
        r"bsc: dead transition",
        # Every child of C12 takes e9 first, so C12's row on e9 (to C13) never fires; in the
        # fix, S12_0's row is guarded, and e9 reaches C12 while S12_0 is active.
        big_chart=BigChart("dead_transition<big::C12, big::e9, big::C13>", ("C12", "e9", "C13"), "C12 + e9 = C13", items=(
            row(f"{s('S12_0')} + {ev('e9')} = {s('S12_2')}", "defect"),
            row(f"{s('S12_0')} + {ev('e9')} {GUARD} = {s('S12_2')}", "fix"),
            *(row(f"{s(f'S12_{j}')} + {ev('e9')} = {s('C13' if j == 1 else f'S12_{(j + 2) % 9}')}")
              for j in range(1, 9)),  # C13 stays reachable
        ))),
    "dead_transition_behind_outer": Defect(r"bsc: dead transition under parent-first priority"),
    "empty_parallel_state": Defect(
        r"bsc: this parallel state has no regions",
        big_chart=BigChart("empty_parallel_state<big::Empty>", ("Empty",), items=(
            decl("struct Empty; struct ER; struct EA;"),
            child("top", "bsc::parallel<Empty>()", "defect"),
            child("top", "bsc::parallel<Empty>(bsc::composite<ER>(bsc::initial<EA>))", "fix"),  # a region
            row(f"{s('S13_5')} + {ev('e1')} = {s('Empty')}"),
            row(f"{s('Empty')} + {ev('e1')} = {s('S13_0')}"),
        ))),
    "dead_timeout": Defect(
        r"bsc_dead_transition_timeout_behind_a_shorter_unguarded_timeout", value=True,
        # S4_4's 2 s timeout never fires: the unguarded 1 s one leaves S4_4 first; in the fix,
        # the 1 s one is internal (it re-arms, S4_4 stays active).
        big_chart=BigChart("dead_timeout", (), items=(
            row(f"{s('S4_4')} + bsc::after(std::chrono::seconds(1)) = {s('S4_0')}", "defect"),
            row(f"{s('S4_4')} + bsc::after(std::chrono::seconds(1)) / [](ctx&) {{}}", "fix"),
            row(f"{s('S4_4')} + bsc::after(std::chrono::seconds(2)) = {s('S4_1')}"),
        ))),
    "local_target_outside_source": Defect(
        r"bsc: local transition to a state outside its source",
        big_chart=BigChart("local_target_outside_source<big::C3, big::S4_0>", ("C3", "S4_0"),
                           "C3 + e8 = local(S4_0)", items=(
            row(f"{s('C3')} + {ev('e8')} = bsc::local({s('S4_0')})", "defect"),
            row(f"{s('C3')} + {ev('e8')} = bsc::local({s('S3_5')})", "fix"),  # below C3
        ))),
    "event_in_two_families": Defect(
        r"bsc: event in two families",
        big_chart=BigChart("event_in_two_families<big::fab>", ("fab",), items=(
            decl("struct fa {}; struct fb {}; struct fab : fa, fb {};", "defect"),
            decl("struct fa {}; struct fb : fa {}; struct fab : fb {};", "fix"),  # one chain: fab, fb, fa
            row(f"{s('S2_3')} + {ev('fab')} = {s('S2_4')}"),
            row(f"{s('S2_3')} + {ev('fb')} = {s('S2_6')}"),
            row(f"{s('S2_3')} + {ev('fa')} = {s('S2_5')}"),
        ))),
    "initial_action_without_initial_transition": Defect(
        r"bsc: initial action of a state without an initial transition",
        big_chart=BigChart("initial_action_without_initial_transition<big::S8_8>", ("S8_8",),
                           "S8_8 + on_initial / action", items=(
            row(f"{s('S8_8')} + bsc::on_initial / [](ctx&) {{}}", "defect"),
            row(f"{s('C8')} + bsc::on_initial / [](ctx&) {{}}", "fix"),  # a composite's
        ))),
    "invalid_history_state": Defect(
        r"bsc: invalid history state",
        big_chart=BigChart("invalid_history_state<big::H>", ("H",), items=(
            decl("struct H;"),
            child(6, "bsc::shallow_history_state<H, S7_0>", "defect"),  # the default outside C6
            child(6, "bsc::shallow_history_state<H, S6_2>", "fix"),
            row(f"{s('S15_5')} + {ev('e1')} = {s('H')}"),
        ))),
    "targets_not_orthogonal": Defect(
        r"bsc: targets not orthogonal",
        big_chart=BigChart("targets_not_orthogonal<big::S16_4, target_states<big::TA1, big::TA2> ?>",
                           ("S16_4", "TA1", "TA2"), "S16_4 + e8 = targets(TA1, TA2)", items=(
            decl("struct Tp; struct TR1; struct TR2; struct TA1; struct TA2; struct TB1; struct TB2;"),
            child("top", "bsc::parallel<Tp>(bsc::composite<TR1>(bsc::initial<TA1>, bsc::state<TA2>), "
                         "bsc::composite<TR2>(bsc::initial<TB1>, bsc::state<TB2>))"),
            row(f"{s('S16_4')} + {ev('e8')} = bsc::targets({s('TA1')}, {s('TA2')})", "defect"),  # both in TR1
            row(f"{s('S16_4')} + {ev('e8')} = bsc::targets({s('TA2')}, {s('TB2')})", "fix"),  # one per region
            row(f"{s('TA1')} + {ev('e1')} = {s('TA2')}"),
            row(f"{s('TB1')} + {ev('e1')} = {s('TB2')}"),
            row(f"{s('Tp')} + {ev('e2')} = {s('S16_0')}"),
        ))),
    "initial_states_not_orthogonal": Defect(
        r"bsc: initial states not orthogonal",
        # Q's two initial states are siblings, not states of two regions.
        big_chart=BigChart("initial_states_not_orthogonal<big::Q>", ("Q",), items=(
            decl("struct Q; struct QA; struct QB;"),
            child("top", "bsc::composite<Q>(bsc::initial<QA, QB>, bsc::state<QA>, bsc::state<QB>)", "defect"),
            child("top", "bsc::composite<Q>(bsc::initial<QA>, bsc::state<QA>, bsc::state<QB>)", "fix"),
            row(f"{s('S18_4')} + {ev('e8')} = {s('Q')}"),
            row(f"{s('QA')} + {ev('e1')} = {s('QB')}"),
            row(f"{s('Q')} + {ev('e2')} = {s('S18_0')}"),
        ))),
    "invalid_deferral": Defect(
        r"bsc: invalid deferral",
        big_chart=BigChart("invalid_deferral<big::S5_5, big::e9>", ("S5_5", "e9"), "S5_5 + e9 / defer = S5_0", items=(
            row(f"{s('S5_5')} + {ev('e9')} / bsc::defer = {s('S5_0')}", "defect"),  # a target
            row(f"{s('S5_5')} + {ev('e9')} / bsc::defer", "fix"),
        ))),
    "done_never_raised": Defect(
        r"bsc: a row takes bsc::done<State>, but State never completes",
        # C14 has no final child, so it never completes; in the fix, D14 is final.
        big_chart=BigChart("done_never_raised<big::C14>", ("C14",), "C14 + done<C14> = C15", items=(
            decl("struct D14;"),
            child(14, s("D14"), "defect"),
            child(14, "bsc::final_state<D14>", "fix"),
            row(f"{s('S14_8')} + {ev('e7')} = {s('D14')}"),
            row(f"{s('D14')} + {ev('e1')} = {s('S14_0')}", "defect"),
            row(f"{s('C14')} + {ev('bsc::done<C14>')} = {s('C15')}"),
        ))),
    "done_of_state_not_in_chart": Defect(
        r"bsc: a row takes bsc::done<State>, but State is not a state of this chart",
        big_chart=BigChart("done_of_state_not_in_chart<big::Ghost>", ("Ghost",), "C17 + done<Ghost> = C18", items=(
            decl("struct Ghost; struct F17;"),
            child(17, "bsc::final_state<F17>"),
            row(f"{s('S17_8')} + {ev('e7')} = {s('F17')}"),
            row(f"{s('C17')} + {ev('bsc::done<Ghost>')} = {s('C18')}", "defect"),  # a misspelt C17
            row(f"{s('C17')} + {ev('bsc::done<C17>')} = {s('C18')}", "fix"),
        ))),
    "done_source_inactive": Defect(
        r"bsc: a row on bsc::done<State> leaves Source",
        big_chart=BigChart("done_source_inactive<big::S7_3, big::C7>", ("S7_3", "C7"), "S7_3 + done<C7> = C8", items=(
            decl("struct F7;"),
            child(7, "bsc::final_state<F7>"),
            row(f"{s('S7_8')} + {ev('e7')} = {s('F7')}"),
            row(f"{s('S7_3')} + {ev('bsc::done<C7>')} = {s('C8')}", "defect"),  # S7_3 is inactive then
            row(f"{s('C7')} + {ev('bsc::done<C7>')} = {s('C8')}", "fix"),
        ))),
    # bsc::in<S> in a guard (tests/compile_fail/in_of_*.fail.cpp)
    "in_of_state_not_in_chart": Defect(r"bsc: a row's guard tests bsc::in<State>, but State is not a state"),
    "in_of_history_state": Defect(r"bsc: a row's guard tests bsc::in<State>, but State is a history pseudo-state"),
    "finding_not_allowable": Defect(r"bsc: make_chart's third argument must be bsc::allow<...> of findings a chart may allow"),
    "root_must_be_composite": Defect(r"bsc: the first argument of make_chart is the root of the state tree"),
    "not_a_state_declaration": Defect(r"bsc: an argument of this state's declaration is not a state or marker"),
    "conflicting_history_markers": Defect(r"bsc: this composite state has more than one history marker"),
    # ---- the machine ----
    "queried_state_not_in_chart": Defect(r"bsc: is<State>\(\) asks about a state that the chart's tree does not declare"),
    "unhandled_event": Defect(r"bsc: no transition of this chart is triggered by the dispatched event type"),
    "event_not_dispatchable": Defect(r"bsc: dispatch\(e\) of an event the environment cannot send"),
    "raised_event_not_in_chart": Defect(r"bsc: an action raises an event type that no transition of this chart handles"),
    "not_an_event": Defect(r"bsc: bsc::event<E> needs E to be a complete, copyable"),
    "last_outcome_not_kept": Defect(r"bsc: this machine's policy has keep_last_outcome = false"),
    "clock_not_kept": Defect(r"bsc: this machine keeps no clock"),
    "duplicate_event_name": Defect(r"bsc: two events of this chart have the same name"),
    "not_an_event_of_the_chart": Defect(r"bsc: bsc::event_set<Chart>::number_of<Event>: Event is none of the chart's events"),
    "event_not_constructible": Defect(r"bsc: dispatch_by_name and dispatch_by_number build the event"),
    "pending_events_not_encoded": Defect(r"bsc: a machine of this Chart keeps events from one call to the next"),
    # ---- the context ----
    "context_not_an_aggregate": Defect(r"bsc: the members of this type of the context cannot be found"),
    "too_many_fields": Defect(r"bsc: this struct of the context has more than 128 fields"),
    "context_type_has_base_class": Defect(r"bsc: this struct of the context has a base class"),
    "context_type_has_c_array": Defect(r"bsc: this struct of the context has a C array member"),
    "hana_adapter_not_included": Defect(r"bsc: this Type of the context is adapted with BOOST_HANA_DEFINE_STRUCT"),
    "state_out_of_reach": Defect(r"bsc: member Member of Owner"),
    "member_not_explorable": Defect(r"bsc: the explorer \(bsc::verify\) encodes scalars"),
    "member_not_retainable": Defect(r"bsc: bsc::save and bsc::restore store"),
    # ---- channels and systems ----
    "input_written_by_the_chart": Defect(r"bsc: an action writes an input channel"),
    "output_written_from_outside": Defect(r"bsc: an output channel is written from outside its chart"),
    "not_a_link": Defect(r"bsc: after the actors and the order, every argument of bsc::system must be a"),
    "invalid_link_option": Defect(r"bsc: this Option of a bsc::link is none of"),
    "actor_twice_in_order": Defect(r"bsc: this Actor is named twice in the system's bsc::order"),
    "actor_not_in_order": Defect(r"bsc: a bsc::link or bsc::from_outside of the system names this Actor"),
    "link_source_not_an_output": Defect(r"bsc: the source of a bsc::link must be an output of its actor"),
    "link_target_not_an_input": Defect(r"bsc: the target of a bsc::link must be an input of its actor"),
    "link_value_types_differ": Defect(r"bsc: this bsc::link carries a From into a channel of To"),
    "link_conversion_not_applicable": Defect(r"bsc: the bsc::convert<F> of a link cannot convert its value"),
    "input_driven_twice": Defect(r"bsc: two links of the system drive this input"),
    "input_not_driven": Defect(r"bsc: no link of the system drives this input of Actor"),
    "from_outside_not_an_input": Defect(r"bsc: bsc::from_outside must name an input of its actor"),
    "input_linked_and_from_outside": Defect(r"bsc: this input \(Channel of Actor\) is declared bsc::from_outside, but a link"),
    # ---- found by constant evaluation: the function that the failed evaluation calls ----
    "negative_timeout": Defect(r"bsc_after_negative_delay", value=True),
    "timeout_beyond_duration": Defect(r"bsc_after_delay_beyond_bsc_duration", value=True),
    "cancel_delayed_id_zero": Defect(r"bsc_cancel_delayed_id_zero_names_no_delayed_event", value=True),
    "chart_ref_from_another_chart": Defect(r"bsc_chart_ref_made_from_another_chart", value=True),
}

# Checks known to have no compile-fail test yet, with the reason; `check` fails for any other.
UNTESTED = {}

# The templates of namespace bsc::error that wrap a check's error or name its arguments.
WRAPPERS = ("at_row", "in_row", "as_written", "member_number", "target_states")


class CatalogueError(Exception):
    pass


def qualified(spec):
    """SPEC with bsc::error:: before the names of bsc's error templates that lack it."""
    names = set(DEFECTS) | set(WRAPPERS)
    return re.sub(r"(?<![\w:])(\w+)<", lambda m: ("bsc::error::" if m.group(1) in names else "") + m.group(0), spec)


def kind_of(spec):
    """The check that SPEC names."""
    spec = spec.strip()
    if re.fullmatch(r"\w+", spec):
        if spec not in DEFECTS:
            raise CatalogueError(f"`{spec}` is not a defect of tests/defects/catalogue.py")
        return spec
    kinds = [k for k in re.findall(r"bsc::error::(\w+)<", qualified(spec)) if k not in WRAPPERS]
    unknown = [k for k in kinds if k not in DEFECTS]
    if unknown or len(kinds) != 1:
        raise CatalogueError(f"`{spec}` must name one defect of tests/defects/catalogue.py"
                             + (f" (unknown: {', '.join(unknown)})" if unknown else ""))
    if DEFECTS[kinds[0]].value:
        raise CatalogueError(f"`{kinds[0]}` is found by constant evaluation: it has no type, write its name alone")
    return kinds[0]


def regex(spec):
    """The regex that a build's output must match for the defect SPEC (see the module's doc)."""
    spec = spec.strip()
    defect = DEFECTS[kind_of(spec)]
    if defect.value:
        return defect.message
    error = f"bsc::error::{spec}<" if re.fullmatch(r"\w+", spec) else qualified(spec)
    return f"({error}.*{defect.message}|{defect.message}.*{error})"


def expectation(line, where):
    """The regex of a compile-fail test's first line: `// EXPECT: defect=TYPE` or `// EXPECT: REGEX`."""
    m = re.match(r"// EXPECT: ([^\r\n]+)", line)
    if not m:
        raise CatalogueError(f"{where} must start with `// EXPECT: defect=TYPE` or `// EXPECT: REGEX`")
    expect = m.group(1).strip()
    if expect.startswith("defect="):
        try:
            return regex(expect[len("defect="):])
        except CatalogueError as e:
            raise CatalogueError(f"{where}: {e}") from None
    return expect


def big_chart_kinds():
    return [k for k, d in DEFECTS.items() if d.big_chart]


# ---- the command line ----------------------------------------------------------------------------

def write_expectations(out, files):
    lines = ["# Generated by tests/defects/catalogue.py from the first lines of tests/compile_fail/*.fail.cpp."]
    for f in files:
        path = Path(f)
        name = path.name[: -len(".fail.cpp")]
        with open(path) as text:
            expect = expectation(text.readline(), f"tests/compile_fail/{path.name}")
        if "]==]" in expect:
            raise CatalogueError(f"tests/compile_fail/{path.name}: the regex may not contain `]==]`")
        lines.append(f"set(bsc_expect_{name} [==[{expect}]==])")
    text = "\n".join(lines) + "\n"
    out = Path(out)
    if not out.exists() or out.read_text() != text:
        out.write_text(text)


def header_messages(error_hpp):
    """{check: its message} for the bsc::error templates with a static_assert."""
    text = error_hpp.read_text()
    found = {}
    for m in re.finditer(r"struct (\w+) \{\s*(?:constexpr )?~\w+\(\) \{\s*static_assert\(\s*detail::dependent_false<\w+>,"
                         r"\s*((?:\"(?:[^\"\\]|\\.)*\"\s*)+)\)", text):
        found[m.group(1)] = "".join(re.findall(r"\"((?:[^\"\\]|\\.)*)\"", m.group(2)))
    return found


def check(root):
    root = Path(root)
    problems = []
    messages = header_messages(root / "include" / "bsc" / "error.hpp")
    for kind, message in messages.items():
        if kind not in DEFECTS:
            problems.append(f"bsc::error::{kind} (include/bsc/error.hpp) is not in the catalogue")
        elif not re.match(DEFECTS[kind].message, message):
            problems.append(f"{kind}: the catalogue's message `{DEFECTS[kind].message}` does not start "
                            f"bsc's, `{message}`")
    headers = "".join(p.read_text() for p in sorted((root / "include").rglob("*.hpp")))
    for kind, defect in DEFECTS.items():
        if defect.value:
            if not re.search(rf"\b{defect.message}\(", headers):
                problems.append(f"{kind}: no function {defect.message} in include/")
        elif kind not in messages:
            problems.append(f"{kind}: no bsc::error::{kind} with a static_assert in include/bsc/error.hpp")

    # Every defect has a test: the 200-state chart, or a compile-fail pair whose EXPECT names it.
    tested = set(big_chart_kinds())
    for fail in sorted((root / "tests" / "compile_fail").glob("*.fail.cpp")):
        where = f"tests/compile_fail/{fail.name}"
        if not (fail.parent / fail.name.replace(".fail.cpp", ".pass.cpp")).exists():
            problems.append(f"{where} has no twin .pass.cpp")
        line = fail.read_text().split("\n", 1)[0]
        try:
            expectation(line, where)
        except CatalogueError as e:
            problems.append(str(e))
            continue
        m = re.match(r"// EXPECT: defect=(.*)", line)
        if m:
            tested.add(kind_of(m.group(1)))
    for kind in DEFECTS:
        if kind not in tested and kind not in UNTESTED:
            problems.append(f"{kind}: no test (a 200-state chart in the catalogue, or a tests/compile_fail "
                            "pair whose first line is `// EXPECT: defect=...` naming it)")
        if kind in tested and kind in UNTESTED:
            problems.append(f"{kind} is tested: take it out of UNTESTED")
    for p in problems:
        print(p, file=sys.stderr)
    if not problems:
        print(f"{len(DEFECTS)} defects, each in include/; {len(tested)} tested, {len(big_chart_kinds())} of them "
              f"on the 200-state chart; untested: " + "; ".join(f"{k} ({why})" for k, why in UNTESTED.items()))
    return 1 if problems else 0


def main(argv):
    try:
        if len(argv) == 2 and argv[0] == "regex":
            print(regex(argv[1]))
            return 0
        if len(argv) >= 2 and argv[0] == "expect":
            write_expectations(argv[1], argv[2:])
            return 0
        if argv == ["big-chart"]:
            print(";".join(big_chart_kinds()))
            return 0
        if len(argv) == 2 and argv[0] == "check":
            return check(argv[1])
    except CatalogueError as e:
        print(f"catalogue.py: {e}", file=sys.stderr)
        return 1
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
