#pragma once
// Runs the W3C SCXML IRP tests compiled by bsc-scxml (tests/scxml/w3c.py): each on both back ends,
// from its start until it halts, the delayed events brought due by the machine's clock. A test
// passes when the machine halts in the top-level final state `pass`.

#include <bsc/scxml.hpp>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace bsc_w3c {

// The longest a test may take, in the machine's time: the suite's delays are at most a few
// seconds. Time passes in 10 ms cycles, so that delays that differ by less still come due in
// their order.
inline constexpr auto horizon = std::chrono::seconds{20};
inline constexpr auto cycle = std::chrono::milliseconds{10};

template <class Machine, auto const& Chart>
std::string run_one() {
    Machine m{Chart};
    bsc::duration now{0};
    while (!m.halted() && now <= horizon) {
        m.step(now);
        now += cycle;
    }
    if (!m.halted()) return "never halted (" + std::string(m.active_states().joined()) + ")";
    if (!m.active_states().contains("pass")) return "halted in " + std::string(m.active_states().joined());
    return {};
}

class registry {
public:
    template <class Compiled, class Table, auto const& Chart>
    void add(char const* id) {
        tests_.push_back({id, &run_one<Compiled, Chart>, &run_one<Table, Chart>});
    }

    // Runs every test (or those named on the command line); prints one line per test and
    // back end that fails, and a summary; returns 1 if any failed.
    int run(int argc, char** argv) {
        int failures = 0;
        int ran = 0;
        for (auto const& t : tests_) {
            if (argc > 1) {
                bool named = false;
                for (int i = 1; i < argc; ++i) named = named || std::strcmp(argv[i], t.id) == 0;
                if (!named) continue;
            }
            ++ran;
            for (auto const& [backend, fn] : {std::pair{"compiled", &t.compiled}, std::pair{"table", &t.table}}) {
                std::string const problem = (*fn)();
                if (!problem.empty()) {
                    ++failures;
                    std::printf("test %s (%s back end): FAIL: %s\n", t.id, backend, problem.c_str());
                }
            }
        }
        std::printf("W3C SCXML IRP: %d documents run on both back ends, %d failures\n", ran, failures);
        return failures == 0 && ran > 0 ? 0 : 1;
    }

private:
    struct test {
        char const* id;
        std::string (*compiled)();
        std::string (*table)();
    };
    std::vector<test> tests_;
};

}  // namespace bsc_w3c
