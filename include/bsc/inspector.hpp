#pragma once
// bsc::inspector: a live view of a running machine in the browser. It serves the inspector's
// page (web/inspector, docs/inspector.md) on 127.0.0.1 and the machine's trace stream to it,
// and, when the program allows it, runs the page's commands on the machine:
//
//   std::array<std::byte, 1 << 16> storage;
//   bsc::trace_buffer buffer{storage};
//   bsc::machine m{chart, ctx{}, bsc::tracer{chart, buffer}};
//   bsc::inspector view{m, buffer, {.port = 8080, .commands = true, .web_root = "web/inspector"}};
//   for (;;) {
//       view.poll(10ms);                  // serve the page, run its commands
//       if (view.may_step()) m.step(now);  // a scan machine: paused and stepped from the page
//   }
//
// Nothing runs behind the program's back: there is no thread; the page's commands run in
// poll(), through the machine's own interface (dispatch_by_name; an input's set, latched at the
// next step), so that the checks and the reentrancy rules hold. The server binds to the
// loopback address only, refuses commands unless `commands` is set, and refuses a command from a
// page of another origin.
//
// Opt-in and POSIX only: <bsc/bsc.hpp> does not include it.

#include <charconv>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <type_traits>

#include <bsc/detail/inspector/site.hpp>
#include <bsc/detail/member_path.hpp>
#include <bsc/detail/members.hpp>
#include <bsc/detail/recorded_members.hpp>
#include <bsc/inspector_options.hpp>
#include <bsc/observers.hpp>
#include <bsc/outcome.hpp>
#include <bsc/trace.hpp>
#include <bsc/trace_buffer.hpp>

namespace bsc {

namespace detail::inspector {

// The tracer among a machine's observers: the observer itself, or the first tracer part of a
// bsc::observers; a no_tracer when there is none (which the inspector refuses).
struct no_tracer {
    template <class Machine>
    void write_dictionary(Machine const&) {}
    template <class Machine>
    void sample(Machine const&) {}
};
template <class T>
inline constexpr bool is_tracer = false;
template <class C>
inline constexpr bool is_tracer<tracer<C>> = true;

template <class O>
auto* tracer_of(O& o) {
    if constexpr (is_tracer<O>) {
        return &o;
    } else {
        (void)o;
        return static_cast<no_tracer*>(nullptr);
    }
}
template <class... Parts>
auto* tracer_of(observers<Parts...>& o) {
    constexpr std::size_t first = [] {
        constexpr bool tracers[] = {is_tracer<Parts>...};
        std::size_t i = 0;
        while (i < sizeof...(Parts) && !tracers[i]) ++i;
        return i;
    }();
    if constexpr (first < sizeof...(Parts))
        return &o.template get<first>();
    else
        return static_cast<no_tracer*>(nullptr);
}

// Finds the context member named `path` (dotted, as the trace names members) in a walk
// (detail/members.hpp) and, if it is an input of a scalar type that `refuse` does not refuse
// (given its address, it says why not, or nothing), sets it to the value `text` reads as;
// `answer` is then empty, or says why not.
struct input_setter {
    static constexpr bool named = true;
    std::string_view path;
    std::string_view text;
    std::function<std::string(void const*)> refuse;
    member_path prefix;
    std::string answer;
    bool found = false;

    // As the trace names them (the page sets what the trace showed it).
    std::string element_name(std::string_view name, std::size_t i) const { return recorded::element_name(name, i); }
    void enter(std::string_view name) { prefix.enter(name); }
    void leave() { prefix.leave(); }
    template <class T>
    void leaf(T const& member, std::string_view name) {
        if (found || prefix.of(name) != path) return;
        found = true;
        std::string const what{path};
        if constexpr (is_channel<T>) {
            using V = channel_value<T>;
            if constexpr (is_output_channel<T>) {  // the chart's own: its const set() is an error
                answer = what + " is an output: only inputs can be set";
            } else if constexpr (!recorded::is_scalar_variable<V>) {
                answer = what + " is not of a scalar type";
            } else if (std::string why = refuse ? refuse(&member) : std::string{}; !why.empty()) {
                answer = std::move(why);
            } else {
                V value{};
                if (read(text, value)) {
                    member.set(value);
                    answer.clear();
                } else {
                    answer = "'" + std::string{text} + "' is not a value of " + what;
                }
            }
        } else {
            (void)member;
            answer = what + " is not an input channel: only inputs can be set";
        }
    }
    template <class V>
    static bool read(std::string_view t, V& value) {
        if constexpr (std::is_same_v<V, bool>) {
            bool const yes = t == "true" || t == "1";
            bool const no = t == "false" || t == "0";
            if (yes || no) value = yes;
            return yes || no;
        } else if constexpr (std::is_enum_v<V>) {
            // Only an enum with a fixed underlying type takes any of its values: list
            // initialisation from an integer compiles for exactly those.
            if constexpr (requires(std::underlying_type_t<V> u) { V{u}; }) {
                std::underlying_type_t<V> n{};
                if (!read(t, n)) return false;
                value = V{n};
                return true;
            } else {
                return false;
            }
        } else {
            auto const r = std::from_chars(t.data(), t.data() + t.size(), value);
            return r.ec == std::errc{} && r.ptr == t.data() + t.size();
        }
    }
};

// Sets the input named `path` of `context` to `text`'s value: "" (done), or why not (`refuse`'s
// answer for the input's address among them).
template <class Context>
std::string set_input(Context const& context, std::string_view path, std::string_view text,
                      std::function<std::string(void const*)> refuse = {}) {
    input_setter setter{path, text, std::move(refuse), {}, "no input is named '" + std::string{path} + "'", false};
    if constexpr (reaches<input_setter, Context>()) walk(context, setter, std::string_view{});
    return setter.answer;
}

}  // namespace detail::inspector

/// Serves a live view of `Machine` to the browser; see the top of this header.
/// Requirements: the machine's observer is a bsc::tracer writing into `buffer`, or a
/// bsc::observers holding one; the machine and the buffer outlive the inspector.
template <class Machine>
class inspector {
public:
    /// Listens on 127.0.0.1:options.port; throws std::system_error if it cannot.
    inspector(Machine& machine, trace_buffer& buffer, inspector_options options)
        : machine_(machine), history_(&buffer), site_(std::move(options)) {
        static_assert(!std::is_same_v<decltype(tracer()), detail::inspector::no_tracer*>,
                      "bsc::inspector: the machine's observer must be a bsc::tracer, or a bsc::observers holding one");
    }

    /// The port it listens on.
    std::uint16_t port() const { return site_.port(); }
    /// The page's address: "http://127.0.0.1:<port>/".
    std::string url() const { return site_.url(); }

    /// Moves the trace into the history, then serves the requests that arrive within `wait`
    /// (and runs their commands).
    void poll(std::chrono::milliseconds wait = {}) {
        collect();
        site_.serve(wait, *this);
        collect();
    }

    /// For a scan loop: whether to run the next step. Always true while not paused; while
    /// paused, true once for each "step" command.
    bool may_step() { return site_.may_step(); }
    /// Whether the page paused the machine.
    bool paused() const { return site_.paused(); }
    /// The commands run so far.
    std::uint64_t commands_run() const { return site_.commands_run(); }
    /// The trace bytes the page can read (from its start, less what the history let go).
    std::size_t trace_end() const { return history_.end(); }

private:
    // The site's handler (detail/inspector/site.hpp): the machine's own answers.
    friend class detail::inspector::site;
    detail::inspector::response info(std::string const& run) const {
        std::string body = "{\"chart\": \"" + detail::inspector::json_name(detail::state_names_of<model>[1]) + "\", ";
        return {200, "application/json", body + run + "}", {}};
    }
    detail::inspector::response trace(std::string_view query) const {
        return history_.answer(detail::inspector::query_number(query, "from"));
    }
    detail::inspector::response command(std::string_view verb, std::string_view rest) {
        using detail::inspector::text;
        if (verb == "dispatch" && !rest.empty()) {
            outcome const o = machine_.dispatch_by_name(rest);
            tracer()->sample(machine_);
            if (o == outcome::unknown_event)
                return text(400, "no event of this chart is named '" + std::string{rest} + "'");
            return text(200, "ok " + std::string{rest} + ": " + detail::inspector::outcome_text(o));
        }
        if (verb == "set" && !rest.empty()) {
            auto const [member, value] = detail::inspector::split_word(rest);
            if (value.empty()) return text(400, "set <input> <value>");
            std::string const why = detail::inspector::set_input(machine_.context(), member, value);
            if (!why.empty()) return text(400, why);
            return text(200, "ok " + std::string{member} + " = " + std::string{value} +
                                 (site_.options().stepping ? " (latched at the next step)" : ""));
        }
        return text(400, "commands: dispatch <event>, set <input> <value>, pause, resume, step");
    }

    void collect() {
        // The history starts again at a dictionary and the configuration written now, so that
        // a page that opens later begins with every name and where the machine stands.
        history_.collect(site_.options().history_limit, [this] { tracer()->write_dictionary(machine_); });
    }

    auto* tracer() { return detail::inspector::tracer_of(machine_.observer()); }

    using model = detail::chart_model<std::remove_cv_t<typename Machine::chart_type>>;

    Machine& machine_;
    detail::inspector::trace_history history_;
    detail::inspector::site site_;
};

template <class Machine>
inspector(Machine&, trace_buffer&, inspector_options) -> inspector<Machine>;

}  // namespace bsc
