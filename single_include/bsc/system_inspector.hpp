#pragma once
// bsc::system_inspector - a live view of a system in the browser, single-header distribution (needs bsc.hpp and
// inspector.hpp beside it; POSIX).
// Generated from include/bsc/system_inspector.hpp by `python3 scripts/amalgamate.py`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
// begin include/bsc/system_inspector.hpp
// bsc::system_inspector: the live view of a running bsc::system in the browser, one panel per
// actor and the links between them. The same page and server as bsc::inspector
// (docs/inspector.md); each actor whose observer is a bsc::tracer (or a bsc::observers holding
// one) has its own trace stream, read by the page from GET /trace?actor=I&from=N:
//
//   bsc::system_inspector view{cell, {.port = 8080, .commands = true, .stepping = true,
//                                     .web_root = "web/inspector"}};
//   for (;;) {
//       view.poll(10ms);                              // serve the page, run its commands
//       if (view.may_step()) cell.step(now), view.sample();
//   }
//
// The page's commands name the actor: "dispatch <actor> <event>", "set <actor> <input>
// <value>" (an input that no link drives: the next step would overwrite it), and pause, resume
// and step for the whole system. They run in poll(), through each machine's own interface.
//
// Opt-in and POSIX only: <bsc/bsc.hpp> does not include it.

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>

// begin include/bsc/detail/system_plan.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_DETAIL_SYSTEM_PLAN_HPP
#define BSC_SINGLE_INCLUDE_BSC_DETAIL_SYSTEM_PLAN_HPP
// What a program that runs or shows a bsc::system knows of it at compile time: the actors in
// their order, with their names; the links with their ends' places and channel names. Used by
// bsc::net::node and bsc::system_inspector.

#include <array>
#include <cstddef>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>


namespace bsc::detail {

template <std::size_t I, auto... Members>
struct nth_member;
template <auto First, auto... Rest>
struct nth_member<0, First, Rest...> {
    static constexpr auto value = First;
};
template <std::size_t I, auto First, auto... Rest>
struct nth_member<I, First, Rest...> : nth_member<I - 1, Rest...> {};

template <class System>
struct system_plan {
    static_assert(sizeof(System) == 0, "System must be a bsc::system<Actors, bsc::order<...>, links...>");
};

template <class Actors, auto... Steps, class... Entries>
struct system_plan<system<Actors, order<Steps...>, Entries...>> {
    // The links only: a system's bsc::from_outside entries are the environment's business.
    using links = typename system<Actors, order<Steps...>, Entries...>::links_type;
    static constexpr std::size_t actor_count = sizeof...(Steps);
    static constexpr std::size_t link_count = std::tuple_size_v<links>;
    static constexpr std::array<std::string_view, actor_count> names{member_name<Steps>()...};

    template <auto Actor>
    static constexpr std::size_t place() {
        std::size_t i = 0, found = actor_count;
        ((same_member_pointer<Actor, Steps>() ? (found = i, ++i) : ++i), ...);
        return found;
    }
    template <std::size_t I>
    static constexpr auto step_at = nth_member<I, Steps...>::value;
    template <std::size_t I>
    using machine_at = std::remove_cvref_t<decltype(std::declval<Actors&>().*nth_member<I, Steps...>::value)>;

    // What link L carries over the network: the source's value, as its publisher published it
    // (the consumer's side applies the link's bsc::convert).
    template <class L>
    using value_of = channel_value<
        std::remove_cvref_t<decltype(((std::declval<Actors&>().*L::from_actor).context()).*L::from_channel)>>;
    // What the consumer of link L reads: its input's value type.
    template <class L>
    using target_value_of =
        channel_value<std::remove_cvref_t<decltype(((std::declval<Actors&>().*L::to_actor).context()).*L::to_channel)>>;

    // (Every actor a link names is in the order: bsc::system checks it.)
    // clang-format off
    static constexpr std::array<std::size_t, link_count> from = []<class... L>(std::tuple<L...>*) {
        return std::array<std::size_t, link_count>{place<L::from_actor>()...};
    }(static_cast<links*>(nullptr));
    // clang-format on
    // clang-format off
    static constexpr std::array<std::size_t, link_count> to = []<class... L>(std::tuple<L...>*) {
        return std::array<std::size_t, link_count>{place<L::to_actor>()...};
    }(static_cast<links*>(nullptr));
    // clang-format on
    // clang-format off
    static constexpr std::array<bool, link_count> lossless = []<class... L>(std::tuple<L...>*) {
        return std::array<bool, link_count>{std::is_same_v<typename L::when_stale, bsc::lossless>...};
    }(static_cast<links*>(nullptr));
    // clang-format on
    // The name of a channel in its actor's context; empty where the context is not an aggregate
    // (one described by bsc::fields: its members' names are not known here).
    template <auto Channel>
    static constexpr std::string_view channel_name() {
        if constexpr (std::is_aggregate_v<decltype(class_of_member(Channel))>)
            return member_name<Channel>();
        else
            return {};
    }
    // The channels each link joins, by their names.
    static constexpr std::array<std::string_view, link_count> from_channels() {
        // clang-format off
        return []<class... L>(std::tuple<L...>*) {
            return std::array<std::string_view, link_count>{channel_name<L::from_channel>()...};
        }(static_cast<links*>(nullptr));
        // clang-format on
    }
    static constexpr std::array<std::string_view, link_count> to_channels() {
        // clang-format off
        return []<class... L>(std::tuple<L...>*) {
            return std::array<std::string_view, link_count>{channel_name<L::to_channel>()...};
        }(static_cast<links*>(nullptr));
        // clang-format on
    }
};

}  // namespace bsc::detail
#endif  // BSC_SINGLE_INCLUDE_BSC_DETAIL_SYSTEM_PLAN_HPP
// end include/bsc/detail/system_plan.hpp
#include "inspector.hpp"

namespace bsc {

/// Serves a live view of `System`, a bsc::system, to the browser; see the top of this header.
/// Requirements: the system outlives the inspector, and so do the rings of its actors' tracers.
/// Actors without a tracer are shown without a chart.
template <class System>
class system_inspector {
    using plan = detail::system_plan<System>;
    static constexpr std::size_t N = plan::actor_count;

public:
    /// Listens on 127.0.0.1:options.port; throws std::system_error if it cannot.
    /// Throws std::invalid_argument if two actors' tracers write into one ring (each stream
    /// needs its own: the reader of one would take the other's frames).
    system_inspector(System& system, inspector_options options) : system_(system), site_(std::move(options)) {
        std::array<trace_buffer const*, N> rings{};
        each([&]<std::size_t I>() {
            if constexpr (traced<I>) {
                rings[I] = &tracer<I>()->buffer();
                for (std::size_t j = 0; j < I; ++j)
                    if (rings[j] == rings[I])
                        throw std::invalid_argument("bsc::system_inspector: " + std::string{plan::names[j]} + " and " +
                                                    std::string{plan::names[I]} + " trace into the same ring");
                histories_[I] = detail::inspector::trace_history{&tracer<I>()->buffer()};
            }
        });
    }

    /// The port it listens on.
    std::uint16_t port() const { return site_.port(); }
    /// The page's address: "http://127.0.0.1:<port>/".
    std::string url() const { return site_.url(); }

    /// Moves the actors' traces into their histories, then serves the requests that arrive
    /// within `wait` (and runs their commands).
    void poll(std::chrono::milliseconds wait = {}) {
        collect();
        site_.serve(wait, *this);
        collect();
    }

    /// Writes the channels, timers and variables of every traced actor that changed (each
    /// tracer's sample()): call it after each step of the system.
    void sample() {
        each([&]<std::size_t I>() {
            if constexpr (traced<I>) tracer<I>()->sample(actor<I>());
        });
    }

    /// For a scan loop: whether to run the next step of the system. Always true while not
    /// paused; while paused, true once for each "step" command.
    bool may_step() { return site_.may_step(); }
    /// Whether the page paused the system.
    bool paused() const { return site_.paused(); }
    /// The commands run so far.
    std::uint64_t commands_run() const { return site_.commands_run(); }
    /// The actors' names, in the system's order (as bsc::net::node gives them).
    static constexpr std::span<std::string_view const, N> actor_names() { return plan::names; }

    /// The system as GET /info describes it, without the run's fields: a JSON object
    /// {"system": true, "actors": [{"name", "chart", "traced"}...], "links": [{"from",
    /// "from_channel", "to", "to_channel", "lossless"}...]}, actors and links in the system's
    /// order. Saved as system.json beside the actors' recorded traces (<name>.bsctrace), it lets
    /// the page replay the system from files.
    static std::string description() {
        using detail::inspector::json_name;
        std::string body = "{\"system\": true, \"actors\": [";
        // clang-format off
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            ((body += std::string(I > 0 ? ", " : "") + "{\"name\": \"" + json_name(plan::names[I]) + "\", \"chart\": \"" +
                      json_name(chart_name<I>()) + "\", \"traced\": " + (traced<I> ? "true" : "false") + "}"),
             ...);
        }(std::make_index_sequence<N>{});
        // clang-format on
        body += "], \"links\": [";
        static constexpr auto from_channels = plan::from_channels();
        static constexpr auto to_channels = plan::to_channels();
        for (std::size_t k = 0; k < plan::link_count; ++k) {
            if (k > 0) body += ", ";
            body += "{\"from\": " + std::to_string(plan::from[k]) + ", \"from_channel\": \"" +
                    json_name(from_channels[k]) + "\", \"to\": " + std::to_string(plan::to[k]) +
                    ", \"to_channel\": \"" + json_name(to_channels[k]) +
                    "\", \"lossless\": " + (plan::lossless[k] ? "true" : "false") + "}";
        }
        return body + "]}";
    }

    /// The trace bytes of the actor at `place` in the system's order that the page can read.
    std::size_t trace_end(std::size_t place) const { return place < N ? histories_[place].end() : 0; }

private:
    friend class detail::inspector::site;
    using response = detail::inspector::response;

    template <std::size_t I>
    auto& actor() {
        return system_.actors.*plan::template step_at<I>;
    }
    // The tracer of the actor at place I, or nullptr.
    template <std::size_t I>
    auto* tracer() {
        using machine = typename plan::template machine_at<I>;
        if constexpr (requires(machine & m) { m.observer(); }) {
            auto* t = detail::inspector::tracer_of(actor<I>().observer());
            if constexpr (std::is_same_v<decltype(t), detail::inspector::no_tracer*>)
                return static_cast<no_tracer_type*>(nullptr);
            else
                return t;
        } else {
            return static_cast<no_tracer_type*>(nullptr);
        }
    }
    // What tracer<I>() gives for an actor without a tracer (a null pointer).
    struct no_tracer_type {};
    template <std::size_t I>
    static constexpr bool traced =
        !std::is_same_v<decltype(std::declval<system_inspector&>().template tracer<I>()), no_tracer_type*>;

    template <class F>
    void each(F&& f) {
        // clang-format off
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            (f.template operator()<I>(), ...);
        }(std::make_index_sequence<N>{});
        // clang-format on
    }
    // Runs f<I>() for the actor at place `place`.
    template <class F>
    void at(std::size_t place, F&& f) {
        each([&]<std::size_t I>() {
            if (I == place) f.template operator()<I>();
        });
    }

    template <std::size_t I>
    static constexpr std::string_view chart_name() {
        using machine = typename plan::template machine_at<I>;
        if constexpr (requires { typename machine::chart_type; })
            return detail::state_names_of<detail::chart_model<std::remove_cv_t<typename machine::chart_type>>>[1];
        else
            return {};
    }

    void collect() {
        each([&]<std::size_t I>() {
            if constexpr (traced<I>)
                histories_[I].collect(site_.options().history_limit,
                                      [this] { tracer<I>()->write_dictionary(actor<I>()); });
        });
    }

    // The place of the actor named `name`, or N.
    static std::size_t place_of(std::string_view name) {
        for (std::size_t i = 0; i < N; ++i)
            if (plan::names[i] == name) return i;
        return N;
    }

    // The site's handler (detail/inspector/site.hpp): the system's own answers.
    response info(std::string const& run) const {
        std::string body = description();
        body.pop_back();  // the closing brace: the run's fields follow
        return {200, "application/json", body + ", " + run + "}", {}};
    }

    response trace(std::string_view query) const {
        std::size_t const place = detail::inspector::query_number(query, "actor", N);
        if (place >= N || !histories_[place].traced())
            return detail::inspector::text(404, "no traced actor at that place");
        return histories_[place].answer(detail::inspector::query_number(query, "from"));
    }

    response command(std::string_view verb, std::string_view rest) {
        using detail::inspector::text;
        // (Not a structured binding: Clang 14 does not capture one in a lambda.)
        auto const words = detail::inspector::split_word(rest);
        std::string_view const name = words.first, what = words.second;
        bool const known = (verb == "dispatch" || verb == "set") && !what.empty();
        if (!known)
            return text(400, "commands: dispatch <actor> <event>, set <actor> <input> <value>, pause, resume, step");
        std::size_t const place = place_of(name);
        if (place == N) return text(400, "no actor of this system is named '" + std::string{name} + "'");
        response answer = text(500, "");
        at(place, [&]<std::size_t I>() { answer = verb == "dispatch" ? dispatch<I>(what) : set<I>(what); });
        return answer;
    }

    template <std::size_t I>
    response dispatch(std::string_view event) {
        using detail::inspector::text;
        std::string const who{plan::names[I]};
        if constexpr (requires(typename plan::template machine_at<I> & m) { m.dispatch_by_name(event); }) {
            outcome const o = actor<I>().dispatch_by_name(event);
            if constexpr (traced<I>) tracer<I>()->sample(actor<I>());
            if (o == outcome::unknown_event)
                return text(400, "no event of " + who + "'s chart is named '" + std::string{event} + "'");
            return text(200, "ok " + who + " " + std::string{event} + ": " + detail::inspector::outcome_text(o));
        } else {
            return text(400, who + " takes no events by name");
        }
    }

    template <std::size_t I>
    response set(std::string_view rest) {
        using detail::inspector::text;
        // (Not a structured binding: Clang 14 does not capture one in a lambda.)
        auto const words = detail::inspector::split_word(rest);
        std::string_view const member = words.first, value = words.second;
        if (value.empty()) return text(400, "set <actor> <input> <value>");
        std::string const who{plan::names[I]};
        // A linked input takes its sender's value at every step: setting it would last no step.
        // Found by its address, which does not depend on how the context names its members.
        std::size_t driving = plan::link_count;  // the link that drives the input, if one does
        auto const refuse = [this, &driving](void const* input) {
            driving = link_driving<I>(input);
            return driving < plan::link_count ? std::string{"driven"} : std::string{};
        };
        std::string const why = detail::inspector::set_input(actor<I>().context(), member, value, refuse);
        if (driving < plan::link_count)
            return text(400, who + "." + std::string{member} + " is driven by the link from " + link_source(driving) +
                                 ": only inputs no link drives can be set");
        if (!why.empty()) return text(400, who + ": " + why);
        return text(200, "ok " + who + "." + std::string{member} + " = " + std::string{value} +
                             (site_.options().stepping ? " (latched at the next step)" : ""));
    }

    // The place in the system's list of links of the link that drives `input`, an input of the
    // actor at place I; link_count if none does.
    template <std::size_t I>
    std::size_t link_driving(void const* input) {
        // clang-format off
        return [&]<std::size_t... K>(std::index_sequence<K...>) {
            std::size_t found = plan::link_count;
            ((found == plan::link_count && linked_input<I, std::tuple_element_t<K, typename plan::links>>() == input
                  ? (found = K, 0)
                  : 0),
             ...);
            return found;
        }(std::make_index_sequence<plan::link_count>{});
        // clang-format on
    }
    // The input that link L drives, if it is an input of the actor at place I (else nullptr).
    template <std::size_t I, class L>
    void const* linked_input() {
        if constexpr (plan::template place<L::to_actor>() == I)
            return &(actor<I>().context().*L::to_channel);
        else
            return nullptr;
    }
    // "robot.press_loaded": the actor and the channel that link k takes its value from.
    static std::string link_source(std::size_t k) {
        static constexpr auto from_channels = plan::from_channels();
        std::string out{plan::names[plan::from[k]]};
        if (!from_channels[k].empty()) out += "." + std::string{from_channels[k]};
        return out;
    }

    System& system_;
    std::array<detail::inspector::trace_history, N> histories_{};
    detail::inspector::site site_;
};

template <class System>
system_inspector(System&, inspector_options) -> system_inspector<System>;

}  // namespace bsc
// end include/bsc/system_inspector.hpp
