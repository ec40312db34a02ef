#pragma once
// bsc::observers - several observers as one, single-header distribution (needs bsc.hpp beside it).
// Generated from include/bsc/observers.hpp by `python3 scripts/amalgamate.py`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
// begin include/bsc/observers.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_OBSERVERS_HPP
#define BSC_SINGLE_INCLUDE_BSC_OBSERVERS_HPP
// bsc::observers: one observer made of several, each hook passed to every part that has it, in
// order; so that a machine can be logged and traced at once:
//
//   bsc::machine m{chart, ctx{}, bsc::observers{bsc::logger{std::clog}, bsc::tracer{chart, buffer}}};
//   m.observer().get<1>().sample(m);
//
// A hook none of the parts has is absent, so it costs nothing, as for any observer.

#include <cstddef>
#include <string_view>
#include <tuple>
#include <utility>


namespace bsc {

/// An observer that forwards each hook (observer.hpp) to each of Parts that has it.
template <class... Parts>
class observers {
public:
    observers() = default;
    explicit observers(Parts... parts) : parts_(std::move(parts)...) {}

    /// The part at position I.
    template <std::size_t I>
    auto& get() {
        return std::get<I>(parts_);
    }
    template <std::size_t I>
    auto const& get() const {
        return std::get<I>(parts_);
    }

    template <class State>
        requires(detail::observes_entry<Parts, State> || ...)
    void on_entry(State s) {
        each([&]<class P>(P& p) {
            if constexpr (detail::observes_entry<P, State>) p.on_entry(s);
        });
    }
    template <class State>
        requires(detail::observes_exit<Parts, State> || ...)
    void on_exit(State s) {
        each([&]<class P>(P& p) {
            if constexpr (detail::observes_exit<P, State>) p.on_exit(s);
        });
    }
    template <class Source, class Target, class E>
        requires(detail::observes_transition<Parts, Source, Target, E> || ...)
    void on_transition(Source s, Target t, E const& e) {
        each([&]<class P>(P& p) {
            if constexpr (detail::observes_transition<P, Source, Target, E>) p.on_transition(s, t, e);
        });
    }
    void on_row(int row) requires(detail::observes_rows<Parts> || ...) {
        each([&]<class P>(P& p) {
            if constexpr (detail::observes_rows<P>) p.on_row(row);
        });
    }
    void on_guard(std::string_view guard) requires(detail::observes_guards<Parts> || ...) {
        each([&]<class P>(P& p) {
            if constexpr (detail::observes_guards<P>) p.on_guard(guard);
        });
    }
    template <class Source, class E>
        requires(detail::observes_deferrals<Parts, Source, E> || ...)
    void on_defer(Source s, E const& e) {
        each([&]<class P>(P& p) {
            if constexpr (detail::observes_deferrals<P, Source, E>) p.on_defer(s, e);
        });
    }
    template <class E>
        requires(detail::observes_dispatch<Parts, E> || ...)
    void on_dispatch(E const& e) {
        each([&]<class P>(P& p) {
            if constexpr (detail::observes_dispatch<P, E>) p.on_dispatch(e);
        });
    }
    void on_cycle(duration now) requires(detail::observes_cycles<Parts> || ...) {
        each([&]<class P>(P& p) {
            if constexpr (detail::observes_cycles<P>) p.on_cycle(now);
        });
    }
    void on_cycle_end() requires(detail::observes_cycle_ends<Parts> || ...) {
        each([&]<class P>(P& p) {
            if constexpr (detail::observes_cycle_ends<P>) p.on_cycle_end();
        });
    }

private:
    template <class F>
    void each(F&& f) {
        std::apply([&](Parts&... p) { (f(p), ...); }, parts_);
    }

    std::tuple<Parts...> parts_;
};

template <class... Parts>
observers(Parts...) -> observers<Parts...>;

}  // namespace bsc
#endif  // BSC_SINGLE_INCLUDE_BSC_OBSERVERS_HPP
// end include/bsc/observers.hpp
