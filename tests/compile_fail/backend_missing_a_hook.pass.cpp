// Twin of backend_missing_a_hook.fail.cpp: the back end supplies every hook.
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
    constexpr void exit_all() {}

public:
    constexpr explicit toy(Chart const& chart) : base(chart, {}, {}) { this->start(); }
};
}  // namespace cf

int main() {
    cf::toy<decltype(cf::chart)> m{cf::chart};
    return m.dispatch(cf::go{}) == bsc::outcome::ignored ? 0 : 1;
}
