// The trace stream (<bsc/trace.hpp>, <bsc/trace_buffer.hpp>, <bsc/trace_reader.hpp>): a machine
// traced on either back end reads back as the dictionary and the records of what it did; the
// ring drops whole frames when full and says so; a reader joins frames cut anywhere, skips damage
// and counts what was lost; and any bytes at all are safe to feed it.

#include <doctest/doctest.h>

#include <bsc/bsc.hpp>
#include <bsc/trace.hpp>
#include <bsc/trace_buffer.hpp>
#include <bsc/trace_reader.hpp>

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "backends.hpp"

namespace trace_test {

using namespace std::chrono_literals;

struct go {};
struct ping {};
struct job {
    int n = 0;
};
struct Root;
struct Idle;
struct Busy;
struct Done;
struct axis {
    double position = 0;
    std::int8_t direction = 0;
};
struct ctx {
    bsc::input<bool> ready;
    bsc::output<int> count{-1};
    axis x;
    bsc::timer dwell{300ms};
    int pings = 0;
};

// One transition of each kind of trigger: an event, a timeout, a condition, an internal
// transition, an event raised by an action, and a deferral.
inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>, bsc::state<Done>),
    bsc::state<Idle> + bsc::event<go> / bsc::raise(ping{}) = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<ping> /
                           [](ctx& c) {
                               ++c.pings;
                               c.count.set(3);
                               c.x.position = 0.5;
                               c.x.direction = -2;
                           },
    bsc::state<Busy> + bsc::event<job> / bsc::defer, bsc::state<Busy> + bsc::after(1500ms) = bsc::state<Done>,
    bsc::state<Done>[([](ctx const& c) { return c.ready.get(); })] = bsc::state<Idle>,
    bsc::state<Idle> + bsc::event<job> / [](ctx& c) { ++c.pings; });

template <class Backend>
using traced_machine = bsc_test::machine_t<Backend, decltype(chart), bsc::scan_policy, bsc::tracer<decltype(chart)>>;

// Everything the buffer holds, drained in pieces of `piece` bytes into a reader, as lines.
inline std::vector<std::string> read_all(bsc::trace_buffer& buffer, bsc::trace_reader& reader, std::size_t piece) {
    std::vector<std::string> lines;
    std::vector<std::byte> chunk(piece);
    while (std::size_t n = buffer.read(chunk)) {
        reader.feed(std::span{chunk}.first(n));
        while (auto r = reader.next()) lines.push_back(reader.describe(*r));
    }
    return lines;
}

inline std::vector<std::byte> drain(bsc::trace_buffer& buffer) {
    std::vector<std::byte> bytes(buffer.size());
    bytes.resize(buffer.read(bytes));
    return bytes;
}

// Two events of the same name in two namespaces: rows and transitions number them by type.
namespace a {
struct press {};
}  // namespace a
namespace b {
struct press {};
}  // namespace b
inline constexpr auto twins = bsc::make_chart<int>(bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
                                                   bsc::state<Idle> + bsc::event<a::press> = bsc::state<Busy>,
                                                   bsc::state<Busy> + bsc::event<b::press> = bsc::state<Idle>);

}  // namespace trace_test

using bsc_test::compiled;
using bsc_test::table;

TEST_CASE_TEMPLATE("a traced machine reads back as its dictionary and what it did, in order", Backend, compiled,
                   table) {
    using namespace trace_test;
    std::array<std::byte, 4096> storage{};
    bsc::trace_buffer buffer{storage};
    traced_machine<Backend> m{chart, ctx{}, bsc::tracer<decltype(chart)>{chart, buffer}};
    m.step(0ms);
    m.observer().sample(m);
    m.step(250ms);
    m.dispatch(go{});
    m.dispatch(job{});
    m.observer().sample(m);
    m.observer().sample(m);  // nothing changed: no values record
    m.step(1750ms);
    m.context().ready.set(true);
    m.step(2s);
    m.observer().sample(m);

    bsc::trace_reader reader;
    auto const lines = read_all(buffer, reader, 7);
    std::vector<std::string> const expected{
        "[0s] chart Root",
        "[0s] state 0 (top)",
        "[0s] state 1 Root",
        "[0s] state 2 Idle",
        "[0s] state 3 Busy",
        "[0s] state 4 Done",
        "[0s] event 0 go",
        "[0s] event 1 ping",
        "[0s] event 2 job",
        "[0s] row 0 Idle -> Busy : go / action",
        "[0s] row 1 Busy -> internal : ping / action",
        "[0s] row 2 Busy -> internal : job / defer",
        "[0s] row 3 Busy -> Done : after(1500ms)",
        "[0s] row 4 Done -> Idle : [guard]",
        "[0s] row 5 Idle -> internal : job / action",
        "[0s] entry Root",  // the construction enters
        "[0s] entry Idle",
        "[0s] cycle",
        "[0s] cycle end",
        "[0s] member 0 ready",
        "[0s] member 1 count",
        "[0s] member 2 x.position",
        "[0s] member 3 x.direction",
        "[0s] member 4 dwell.running",
        "[0s] member 5 dwell.expired",
        "[0s] member 6 dwell.elapsed",
        "[0s] member 7 pings",
        "[0s] values ready=false count=-1 x.position=0 x.direction=0 dwell.running=false dwell.expired=false "
        "dwell.elapsed=0 pings=0",
        "[250ms] cycle",
        "[250ms] cycle end",
        "[250ms] dispatch go",
        "[250ms] exit Idle",
        "[250ms] transition Idle -> Busy on go (row 0)",
        "[250ms] entry Busy",
        "[250ms] transition Busy -> internal on ping (row 1)",
        "[250ms] dispatch job",
        "[250ms] defer job in Busy",
        "[250ms] values count=3 x.position=0.5 x.direction=-2 pings=1",
        "[1750ms] cycle",
        "[1750ms] exit Busy",
        "[1750ms] transition Busy -> Done on after(1500ms) (row 3)",
        "[1750ms] entry Done",
        "[1750ms] cycle end",
        "[2s] cycle",
        "[2s] exit Done",
        "[2s] transition Done -> Idle on condition (row 4)",
        "[2s] entry Idle",
        "[2s] cycle end",
        "[2s] values ready=true",  // the deferred job was retried in Done, which takes none

    };
    CHECK(lines == expected);
    CHECK(reader.frames() == lines.size());
    CHECK(reader.missing() == 0);
    CHECK(reader.skipped_bytes() == 0);
    CHECK(reader.malformed() == 0);
    CHECK(buffer.dropped() == 0);
    CHECK(buffer.written() == lines.size());
    auto const& d = reader.dictionary();
    CHECK(d.version == 1);
    CHECK(d.states.size() == 5);
    CHECK(d.states[2].parent == 1);
    CHECK(d.states[1].kind == 3);   // composite
    CHECK(d.members[2].kind == 3);  // real
}

TEST_CASE("the dictionary is written again on request, with the configuration, the members at the next sample") {
    using namespace trace_test;
    std::array<std::byte, 4096> storage{};
    bsc::trace_buffer buffer{storage};
    traced_machine<compiled> m{chart, ctx{}, bsc::tracer{chart, buffer}};
    m.step(0ms);
    m.observer().sample(m);
    (void)drain(buffer);
    m.dispatch(go{});  // Busy
    (void)drain(buffer);
    m.observer().write_dictionary(m);
    m.observer().sample(m);
    // A reader that joins now learns every name and where the machine stands, and the sample
    // gives every value again.
    bsc::trace_reader reader;
    auto const lines = read_all(buffer, reader, 4096);
    REQUIRE(lines.size() == 15 + 1 + 8 + 1);
    CHECK(lines[15] == "[0s] configuration Root Busy");
    CAPTURE(lines.back());
    CHECK(lines.back().starts_with("[0s] values ready=false count=3 x.position=0.5"));
    CHECK(lines.back().ends_with(" pings=1"));
    bsc::trace_reader again;
    again.feed(std::as_bytes(std::span{lines.front()}));  // not a frame: skipped, nothing read
    CHECK_FALSE(again.next().has_value());
    CHECK(reader.dictionary().members.size() == 8);
    CHECK(reader.dictionary().events.size() == 3);
    REQUIRE(reader.dictionary().rows.size() == 6);
    CHECK(reader.dictionary().rows[3].label == "after(1500ms)");
    CHECK(reader.dictionary().rows[3].trigger == 0xFFFD);
    CHECK(reader.dictionary().rows[2].flags == 1);  // defers
    CHECK(reader.dictionary().rows[2].trigger == 2);
    CHECK(reader.missing() == 0);  // the reader's first frame sets its count
}

TEST_CASE("a full ring drops whole frames, counts them, and says so when room returns") {
    using namespace trace_test;
    std::array<std::byte, 360> storage{};
    bsc::trace_buffer buffer{storage};
    // The dictionary (hello 18, states 81, events 36, rows 163 bytes) and the entries of Root
    // and Idle (9 each).
    traced_machine<compiled> m{chart, ctx{}, bsc::tracer{chart, buffer}};
    CHECK(buffer.size() == 316);
    m.step(0ms);    // cycle 15 and cycle end 7 bytes: 338
    m.step(100ms);  // 360: full
    CHECK(buffer.size() == 360);
    CHECK(buffer.dropped() == 0);
    m.step(200ms);  // both dropped
    m.step(300ms);
    CHECK(buffer.size() == 360);
    CHECK(buffer.dropped() == 4);
    bsc::trace_reader reader;
    auto lines = read_all(buffer, reader, 64);
    CHECK(lines.size() == 21);
    CHECK(reader.missing() == 0);  // nothing read after the drops yet
    m.step(400ms);                 // room again: the overflow record first
    lines = read_all(buffer, reader, 64);
    REQUIRE(lines.size() == 3);
    CHECK(lines[0] == "[100ms] overflow: 4 frames dropped");
    CHECK(lines[1] == "[400ms] cycle");
    CHECK(lines[2] == "[400ms] cycle end");
    CHECK(reader.missing() == 4);  // the reader sees the drops as a gap in the sequence numbers
    CHECK(buffer.written() == 24);

    // Lap after lap around a ring whose size divides nothing: every frame read back whole.
    {
        std::array<std::byte, 97> small{};
        bsc::trace_buffer ring{small};
        bsc::trace_reader laps;
        std::array<std::byte, 13> out{};
        std::size_t frames = 0;
        for (int i = 0; i < 5000; ++i) {
            std::array<std::byte, 9> payload{};
            payload[0] = static_cast<std::byte>(i);
            REQUIRE(ring.write(bsc::trace_record_type::cycle_end,
                               std::span{payload}.first(static_cast<std::size_t>(i % 10))));
            while (std::size_t const n = ring.read(out)) laps.feed(std::span{out}.first(n));
            while (laps.next()) ++frames;
        }
        CHECK(laps.frames() == 5000);
        CHECK(laps.malformed() == 5000 - 500);  // a cycle end has no payload: only those of length 0 fit
        CHECK(frames == 500);
        CHECK(laps.missing() == 0);
        CHECK(laps.skipped_bytes() == 0);
    }

    // A frame longer than the storage is always dropped; a buffer without storage drops everything.
    bsc::trace_buffer empty{std::span<std::byte>{}};
    CHECK_FALSE(empty.write(bsc::trace_record_type::cycle_end, {}));
    CHECK(empty.dropped() == 1);
    CHECK(empty.size() == 0);
}

TEST_CASE("a reader joins frames cut anywhere, resynchronises after damage and counts the loss") {
    using namespace trace_test;
    std::array<std::byte, 4096> storage{};
    bsc::trace_buffer buffer{storage};
    traced_machine<compiled> m{chart, ctx{}, bsc::tracer{chart, buffer}};
    m.step(0ms);
    m.dispatch(go{});
    m.step(2s);
    auto const bytes = drain(buffer);

    bsc::trace_reader whole;
    whole.feed(bytes);
    std::vector<std::string> reference;
    while (auto r = whole.next()) reference.push_back(whole.describe(*r));
    REQUIRE(reference.size() == 29);

    bsc::trace_reader bytewise;
    std::vector<std::string> lines;
    for (std::byte b : bytes) {
        bytewise.feed(std::span{&b, 1});
        while (auto r = bytewise.next()) lines.push_back(bytewise.describe(*r));
    }
    CHECK(lines == reference);

    // A damaged byte loses its frame only: the reader skips to the next sync byte.
    for (std::size_t at : {std::size_t{20}, bytes.size() / 2}) {
        auto damaged = bytes;
        damaged[at] ^= std::byte{0x40};
        bsc::trace_reader reader;
        reader.feed(damaged);
        std::size_t n = 0;
        while (reader.next()) ++n;
        CAPTURE(at);
        CHECK(n == reference.size() - 1);
        CHECK(reader.skipped_bytes() > 0);
        CHECK(reader.missing() == 1);
    }

    // A damaged length near the end: the frame it announces cannot end within the stream. The
    // reader waits for bytes that will not come, until told the stream is whole.
    {
        auto damaged = bytes;
        std::size_t const at = bytes.size() - 7 - 9 + 4;  // the length of the last frame but one (entry Done)
        damaged[at] = std::byte{0xF0};
        bsc::trace_reader reader;
        reader.feed(damaged);
        std::size_t n = 0;
        while (reader.next()) ++n;
        CHECK(n == reference.size() - 2);
        reader.finish();
        while (reader.next()) ++n;
        CHECK(n == reference.size() - 1);  // the last frame read after all
        CHECK(reader.missing() == 1);
    }

    // A stream cut short reads as its whole frames: the last, cut, waits for the rest.
    bsc::trace_reader cut;
    cut.feed(std::span{bytes}.first(bytes.size() - 3));
    std::size_t n = 0;
    while (cut.next()) ++n;
    CHECK(n == reference.size() - 1);
    CHECK(cut.skipped_bytes() == 0);
}

TEST_CASE("any bytes are safe to feed a reader: random input, and a real stream mutated") {
    using namespace trace_test;
    std::array<std::byte, 4096> storage{};
    bsc::trace_buffer buffer{storage};
    traced_machine<compiled> m{chart, ctx{}, bsc::tracer{chart, buffer}};
    m.step(0ms);
    m.observer().sample(m);
    m.dispatch(go{});
    m.dispatch(job{});
    m.step(2s);
    m.observer().sample(m);
    auto const bytes = drain(buffer);

    std::mt19937 random{20261128};
    std::uniform_int_distribution<int> byte_value{0, 255};
    for (int round = 0; round < 2000; ++round) {
        std::vector<std::byte> input;
        if (round % 2 == 0) {
            // Random bytes, sync bytes made common so that frames start often.
            input.resize(static_cast<std::size_t>(byte_value(random)) * 4);
            for (auto& b : input) b = random() % 4 == 0 ? std::byte{0xB5} : static_cast<std::byte>(byte_value(random));
        } else {
            // The real stream with a few bytes changed, cut or repeated.
            input = bytes;
            for (int k = 0; k < 1 + round % 5; ++k) {
                std::size_t const at = random() % input.size();
                switch (random() % 3) {
                    case 0: input[at] = static_cast<std::byte>(byte_value(random)); break;
                    case 1: input.erase(input.begin() + static_cast<std::ptrdiff_t>(at)); break;
                    default: input.insert(input.begin() + static_cast<std::ptrdiff_t>(at), input[at]); break;
                }
            }
        }
        bsc::trace_reader reader;
        std::size_t records = 0;
        for (std::size_t at = 0; at < input.size();) {
            std::size_t const n = std::min<std::size_t>(1 + random() % 40, input.size() - at);
            reader.feed(std::span{input}.subspan(at, n));
            at += n;
            while (auto r = reader.next()) {
                (void)reader.describe(*r);
                ++records;
            }
        }
        CHECK(records + reader.malformed() == reader.frames());
        CHECK(reader.frames() * 7 + reader.skipped_bytes() <= input.size());
    }
}

TEST_CASE("a row's trigger is numbered by its event's type, as the transition records number it") {
    using namespace trace_test;
    std::array<std::byte, 1024> storage{};
    bsc::trace_buffer buffer{storage};
    bsc::machine m{twins, 0, bsc::tracer{twins, buffer}};
    m.dispatch(a::press{});
    m.dispatch(b::press{});
    bsc::trace_reader reader;
    reader.feed(drain(buffer));
    std::vector<std::uint16_t> fired;
    while (auto r = reader.next())
        if (r->type == bsc::trace_record_type::transition) fired.push_back(r->event);
    auto const& d = reader.dictionary();
    REQUIRE(d.rows.size() == 2);
    CHECK(d.rows[0].trigger == 0);
    CHECK(d.rows[1].trigger == 1);
    CHECK(fired == std::vector<std::uint16_t>{0, 1});
}
