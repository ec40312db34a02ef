#pragma once
// Closed models of bsc machines for the explorer:
//  - event_model: a machine to which every listed event is offered in every state;
//  - cycle_model: a machine stepped with a fixed period, its inputs drawn each cycle from
//    a finite set of choices the user declares;
//  - system_model: any aggregate of machines and plant models, stepped by a user function
//    with a finite set of choices per cycle (the closed loops of the [BSC] and [COMDES] papers,
//    docs/references.md).
// Time is made relative: every explored state is decoded with its machines' clocks at the
// same origin, so states that differ only in absolute time are one state.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include <bsc/detail/type_name.hpp>
#include <bsc/event_name.hpp>
#include <bsc/detail/verify/codec.hpp>

namespace bsc::detail {
// The clock every explored state is decoded at; far enough from zero that relative times fit.
inline constexpr duration origin = std::chrono::hours{1};

template <class T>
struct codec {
    static constexpr std::size_t key_size = encoded_size<T>();
    duration period{};
    void encode(T const& s, std::byte* out) const {
        std::memset(out, 0, key_size);
        bit_writer writer{out, encoded_bits<T>()};
        detail::encode(s, writer, time_frame{origin + period, period});
        if (writer.bits() != encoded_bits<T>()) std::abort();  // the size computed from the types is exact
    }
    // The named parts of a key, found by encoding a state of the model.
    std::vector<encoded_field> fields(T const& s) const {
        std::vector<std::byte> scratch(key_size);
        bit_writer writer{scratch.data(), encoded_bits<T>()};
        std::vector<encoded_field> out;
        detail::encode(s, writer, time_frame{origin + period, period}, &out);
        return out;
    }
    T decode(T prototype, std::byte const* in) const {
        bit_reader reader{in, encoded_bits<T>()};
        detail::decode(prototype, reader, time_frame{origin, period});
        if (reader.bits() != encoded_bits<T>()) std::abort();
        return prototype;
    }
};
// What every model of a bsc state keeps and does alike: the initial state, its states encoded
// and decoded by the codec, and the successors of a state, one per alternative the model
// offers (Model's labels() and advance(state, label)).
template <class Model, class State>
class encoded_model {
public:
    using state = State;
    static constexpr std::size_t key_size = codec<State>::key_size;

    template <class Emit>
    void successors(state const& s, Emit&& emit) const {
        auto const& model = static_cast<Model const&>(*this);
        auto const labels = static_cast<std::uint16_t>(model.labels());
        for (std::uint16_t label = 0; label < labels; ++label) {
            state next = s;
            model.advance(next, label);
            emit(label, next);
        }
    }
    state initial() const { return initial_; }
    void encode(state const& s, std::byte* out) const { codec_.encode(s, out); }
    state decode(std::byte const* in) const { return codec_.decode(initial_, in); }
    std::vector<encoded_field> fields() const { return codec_.fields(initial_); }

protected:
    encoded_model(State initial, duration period) : initial_(std::move(initial)), codec_{period} {}
    duration step_period() const { return codec_.period; }

private:
    State initial_;
    codec<State> codec_;
};
}  // namespace bsc::detail

namespace bsc::verify {

/// Offers each of the events Es... to the machine in every state (dispatch).
template <class Machine, class... Es>
class event_model : public detail::encoded_model<event_model<Machine, Es...>, Machine> {
public:
    using state = Machine;

    explicit event_model(Machine initial)
        : detail::encoded_model<event_model, Machine>(std::move(initial), duration{}) {}

    /// The number of alternatives offered in every state: the events.
    static constexpr std::size_t labels() { return sizeof...(Es); }
    /// Takes alternative `label` in place: dispatches the label-th event. `M` is the machine
    /// type or the same chart with another observer (bsc/benchmark.hpp replays with a logger).
    template <class M>
    void advance(M& s, std::uint16_t label) const {
        std::uint16_t k = 0;
        ((k++ == label ? static_cast<void>(s.dispatch(Es{})) : static_cast<void>(0)), ...);
    }
    std::string label(std::uint16_t i) const {
        constexpr std::string_view names[] = {event_name<Es>...};
        return std::string(names[i]);
    }
    std::string describe(state const& s) const { return s.active_states().joined(); }
};

// The label of a cycle_model's choice when the user gives none.
struct numbered_inputs {
    std::string operator()(std::size_t choice) const { return "cycle, inputs #" + std::to_string(choice); }
};

/// Steps the machine with a fixed period; before each cycle, `apply(context, choice)` sets the
/// inputs for one of `choices` alternatives (`context` is the machine's `context()`, const, the
/// environment's view: inputs are set through it), and every alternative is explored.
/// `label(choice)` names an alternative in traces; written as `name=value` words
/// ("P1=1 S1=0"), a trace shows only the words that changed from one step to the next
/// (verdict::to_string).
template <class Machine, class Apply, class Label = numbered_inputs>
class cycle_model : public detail::encoded_model<cycle_model<Machine, Apply, Label>, Machine> {
public:
    using state = Machine;

    // (The parameter is not `label`: a function pointer of that name shadows label() for -Wshadow.)
    cycle_model(Machine initial, duration period, std::size_t choices, Apply apply, Label choice_label = {})
        : detail::encoded_model<cycle_model, Machine>(std::move(initial), period),
          choices_(choices),
          apply_(std::move(apply)),
          label_(std::move(choice_label)) {}

    /// The number of alternatives offered in every state: the choices of inputs.
    std::size_t labels() const { return choices_; }
    /// Takes alternative `choice` in place: sets its inputs, then steps one period on. `M` is
    /// the machine type or the same chart with another observer.
    template <class M>
    void advance(M& s, std::uint16_t choice) const {
        apply_(s.context(), choice);
        s.step(detail::origin + period());
    }
    std::string label(std::uint16_t i) const { return label_(i); }
    std::string describe(state const& s) const { return s.active_states().joined(); }
    /// The time between two cycles: a trace's step k is at k periods.
    duration period() const { return this->step_period(); }

private:
    std::size_t choices_;
    Apply apply_;
    Label label_;
};

/// A closed system: an aggregate `System` of machines and plant data, advanced by
/// `step(system, choice, now)` for each of `choices` alternatives per cycle. `describe`
/// names a system state for traces; `label(choice)` names an alternative.
template <class System, class Step, class Describe, class Label>
class system_model : public detail::encoded_model<system_model<System, Step, Describe, Label>, System> {
public:
    using state = System;

    system_model(System initial, duration period, std::size_t choices, Step step, Describe describe, Label choice_label)
        : detail::encoded_model<system_model, System>(std::move(initial), period),
          choices_(choices),
          step_(std::move(step)),
          describe_(std::move(describe)),
          label_(std::move(choice_label)) {}

    /// The number of alternatives offered in every state.
    std::size_t labels() const { return choices_; }
    /// Takes alternative `choice` in place: one step of the system.
    void advance(state& s, std::uint16_t choice) const { step_(s, choice, detail::origin + period()); }
    std::string label(std::uint16_t i) const { return label_(i); }
    std::string describe(state const& s) const { return describe_(s); }
    /// The time between two steps: a trace's step k is at k periods.
    duration period() const { return this->step_period(); }

private:
    std::size_t choices_;
    Step step_;
    Describe describe_;
    Label label_;
};

}  // namespace bsc::verify
