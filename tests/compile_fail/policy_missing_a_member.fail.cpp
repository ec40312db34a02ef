// EXPECT: (does not satisfy 'machine_policy'|the required expression [^ ]*Policy::max_eventless_steps[^ ]* is invalid)
// A policy written from scratch that lacks a member of bsc::default_policy (here everything but
// queue_capacity) fails where the machine is declared, naming the concept bsc::machine_policy.
#include "two_states.hpp"

namespace cf {
struct limits {
    static constexpr std::size_t queue_capacity = 4;
};
}  // namespace cf

int main() {
    bsc::table::machine<decltype(cf::chart), cf::limits> m{cf::chart};
    return m.is<cf::Idle>() ? 0 : 1;
}
