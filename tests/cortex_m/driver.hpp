#pragma once
// The driver shared by the programs of tests/cortex_m/: the same source runs on the host and,
// built by tests/cortex_m/CMakeLists.txt, on a Cortex-M4 under QEMU.
//
//   PROGRAM        the trace: the observation after each event (each scan cycle) of a fixed
//                  sequence, one line each; scripts/cortex_m.py compares it with the host's
//   PROGRAM N      N events (cycles) of the same sequence, then one line with a checksum of
//                  what was observed: scripts/cortex_m.py counts the instructions of N and of 0
//
// A program is one implementation of one chart: the machine (or the hand-written controller)
// is a global named `subject`, whose size is the RAM the report gives; an adapter tells the
// driver how to give it an event and what to observe.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "console.hpp"

namespace cm {

/// A line of text written to the console when it ends (no formatted output on the target).
class line {
public:
    line& operator<<(std::string_view s) {
        for (char c : s) put(c);
        return *this;
    }
    line& operator<<(char const* s) {
        while (*s != '\0') put(*s++);  // not through strlen, which newlib aligns to 64 bytes
        return *this;
    }
    line& operator<<(std::uint32_t n) {
        char digits[10];
        int count = 0;
        do {
            digits[count++] = static_cast<char>('0' + n % 10);
            n /= 10;
        } while (n != 0);
        while (count > 0) put(digits[--count]);
        return *this;
    }
    line& operator<<(char c) {
        put(c);
        return *this;
    }
    void end() {
        put('\n');
        text_[size_] = '\0';
        write(text_);
        size_ = 0;
    }

private:
    void put(char c) {
        if (size_ < capacity) text_[size_++] = c;
    }
    static constexpr std::size_t capacity = 94;
    char text_[capacity + 2];
    std::size_t size_ = 0;
};

/// The number of events to count, from the command line: false when there is none (a trace).
inline bool events_to_count(int argc, char** argv, std::uint32_t& n) {
    if (argc < 2) return false;
    n = 0;
    for (char const* p = argv[1]; *p >= '0' && *p <= '9'; ++p) n = n * 10 + static_cast<std::uint32_t>(*p - '0');
    return true;
}

/// Events are small integers, as they reach a controller from a queue or a fieldbus; the
/// workload records a fixed sequence of them (sequence_length, a power of two, so that the
/// count loop wraps around with a mask rather than a division).
inline constexpr std::size_t sequence_length = 1024;
inline std::uint8_t sequence[sequence_length];

/// Runs an event-driven workload: Workload records the sequence (record), says how many events
/// the trace holds (trace_events), prints an observation and reduces it to a checksum; Adapter
/// gives the subject an event (on) and observes it (observe).
template <class Workload, class Adapter>
int run_events(int argc, char** argv) {
    Workload::record(sequence);
    std::uint32_t n = Workload::trace_events;
    bool const counting = events_to_count(argc, argv, n);
    line out;
    if (!counting) {
        out << "initial ";
        Workload::print(out, Adapter::observe());
        out.end();
    }
    // One loop for both modes, so that the subject's code is inlined (or called) from one place
    // only and the image holds it once.
    for (std::uint32_t i = 0; i < n; ++i) {
        Adapter::on(sequence[i & (sequence_length - 1)]);
        if (!counting) {
            Workload::print(out, Adapter::observe());
            out.end();
        }
    }
    if (counting) {
        out << "events " << n << " checksum " << Workload::checksum(Adapter::observe());
        out.end();
    }
    return 0;
}

}  // namespace cm
