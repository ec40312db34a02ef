#pragma once
// Instructions of a piece of code, counted by callgrind when the program runs under it
// (valgrind --tool=callgrind): the counts are zeroed before the code, dumped after it, and the
// dump (a file callgrind writes as the request returns) read back and removed. Without
// valgrind's headers, or outside valgrind, nothing is counted.

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>

#if __has_include(<valgrind/callgrind.h>) && __has_include(<unistd.h>)
#include <unistd.h>
#include <valgrind/callgrind.h>
#define BSC_DETAIL_HAS_CALLGRIND 1
#else
#define BSC_DETAIL_HAS_CALLGRIND 0
#endif

namespace bsc::detail {

class callgrind_counter {
public:
    // `out_file`: callgrind's --callgrind-out-file, where %p stands for the process id; dump k
    // goes to that name followed by ".k".
    explicit callgrind_counter(std::string out_file) : prefix_(expand(out_file)) {}

    // Whether the program runs under valgrind (and the counts can be read).
    static bool available() {
#if BSC_DETAIL_HAS_CALLGRIND
        return RUNNING_ON_VALGRIND != 0;
#else
        return false;
#endif
    }

    // The instructions `run()` executes, less the requests' own; nothing if callgrind's dump
    // cannot be read (another tool, another output file).
    template <class F>
    std::optional<std::uint64_t> count(F&& run) {
        auto const measured = raw(run);
        if (!overhead_) overhead_ = raw([] {});
        if (!measured || !overhead_) return std::nullopt;
        return *measured > *overhead_ ? *measured - *overhead_ : 0;
    }

private:
    template <class F>
    std::optional<std::uint64_t> raw([[maybe_unused]] F&& run) {
#if BSC_DETAIL_HAS_CALLGRIND
        if (!available()) return std::nullopt;
        CALLGRIND_ZERO_STATS;
        run();
        CALLGRIND_DUMP_STATS_AT("bsc latency");
        // Callgrind numbers a process's dumps from 1, whoever asks for them (the program itself,
        // callgrind_control, --dump-every-bb): this one is the first after the last one read
        // that says it is ours. A file that is not ours is left as it is.
        for (unsigned k = dumps() + 1;; ++k) {
            dump const d = read(prefix_ + "." + std::to_string(k));
            if (!d.exists) return std::nullopt;
            if (d.ours) {
                dumps() = k;
                return d.total;
            }
        }
#else
        return std::nullopt;
#endif
    }

    struct dump {
        bool exists = false;
        bool ours = false;  // its description is our request's
        std::optional<std::uint64_t> total;
    };

    // "totals: N" (or "summary: N"), the first event of which is the instructions (Ir). A dump
    // of ours is removed once read.
    static dump read(std::string const& path) {
        dump d;
        std::FILE* f = std::fopen(path.c_str(), "r");
        if (!f) return d;
        d.exists = true;
        char line[512];
        while (std::fgets(line, sizeof line, f)) {
            unsigned long long n = 0;
            if (std::strncmp(line, "desc: Trigger: Client Request: bsc latency", 42) == 0) d.ours = true;
            if (std::sscanf(line, "totals: %llu", &n) == 1 || std::sscanf(line, "summary: %llu", &n) == 1)
                d.total = static_cast<std::uint64_t>(n);
        }
        std::fclose(f);
        if (d.ours) std::remove(path.c_str());
        return d;
    }

    static std::string expand(std::string const& pattern) {
        std::string out;
        for (std::size_t i = 0; i < pattern.size(); ++i) {
            if (pattern[i] == '%' && i + 1 < pattern.size() && pattern[i + 1] == 'p') {
#if BSC_DETAIL_HAS_CALLGRIND
                out += std::to_string(static_cast<long long>(::getpid()));
#endif
                ++i;
            } else {
                out += pattern[i];
            }
        }
        return out;
    }

    // Callgrind numbers the dumps of a process from 1, whoever asks for them.
    static unsigned& dumps() {
        static unsigned count = 0;
        return count;
    }

    std::string prefix_;
    std::optional<std::uint64_t> overhead_;
};

}  // namespace bsc::detail
