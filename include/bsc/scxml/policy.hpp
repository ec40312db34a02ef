#pragma once
// bsc::scxml::policy: the machine policy of a chart compiled from an SCXML document.

#include <cstddef>

#include <bsc/policies.hpp>

namespace bsc::scxml {

/// SCXML's rules where bsc's default policy differs: an error.execution that no transition
/// takes is dropped (`rethrow_failures = false`: the machine reports outcome::failed and goes
/// on), and the queues are deeper, since documents raise and send freely.
struct policy : default_policy {
    static constexpr std::size_t queue_capacity = 32;
    static constexpr std::size_t deferred_capacity = 8;
    static constexpr std::size_t delayed_capacity = 32;
    static constexpr bool rethrow_failures = false;
};

}  // namespace bsc::scxml
