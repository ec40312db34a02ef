// Twin of policy_missing_a_member.fail.cpp: the policy derives from bsc::default_policy and
// overrides the one member it changes.
#include "two_states.hpp"

namespace cf {
struct limits : bsc::default_policy {
    static constexpr std::size_t queue_capacity = 4;
};
}  // namespace cf

int main() {
    bsc::table::machine<decltype(cf::chart), cf::limits> m{cf::chart};
    return m.is<cf::Idle>() ? 0 : 1;
}
