#pragma once
// A test observer that records entries, exits and transitions as one readable string.

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

}  // namespace bsc_test
