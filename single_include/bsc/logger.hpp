#pragma once
// bsc::logger - records of what a machine does, single-header distribution (needs bsc.hpp beside it).
// Generated from include/bsc/logger.hpp by `python3 scripts/amalgamate.py`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
// begin include/bsc/logger.hpp
// bsc::logger: an observer that reports what a machine does, one record per dispatch, exit,
// transition and entry, with the machine's time, the cycle's number, and the trigger as the
// chart writes it (the event's bsc::event_name, "after(5s)", or "condition"), followed by the
// guard's name in brackets where the guard has one ("go [ready]", "[released]"); an event a row
// defers is reported as a deferral ("defer go in Busy"). Records go to a callback, or as lines
// to a std::ostream:
//
//   bsc::machine<decltype(chart), bsc::scan_policy, bsc::logger> m{chart, ctx{}, bsc::logger{std::clog}};
//   m.step(0s);
//   m.step(2s);   // [2s #2] exit Idle / [2s #2] transition Idle -> Busy on after(1500ms) / [2s #2] entry Busy
//
// Opt-in: <bsc/bsc.hpp> does not include it, and a machine without it pays nothing.

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

// begin include/bsc/detail/delay_label.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_DETAIL_DELAY_LABEL_HPP
#define BSC_SINGLE_INCLUDE_BSC_DETAIL_DELAY_LABEL_HPP
// A duration as short exact text, for the exports' timeout labels and the logger's times.

#include <string>


namespace bsc::detail {

/// "3s", "250ms", "20us" or "7ns": the largest unit that divides the delay.
inline std::string delay_label(std::chrono::nanoseconds d) {
    auto const n = d.count();
    if (n % 1'000'000'000 == 0) return std::to_string(n / 1'000'000'000) + "s";
    if (n % 1'000'000 == 0) return std::to_string(n / 1'000'000) + "ms";
    if (n % 1'000 == 0) return std::to_string(n / 1'000) + "us";
    return std::to_string(n) + "ns";
}

}  // namespace bsc::detail
#endif  // BSC_SINGLE_INCLUDE_BSC_DETAIL_DELAY_LABEL_HPP
// end include/bsc/detail/delay_label.hpp

namespace bsc {

/// One thing a machine did, as bsc::logger reports it. The views are valid during the
/// callback only.
struct log_record {
    enum class kind { dispatch, exit, transition, entry, deferral };
    kind what = kind::dispatch;
    /// The machine's time: the cycle's `now` within step(now), otherwise the time of the last
    /// cycle this logger saw (zero before the first).
    duration time{};
    /// The cycle's number within step(now), counted from 1 by this logger; 0 outside a cycle
    /// (the construction, a dispatch).
    std::uint64_t cycle = 0;
    std::string_view state;    ///< exit, entry: the state; transition, deferral: the source
    std::string_view target;   ///< transition: the target, "internal" for an internal transition
    std::string_view trigger;  ///< transition: the event's name, "after(<delay>)" or "condition",
                               ///< then " [guard]" for a named guard, or "[guard]" alone for an
                               ///< eventless row; dispatch, deferral: the event's name
};

/// The record as one line, without newline: "[1500ms #3] transition Idle -> Busy on go",
/// "[1500ms] dispatch go" (no cycle number outside a cycle), "[2s #4] defer go in Busy".
inline std::string to_string(log_record const& r) {
    std::string line = "[" + detail::delay_label(r.time);
    if (r.cycle > 0) line += " #" + std::to_string(r.cycle);
    line += "] ";
    switch (r.what) {
        case log_record::kind::dispatch: line.append("dispatch ").append(r.trigger); break;
        case log_record::kind::exit: line.append("exit ").append(r.state); break;
        case log_record::kind::transition:
            line.append("transition ").append(r.state).append(" -> ").append(r.target).append(" on ").append(r.trigger);
            break;
        case log_record::kind::entry: line.append("entry ").append(r.state); break;
        case log_record::kind::deferral: line.append("defer ").append(r.trigger).append(" in ").append(r.state); break;
    }
    return line;
}

/// An observer that reports every dispatch, exit, transition and entry of a machine as a
/// bsc::log_record, to a callback or as lines to a stream (which must outlive the machine).
class logger {
public:
    using sink_type = std::function<void(log_record const&)>;

    /// Writes each record as a line (to_string) to `out`.
    explicit logger(std::ostream& out) : sink_([&out](log_record const& r) { out << to_string(r) << '\n'; }) {}
    /// Calls `sink` with each record.
    explicit logger(sink_type sink) : sink_(std::move(sink)) {}

    /// The number of cycles seen, which numbers the next one.
    std::uint64_t cycles() const { return cycles_; }

    // ---- the observer hooks (observer.hpp) ------------------------------------------------
    template <class E>
    void on_dispatch(E const&) {
        in_cycle_ = false;
        emit({log_record::kind::dispatch, time_, 0, {}, {}, event_name<E>});
    }
    void on_cycle(duration now) {
        ++cycles_;
        time_ = now;
        in_cycle_ = true;
    }
    void on_cycle_end() { in_cycle_ = false; }

    template <class State>
    void on_exit(State) {
        emit({log_record::kind::exit, time_, cycle(), State::name, {}, {}});
    }
    template <class State>
    void on_entry(State) {
        emit({log_record::kind::entry, time_, cycle(), State::name, {}, {}});
    }
    // Before on_transition of a guarded row: the guard as the exports write it ("guard" when no
    // part of it has a name, which the record leaves out).
    void on_guard(std::string_view guard) {
        guard_.assign(guard);
        guarded_ = guard != "guard";
    }
    // Before on_transition of a deferring row: that transition is reported as the deferral.
    template <class Source, class E>
    void on_defer(Source, E const&) {
        deferring_ = true;
    }
    template <class Source, class Target, class E>
    void on_transition(Source, Target, E const& e) {
        bool const guarded = std::exchange(guarded_, false);
        if (std::exchange(deferring_, false)) {
            emit({log_record::kind::deferral, time_, cycle(), Source::name, {}, event_name<E>});
            return;
        }
        if constexpr (std::is_same_v<E, timeout_elapsed>) {
            trigger_ = "after(" + detail::delay_label(e.delay) + ")";
        } else if constexpr (std::is_same_v<E, eventless>) {
            trigger_ = guarded ? std::string{} : std::string{"condition"};
        } else {
            trigger_.assign(event_name<E>);
        }
        if (guarded) trigger_.append(trigger_.empty() ? "[" : " [").append(guard_).append("]");
        emit({log_record::kind::transition, time_, cycle(), Source::name, Target::name, trigger_});
    }

private:
    std::uint64_t cycle() const { return in_cycle_ ? cycles_ : 0; }
    void emit(log_record const& r) {
        if (sink_) sink_(r);
    }

    sink_type sink_;
    duration time_{};  // the last cycle's time: a dispatch's too
    std::uint64_t cycles_ = 0;
    bool in_cycle_ = false;
    std::string trigger_;     // the text of the last transition's trigger, which a record views
    std::string guard_;       // the guard of the transition about to be reported
    bool guarded_ = false;    // it has a name to report
    bool deferring_ = false;  // the transition about to be reported defers its event
};

}  // namespace bsc
// end include/bsc/logger.hpp
