// EXPECT: backend_hooks::exit_all\(b\)[^ ]* (is|would be) invalid
// A back end of the driver that lacks a hook (here exit_all) fails where the machine is built,
// at the driver's check of the contract (detail/runtime/backend.hpp), naming machine_backend.
#include "two_states.hpp"

namespace cf {
// A back end that fires nothing: enough to show which hooks the driver needs.
template <class Chart>
class toy : public bsc::detail::driver<toy<Chart>, Chart, bsc::default_policy, bsc::no_observer,
                                       bsc::detail::queue_for<Chart, bsc::default_policy>> {
    using base = bsc::detail::driver<toy, Chart, bsc::default_policy, bsc::no_observer,
                                     bsc::detail::queue_for<Chart, bsc::default_policy>>;
    friend base;  // the driver's layers that call the hooks, and backend_hooks
    friend bsc::detail::backend_hooks;
    template <class, class, class, class, class>
    friend class bsc::detail::settling;
    template <class, class, class, class, class>
    friend class bsc::detail::deferral;
    template <class, class, class, class, class>
    friend class bsc::detail::done_raising;
    static constexpr bool marks_running_lazily = false;
    constexpr void enter_initial() {}
    template <int Trigger, class E>
    constexpr bool fire(E const&) {
        return false;
    }
    template <int Trigger, class E>
    constexpr bool fire_dispatched(E const&) {
        return false;
    }
    template <int Component>
    constexpr bool component_step() {
        return false;
    }
    template <int S>
    constexpr bool is_active() const {
        return S == 0;
    }

public:
    constexpr explicit toy(Chart const& chart) : base(chart, {}, {}) { this->start(); }
};
}  // namespace cf

int main() {
    cf::toy<decltype(cf::chart)> m{cf::chart};
    return m.dispatch(cf::go{}) == bsc::outcome::ignored ? 0 : 1;
}
