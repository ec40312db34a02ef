#pragma once
// The harness shared by the dispatch benchmarks (bench/<workload>/*.cpp).
//
// A workload is a chart plus a recorded sequence of events. Events are recorded as small
// integers (the index of the event type), the way events reach a controller from a queue, a
// fieldbus or an operator panel; every implementation turns an index into its own event type
// with the same `switch` (bench::with_index) and processes it.
//
// An implementation is a class with
//     void on(std::uint8_t event);                         // process one event to completion
//     typename Workload::observation observe() const;      // what it did so far
// constructed in the chart's initial configuration. BENCH_IMPL(workload, "name", Impl)
// registers it: as a Google Benchmark ("<workload>/<name>") that replays the recorded
// sequence, and for the equivalence check. Before the first timing, every registered
// implementation of the workload is run over the whole sequence and observed after every
// event; any difference from the hand-written implementation aborts the program.
//
// A Workload type has `static constexpr char const* name`, `struct observation` (with ==),
// `static std::string describe(observation const&)` and `static std::vector<std::uint8_t>
// record()` (the sequence, from a fixed seed).
//
// This header and the workload headers are C++17: Boost.MSM 1.74 does not compile as C++20
// (bench/CMakeLists.txt), so its translation units are built as C++17.

#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace bench {

using sequence = std::vector<std::uint8_t>;

/// Calls f(std::integral_constant<std::size_t, I>{}) for I == i, I < N. The chain of
/// comparisons over a dense range compiles to a jump table (GCC and Clang), as a switch would.
// Always inlined, so that an implementation's on() holds the switch, as the hand-written one's
// does, and the event reaches the machine without a closure built on the stack.
template <class F, std::size_t... I>
[[gnu::always_inline]] inline void with_index_impl(std::size_t i, F& f, std::index_sequence<I...>) {
    (void)((i == I ? (f(std::integral_constant<std::size_t, I>{}), true) : false) || ...);
}
template <std::size_t N, class F>
[[gnu::always_inline]] inline void with_index(std::size_t i, F&& f) {
    with_index_impl(i, f, std::make_index_sequence<N>{});
}

/// A small deterministic generator (xorshift64*), so that every run of every build replays
/// the same events.
struct rng {
    std::uint64_t s;
    explicit rng(std::uint64_t seed) : s(seed * 0x9E3779B97F4A7C15ull + 1) {}
    std::uint64_t next() {
        s ^= s >> 12;
        s ^= s << 25;
        s ^= s >> 27;
        return s * 0x2545F4914F6CDD1Dull;
    }
    std::size_t below(std::size_t n) { return static_cast<std::size_t>((next() >> 33) % n); }
};

[[noreturn]] inline void fail(char const* workload, char const* what) {
    std::fprintf(stderr, "bench %s: %s\n", workload, what);
    std::abort();
}

template <class W>
struct registry {
    using observation = typename W::observation;
    struct entry {
        std::string name;
        std::vector<observation> (*trace)(sequence const&);  // observed after every event
        std::uint64_t (*run)(sequence const&, std::size_t);  // n events, for the instruction counts
    };
    static std::vector<entry>& entries() {
        static std::vector<entry> e;
        return e;
    }
    static sequence const& recorded() {
        static sequence const s = W::record();
        return s;
    }
    /// The recorded sequence, once every implementation has been found equivalent on it.
    static sequence const& checked() {
        static bool const ok = [] {
            auto const& seq = recorded();
            entry const* reference = nullptr;
            for (auto const& e : entries())
                if (e.name == "hand_written") reference = &e;
            if (!reference) fail(W::name, "no hand-written implementation registered");
            auto const expected = reference->trace(seq);
            for (auto const& e : entries()) {
                auto const got = e.trace(seq);
                for (std::size_t i = 0; i < seq.size(); ++i) {
                    if (!(got[i] == expected[i])) {
                        std::fprintf(stderr,
                                     "bench %s: %s differs from hand_written after event %zu (event index %u)\n"
                                     "  hand_written: %s\n  %s: %s\n",
                                     W::name, e.name.c_str(), i, unsigned(seq[i]), W::describe(expected[i]).c_str(),
                                     e.name.c_str(), W::describe(got[i]).c_str());
                        std::abort();
                    }
                }
            }
            return true;
        }();
        (void)ok;
        return recorded();
    }
};

template <class W, class Impl>
std::vector<typename W::observation> trace_of(sequence const& seq) {
    std::vector<typename W::observation> out;
    out.reserve(seq.size());
    auto m = std::make_unique<Impl>();
    for (std::uint8_t e : seq) {
        m->on(e);
        out.push_back(m->observe());
    }
    return out;
}

template <class W, class Impl>
std::uint64_t run_events(sequence const& seq, std::size_t n) {
    auto m = std::make_unique<Impl>();
    for (std::size_t i = 0; i < n; ++i) m->on(seq[i % seq.size()]);
    return std::hash<std::string>{}(W::describe(m->observe()));
}

// Each iteration replays the whole sequence on one machine that lives across iterations (the
// sequence is a random walk, so where one replay ends is as good a start as any): no
// construction, copy or allocation of a machine is timed.
template <class W, class Impl>
void timed(benchmark::State& state) {
    auto const& seq = registry<W>::checked();
    auto m = std::make_unique<Impl>();
    std::uint8_t const* const first = seq.data();
    std::uint8_t const* const last = first + seq.size();
    for (auto _ : state) {
        for (std::uint8_t const* p = first; p != last; ++p) m->on(*p);
        benchmark::ClobberMemory();
    }
    auto* raw = m.get();
    benchmark::DoNotOptimize(raw);
    auto const events = static_cast<double>(seq.size()) * static_cast<double>(state.iterations());
    state.SetItemsProcessed(static_cast<std::int64_t>(events));
    state.counters["events"] = static_cast<double>(seq.size());
}

template <class W, class Impl>
bool register_impl(char const* name) {
    registry<W>::entries().push_back({name, &trace_of<W, Impl>, &run_events<W, Impl>});
    benchmark::RegisterBenchmark((std::string(W::name) + "/" + name).c_str(), &timed<W, Impl>)
        ->Unit(benchmark::kMicrosecond);
    return true;
}

/// The driver of the instruction counts (bench/insns_main.cpp): runs `n` events of workload W
/// on the implementation `name`, prints a checksum of what it observed.
template <class W>
int drive(int argc, char** argv) {
    bool const asked = argc == 2 && (std::string_view{argv[1]} == "--help" || std::string_view{argv[1]} == "-h");
    if (argc != 3 || asked || argv[1][0] == '-') {  // a flag other than --help is unknown
        std::FILE* const to = asked ? stdout : stderr;
        std::fprintf(to,
                     "usage: %s IMPLEMENTATION EVENTS\n"
                     "Runs EVENTS events of the %s workload on IMPLEMENTATION and prints a checksum of what it\n"
                     "observed (no flags, no defaults: both arguments are required).\n"
                     "  -h, --help  print this text and exit\n"
                     "IMPLEMENTATION is one of:\n",
                     argv[0], W::name);
        for (auto const& e : registry<W>::entries()) std::fprintf(to, "  %s\n", e.name.c_str());
        return asked ? 0 : 2;
    }
    std::size_t const n = std::strtoull(argv[2], nullptr, 10);
    for (auto const& e : registry<W>::entries()) {
        if (e.name == argv[1]) {
            std::printf("%s %s %zu %llx\n", W::name, argv[1], n,
                        static_cast<unsigned long long>(e.run(registry<W>::recorded(), n)));
            return 0;
        }
    }
    std::fprintf(stderr, "%s: no implementation %s\n", argv[0], argv[1]);
    return 2;
}

}  // namespace bench

#define BENCH_CAT2(a, b) a##b
#define BENCH_CAT(a, b) BENCH_CAT2(a, b)
/// Registers implementation Impl of workload W under `name` (one line per implementation).
#define BENCH_IMPL(W, name, ...)                                    \
    [[maybe_unused]] static bool const BENCH_CAT(bench_registered_, \
                                                 __LINE__) = ::bench::register_impl<W, __VA_ARGS__>(name)
