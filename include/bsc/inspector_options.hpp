#pragma once
// bsc::inspector_options: how a bsc::inspector or a bsc::system_inspector serves its page.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace bsc {

/// How an inspector serves.
struct inspector_options {
    std::uint16_t port = 0;  ///< the port on 127.0.0.1; 0: one the system picks (port() tells)
    bool commands = false;   ///< run the page's commands: dispatch, set, pause, resume, step
    /// The program asks may_step() before each step, so that the page may pause it and step it
    /// one step at a time (a scan loop).
    bool stepping = false;
    std::string web_root;  ///< the folder of the page's files (index.html, inspector.js, ...)
    /// The trace bytes kept for a page that opens later (for each actor of a system); past it
    /// the history starts again with the dictionary and the configuration written anew.
    std::size_t history_limit = std::size_t{64} << 20;
    /// Called after each command the page sent, with the command and the answer it got (the
    /// program's own log of what was done to it).
    std::function<void(std::string_view command, std::string_view answer)> on_command;
};

}  // namespace bsc
