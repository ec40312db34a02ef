// bsc::inspector (<bsc/inspector.hpp>) asked over a real loopback socket, in one thread: the
// client sends its request, the inspector's poll() answers it. Its trace, its commands (an
// input set and latched at the next step, an output refused, a pause and single steps), a
// read-only view, a page of another origin, and a history that lets its oldest half go and
// writes the dictionary again.

#include <doctest/doctest.h>

#include <bsc/bsc.hpp>
#include <bsc/inspector.hpp>
#include <bsc/observers.hpp>
#include <bsc/trace.hpp>
#include <bsc/trace_reader.hpp>

#include "inspector_client.hpp"

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace inspector_test {

using namespace std::chrono_literals;
using inspector_client::answer;
using inspector_client::ask;
using inspector_client::header;
using inspector_client::sent_as;

struct Root;
struct Idle;
struct Busy;
struct stop {};
enum class speed : std::uint8_t { slow, fast };
enum legacy_mode { manual, automatic };  // no fixed underlying type: not every number is a value
struct io {
    bsc::input<bool> start;
    bsc::output<int> count{0};
    int steps = 0;
    bsc::input<speed> rate;
    bsc::input<legacy_mode> mode;
};

inline constexpr auto chart = bsc::make_chart<io>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
    bsc::state<Idle>[([](io const& c) { return c.start.get(); })] /
        [](io& c) { c.count.set(c.count.pending() + 1); } = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<stop> = bsc::state<Idle>);

using tracer = bsc::tracer<decltype(chart)>;
using machine = bsc::machine<decltype(chart), bsc::scan_policy, tracer>;

}  // namespace inspector_test

TEST_CASE("the inspector serves the trace and runs a stepping program's commands through the machine") {
    using namespace inspector_test;
    std::array<std::byte, 1 << 14> storage{};
    bsc::trace_buffer buffer{storage};
    machine m{chart, io{}, tracer{chart, buffer}};
    std::string log;
    bsc::inspector_options options;
    options.commands = true;
    options.stepping = true;
    options.on_command = [&](std::string_view command, std::string_view reply) {
        log.append(command).append(" -> ").append(reply).append("\n");
    };
    bsc::inspector view{m, buffer, options};
    CHECK(view.port() != 0);
    CHECK(view.url() == "http://127.0.0.1:" + std::to_string(view.port()) + "/");
    m.step(0ms);

    auto const info = ask(view, "GET", "/info");
    CHECK(info.status == 200);
    CHECK(info.body == R"({"chart": "Root", "commands": true, "paused": false, "scan": true})");

    auto const trace = ask(view, "GET", "/trace?from=0");
    CHECK(trace.status == 200);
    CHECK(header(trace, "X-Trace-Start") == "0");
    CHECK(header(trace, "X-Trace-End") == std::to_string(trace.body.size()));
    bsc::trace_reader reader;
    reader.feed(std::as_bytes(std::span{trace.body}));
    int cycles = 0;
    while (auto r = reader.next()) cycles += r->type == bsc::trace_record_type::cycle;
    CHECK(reader.dictionary().chart == "Root");
    CHECK(reader.dictionary().states.size() == 4);
    CHECK(cycles == 1);

    // An input is set through the machine's interface: latched at the next step.
    auto const set = ask(view, "POST", "/command", "set start true");
    CHECK(set.status == 200);
    CHECK(set.body == "ok start = true (latched at the next step)");
    CHECK(m.is<Idle>());
    m.step(100ms);
    CHECK(m.is<Busy>());
    CHECK(m.context().count.get() == 1);
    CHECK(ask(view, "POST", "/command", "set count 5").body == "count is an output: only inputs can be set");
    CHECK(ask(view, "POST", "/command", "set start maybe").body == "'maybe' is not a value of start");
    CHECK(ask(view, "POST", "/command", "set steps 2").body == "steps is not an input channel: only inputs can be set");
    CHECK(ask(view, "POST", "/command", "set nothing 1").body == "no input is named 'nothing'");
    CHECK(ask(view, "POST", "/command", "set rate 1").status == 200);
    m.step(150ms);
    CHECK(m.context().rate.get() == speed::fast);
    CHECK(ask(view, "POST", "/command", "set mode 7").body == "'7' is not a value of mode");

    // Pause, single steps, resume.
    CHECK(view.may_step());
    CHECK(ask(view, "POST", "/command", "pause").body == "ok paused");
    CHECK(view.paused());
    CHECK_FALSE(view.may_step());
    CHECK(ask(view, "POST", "/command", "step").body == "ok one step");
    CHECK(ask(view, "POST", "/command", "step").body == "ok one step");
    CHECK(view.may_step());
    CHECK(view.may_step());
    CHECK_FALSE(view.may_step());
    CHECK(ask(view, "GET", "/info").body.find(R"("paused": true)") != std::string::npos);
    CHECK(ask(view, "POST", "/command", "resume").body == "ok running");
    CHECK(view.may_step());

    // An event by name; an unknown one; a command from another origin.
    auto const dispatched = ask(view, "POST", "/command", "dispatch stop");
    CHECK(dispatched.body == "ok stop: consumed");
    CHECK(m.is<Idle>());
    CHECK(ask(view, "POST", "/command", "dispatch go").status == 400);
    auto const foreign = ask(view, "POST", "/command", "dispatch stop",
                             {.origin = "http://example.com", .host = {}, .as_page = true});
    CHECK(foreign.status == 403);
    CHECK(foreign.body == "a command from another origin is refused");
    // What another site's page can send without asking first: no custom header; or its origin
    // hidden (a sandboxed frame's "null").
    CHECK(ask(view, "POST", "/command", "dispatch stop", {.origin = {}, .host = {}, .as_page = false}).status == 403);
    CHECK(ask(view, "POST", "/command", "dispatch stop", {.origin = "null", .host = {}, .as_page = true}).status ==
          403);
    CHECK(ask(view, "POST", "/command", "resume",
              {.origin = "http://localhost:" + std::to_string(view.port()), .host = {}, .as_page = true})
              .status == 200);
    // A name that resolves here but is not this server's (DNS rebinding): nothing answered.
    auto const rebound = ask(view, "GET", "/trace?from=0", {},
                             {.origin = {}, .host = "attacker.example:80", .as_page = true});
    CHECK(rebound.status == 421);
    CHECK(rebound.body.empty() == false);
    CHECK(rebound.body.find('\xB5') == std::string::npos);
    CHECK(ask(view, "POST", "/command", "dance").status == 400);
    CHECK(ask(view, "GET", "/command").status == 405);
    CHECK(view.commands_run() == 14);  // not those refused before they ran: another origin, unknown, GET
    CHECK(log.find("set start true -> ok start = true (latched at the next step)\n") == 0);

    // The trace from where the page stopped reading: the dispatch and the transition it made.
    auto const more = ask(view, "GET", "/trace?from=" + header(trace, "X-Trace-End"));
    reader.feed(std::as_bytes(std::span{more.body}));
    std::string lines;
    while (auto r = reader.next()) lines += reader.describe(*r) + "\n";
    CHECK(lines.find("[150ms] dispatch stop\n[150ms] exit Busy\n[150ms] transition Busy -> Idle on stop (row 1)\n") !=
          std::string::npos);
    CHECK(reader.missing() == 0);
    // From past the end (a page that read an earlier, longer run): nothing, and the end to
    // start again from; never bytes beyond the history.
    auto const beyond = ask(view, "GET", "/trace?from=" + std::to_string(view.trace_end() + 1000));
    CHECK(beyond.status == 200);
    CHECK(beyond.body.empty());
    CHECK(header(beyond, "X-Trace-Start") == std::to_string(view.trace_end()));
    CHECK(header(beyond, "X-Trace-End") == std::to_string(view.trace_end()));

    // No files without a web root; nothing outside it.
    CHECK(ask(view, "GET", "/").status == 404);
    CHECK(ask(view, "GET", "/../secret").status == 404);
}

TEST_CASE("a read-only inspector refuses commands; a long run's history starts again at the dictionary") {
    using namespace inspector_test;
    std::array<std::byte, 1 << 12> storage{};
    bsc::trace_buffer buffer{storage};
    bsc::machine m{chart, io{}, bsc::observers{tracer{chart, buffer}}};
    bsc::inspector_options options;
    options.history_limit = 2000;
    bsc::inspector view{m, buffer, options};
    auto const refused = ask(view, "POST", "/command", "dispatch stop");
    CHECK(refused.status == 403);
    CHECK(refused.body == "this program does not accept commands: the view is read-only");
    CHECK(m.is<Idle>());
    CHECK(view.commands_run() == 0);

    for (int i = 0; i < 200; ++i) {
        m.step(i * 100ms);
        view.poll();
    }
    CHECK(buffer.dropped() == 0);
    auto const trace = ask(view, "GET", "/trace?from=0");
    std::size_t const start = std::stoul(header(trace, "X-Trace-Start"));
    CHECK(start > 0);
    CHECK(start + trace.body.size() == std::stoul(header(trace, "X-Trace-End")));
    CHECK(trace.body.size() <= 2000 + 1000);
    // A page that opens now starts at a hello: every name, then where the machine stands.
    REQUIRE(trace.body.size() > 2);
    CHECK(trace.body[0] == '\xB5');
    CHECK(trace.body[1] == '\x01');
    bsc::trace_reader reader;
    reader.feed(std::as_bytes(std::span{trace.body}));
    std::string configuration;
    while (auto r = reader.next())
        if (r->type == bsc::trace_record_type::configuration) configuration = reader.describe(*r);
    CHECK(reader.dictionary().chart == "Root");
    CHECK(reader.dictionary().states.size() == 4);
    CHECK(configuration.ends_with("] configuration Root Idle"));
    CHECK(reader.skipped_bytes() == 0);
    CHECK(reader.missing() == 0);
}
