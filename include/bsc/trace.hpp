#pragma once
// bsc::tracer: an observer that writes what a machine does as a compact binary trace into a
// bsc::trace_buffer, for a file (record now, replay later) or a socket (watch it live). The
// chart's dictionary (its states, events and, at the first sample, its context's members) is
// written once, then every record carries numbers (docs/trace.md has the format):
//
//   std::array<std::byte, 8192> storage;
//   bsc::trace_buffer buffer{storage};
//   bsc::machine m{chart, ctx{}, bsc::tracer{chart, buffer}};
//   m.step(0s);
//   m.observer().sample(m);   // the channels, timers and variables that changed
//   // drain `buffer` to a file or a socket; bsc::trace_reader reads it back
//
// Opt-in: <bsc/bsc.hpp> does not include it, and a machine without it pays nothing. With it,
// each record costs a frame of 7 bytes plus its payload (an exit or entry: 9 bytes) and the
// instructions docs/trace.md gives; it never blocks. It allocates where it writes names: the
// dictionary (construction, write_dictionary) and sample()'s first call, and in sample() for the
// names of array elements; the hooks never allocate.

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include <bsc/detail/access.hpp>
#include <bsc/detail/export/model.hpp>
#include <bsc/detail/member_path.hpp>
#include <bsc/detail/members.hpp>
#include <bsc/detail/model/chart_model.hpp>
#include <bsc/detail/recorded_members.hpp>
#include <bsc/detail/trace/format.hpp>
#include <bsc/duration.hpp>
#include <bsc/event_name.hpp>
#include <bsc/events.hpp>
#include <bsc/observer.hpp>
#include <bsc/trace_buffer.hpp>

namespace bsc {

/// Writes a machine of chart type Chart into a trace_buffer: construct it with the buffer (which
/// must outlive it) and give it to the machine as its observer. Requirements: the chart has at
/// most 65,533 states and events (numbers 0xFFFD to 0xFFFF are reserved).
template <class Chart>
class tracer {
    using model = detail::chart_model<std::remove_cv_t<Chart>>;
    using events = typename model::events;
    static_assert(model::N < detail::trace::timeout_trigger && events::size < detail::trace::timeout_trigger,
                  "bsc::tracer: a chart with more than 65,532 states or events cannot be traced");

public:
    using chart_type = Chart;

    /// Writes the dictionary of `chart`'s states, events and transitions into `buffer`. Both
    /// must outlive the tracer.
    tracer(Chart const& chart, trace_buffer& buffer) : chart_(&chart), buffer_(&buffer) { write_dictionary(); }

    /// The ring it writes into.
    trace_buffer& buffer() const { return *buffer_; }

    /// Writes the dictionary again (for a reader that joins late): the hello, the states,
    /// events and transitions now, the members at the next sample(). The transitions' labels
    /// are built as the exports build them (with std::string: this allocates).
    void write_dictionary() {
        namespace t = detail::trace;
        static constexpr auto const& names = detail::state_names_of<model>;
        std::byte payload[t::max_payload];
        std::byte* p = payload;
        p = t::put(p, t::format_version);
        p = t::put(p, static_cast<std::uint16_t>(model::N));
        p = t::put(p, static_cast<std::uint16_t>(events::size));
        auto const diagram = detail::model_of(*chart_);
        p = t::put(p, static_cast<std::uint16_t>(diagram.transitions.size()));
        write(t::record_type::hello, with_text(payload, p, names[1]));
        for (std::size_t s = 0; s < names.size(); ++s) {
            p = t::put(payload, static_cast<std::uint16_t>(s));
            int const parent = model::tree.parent[s];
            p = t::put(p, parent < 0 ? t::no_number : static_cast<std::uint16_t>(parent));
            p = t::put(p, static_cast<std::uint8_t>(model::tree.kinds[s]));
            write(t::record_type::state, with_text(payload, p, s == 0 ? std::string_view{"(top)"} : names[s]));
        }
        // clang-format off
        [&]<class... Es>(detail::type_list<Es...>) {
            std::uint16_t number = 0;
            ((p = t::put(payload, number++), write(t::record_type::event, with_text(payload, p, event_name<Es>))), ...);
        }(events{});
        // clang-format on
        for (auto const& row : diagram.transitions) {
            p = t::put(payload, static_cast<std::uint16_t>(row.row));
            p = t::put(p, static_cast<std::uint16_t>(row.source + 1));  // the diagram leaves out the top
            p = t::put(p, row.target < 0 ? t::no_number : static_cast<std::uint16_t>(row.target + 1));
            p = t::put(p, row.trigger == detail::trigger_kind::timeout
                              ? t::timeout_trigger
                              : row_triggers[static_cast<std::size_t>(row.row)]);
            p = t::put(p, static_cast<std::uint8_t>((row.defers ? 1 : 0) | (row.local ? 2 : 0)));
            write(t::record_type::row, with_text(payload, p, row.label()));
        }
        members_named_ = false;
    }

    /// Writes the dictionary again and then the machine's active configuration, so that a
    /// reader that joins now knows where the machine stands (the inspector does this when it
    /// lets the oldest part of its history go).
    template <class Machine>
    void write_dictionary(Machine const& machine) {
        namespace t = detail::trace;
        write_dictionary();
        auto const active = detail::access::active_flags(machine);
        std::byte payload[t::max_payload];
        std::byte* p = t::put(payload, std::uint8_t{1});
        for (std::size_t s = 1; s < active.size(); ++s) {
            if (!active[s]) continue;
            if (static_cast<std::size_t>(p - payload) + 2 > t::max_payload) {
                write(t::record_type::configuration, std::span<std::byte const>{payload, p});
                p = t::put(payload, std::uint8_t{0});
            }
            p = t::put(p, static_cast<std::uint16_t>(s));
        }
        write(t::record_type::configuration, std::span<std::byte const>{payload, p});
    }

    /// Writes the machine's channels, timers and scalar variables that changed since the last
    /// sample (all of them, with their names, at the first), at the machine's time. Call it
    /// after each step or dispatch you want the values of. Allocates at the first call, and
    /// where it names the elements of an array member.
    template <class Machine>
    void sample(Machine const& machine) {
        using context = typename Machine::context_type;
        using visitor = detail::recorded::recorded_members<value_writer>;
        if constexpr (detail::reaches<visitor, context>()) {
            value_writer writer{*this, machine.now().count()};
            visitor members{writer};
            detail::walk(machine.context(), members, std::string_view{});
            writer.flush();
            members_named_ = true;
        }
    }

    // ---- the observer hooks (observer.hpp) ------------------------------------------------
    template <class E>
    void on_dispatch(E const&) {
        std::byte payload[10];
        detail::trace::put(detail::trace::put(payload, time_), event_number<E>());
        write(detail::trace::record_type::dispatch, payload);
    }
    void on_cycle(duration now) {
        time_ = now.count();
        std::byte payload[8];
        detail::trace::put(payload, time_);
        write(detail::trace::record_type::cycle, payload);
    }
    void on_cycle_end() { write(detail::trace::record_type::cycle_end, {}); }
    template <class State>
    void on_exit(State) {
        write_state(detail::trace::record_type::exit, state_number<typename State::type>());
    }
    template <class State>
    void on_entry(State) {
        write_state(detail::trace::record_type::entry, state_number<typename State::type>());
    }
    template <class Source, class E>
    void on_defer(Source, E const&) {
        deferring_ = true;
    }
    // The transition is written at on_row, which follows, so that one record holds the row too.
    template <class Source, class Target, class E>
    void on_transition(Source, Target, E const& e) {
        source_ = state_number<typename Source::type>();
        target_ = std::is_same_v<typename Target::type, internal> ? detail::trace::no_number
                                                                  : state_number<typename Target::type>();
        trigger_ = event_number<E>();
        if constexpr (std::is_same_v<E, timeout_elapsed>)
            delay_ = e.delay.count();
        else
            (void)e;
    }
    void on_row(int row) {
        namespace t = detail::trace;
        std::byte payload[16];
        if (deferring_) {
            deferring_ = false;
            t::put(t::put(payload, source_), trigger_);
            write(t::record_type::deferral, std::span<std::byte const>{payload, 4});
            return;
        }
        std::byte* p = t::put(payload, static_cast<std::uint16_t>(row));
        p = t::put(p, source_);
        p = t::put(p, target_);
        p = t::put(p, trigger_);
        if (trigger_ == t::timeout_trigger) p = t::put(p, delay_);
        write(t::record_type::transition, std::span<std::byte const>{payload, p});
    }

private:
    template <class S>
    static constexpr std::uint16_t state_number() {
        return static_cast<std::uint16_t>(model::template index_of_state<S>::value);
    }
    template <class E>
    static constexpr std::uint16_t event_number() {
        if constexpr (std::is_same_v<E, eventless>) {
            return detail::trace::eventless_trigger;
        } else if constexpr (std::is_same_v<E, timeout_elapsed>) {
            return detail::trace::timeout_trigger;
        } else {
            constexpr int at = detail::position_in<E, events>::value;
            constexpr int family = model::template trigger_of<E>::value;
            return at >= 0 ? static_cast<std::uint16_t>(at)
                           : (family >= 0 ? static_cast<std::uint16_t>(family) : detail::trace::no_number);
        }
    }

    // Each row's trigger by its type (an eventless row's, and a timeout's, as eventless: the
    // diagram tells the timeouts apart), as the transition records number it.
    // clang-format off
    static constexpr auto row_triggers = []<std::size_t... I>(std::index_sequence<I...>) {
        return std::array<std::uint16_t, sizeof...(I)>{
            event_number<detail::row_event_t<typename model::template row_at<static_cast<int>(I)>>>()...};
    }(std::make_index_sequence<static_cast<std::size_t>(model::R)>{});
    // clang-format on

    void write(detail::trace::record_type type, std::span<std::byte const> payload) { buffer_->write(type, payload); }
    void write_state(detail::trace::record_type type, std::uint16_t state) {
        std::byte payload[2];
        detail::trace::put(payload, state);
        write(type, payload);
    }
    // The payload from `begin` to `end` followed by as much of `text` as fits.
    static std::span<std::byte const> with_text(std::byte* begin, std::byte* end, std::string_view text) {
        auto const room = detail::trace::max_payload - static_cast<std::size_t>(end - begin);
        std::size_t const n = text.size() < room ? text.size() : room;
        for (std::size_t i = 0; i < n; ++i) *end++ = static_cast<std::byte>(text[i]);
        return {begin, end};
    }

    // Receives the context's recorded members (detail/recorded_members.hpp) in walk order,
    // names them at the first sample and writes the values that changed, in frames of up to 24.
    struct value_writer {
        value_writer(tracer& owner, std::int64_t now) : self(owner), time(now), path(owner.path_) { path.clear(); }

        tracer& self;
        std::int64_t time;
        std::size_t next = 0;       // the member's number
        detail::member_path& path;  // the tracer's, whose memory each sample reuses
        std::byte payload[detail::trace::max_payload]{};
        std::byte* end = nullptr;

        void scope(std::string_view name) { path.enter(name); }
        void upscope() { path.leave(); }
        void var(detail::recorded::var_kind kind, unsigned width, std::string_view name,
                 detail::recorded::value const& v) {
            namespace t = detail::trace;
            std::size_t const number = next++;
            if (number >= t::no_number) return;  // past the numbers a record can carry
            if (!self.members_named_) {
                std::byte entry[t::max_payload];
                std::byte* p = t::put(entry, static_cast<std::uint16_t>(number));
                p = t::put(p, static_cast<std::uint8_t>(kind));
                p = t::put(p, static_cast<std::uint8_t>(width));
                std::string const full = path.of(name);
                self.write(t::record_type::member, with_text(entry, p, full));
            }
            std::uint64_t const bits = kind == detail::recorded::var_kind::real ? std::bit_cast<std::uint64_t>(v.real)
                                                                                : v.bits;
            if (self.last_.size() <= number) self.last_.resize(number + 1);
            if (self.members_named_ && self.last_[number] == bits) return;
            self.last_[number] = bits;
            if (end == nullptr || static_cast<std::size_t>(end - payload) + 10 > t::max_payload) {
                flush();
                end = t::put(payload, time);
            }
            end = t::put(t::put(end, static_cast<std::uint16_t>(number)), bits);
        }
        void flush() {
            if (end != nullptr && end - payload > 8)
                self.write(detail::trace::record_type::values, std::span<std::byte const>{payload, end});
            end = nullptr;
        }
    };

    Chart const* chart_;
    trace_buffer* buffer_;
    std::int64_t time_ = 0;  // the last cycle's time: a dispatch's too
    std::uint16_t source_ = 0, target_ = 0, trigger_ = 0;
    std::int64_t delay_ = 0;
    bool deferring_ = false;
    bool members_named_ = false;
    std::vector<std::uint64_t> last_;  // each member's last value written
    detail::member_path path_;         // the member names of sample()'s walk
};

template <class Chart>
tracer(Chart const&, trace_buffer&) -> tracer<Chart const>;

}  // namespace bsc
