#pragma once
// Traces as one readable string: a test observer that records entries, exits and transitions,
// and an action that appends a word to the context's own `log`.

#include <string>
#include <string_view>

#include <bsc/bsc.hpp>

namespace bsc_test {

struct trace_observer {
    std::string* log;
    void put(std::string_view s) const {
        if (!log->empty()) *log += ' ';
        *log += s;
    }
    void on_entry(auto state) const { put("+" + std::string(state.name)); }
    void on_exit(auto state) const { put("-" + std::string(state.name)); }
    void on_transition(auto source, auto target, auto const&) const {
        put(std::string(source.name) + ">" + std::string(target.name));
    }
};

// `log_action<ctx>("enter A")`: an action that appends the word to `ctx::log`, a std::string,
// separated by a space.
template <class Ctx>
inline constexpr auto log_action = [](char const* what) {
    return bsc::action([what](Ctx& c) {
        if (!c.log.empty()) c.log += ' ';
        c.log += what;
    });
};

}  // namespace bsc_test
