// The explorer from the single header verify.hpp alone (it includes bsc.hpp beside it): every
// state of a turnstile is reachable, and Locked is reachable from every state.
#include <bsc/verify.hpp>

#include <cstdio>

namespace turnstile {
struct coin {};
struct push {};
struct Turnstile;
struct Locked;
struct Unlocked;
struct nothing {};
inline constexpr auto chart = bsc::make_chart<nothing>(
    bsc::composite<Turnstile>(bsc::initial<Locked>, bsc::state<Unlocked>),
    bsc::state<Locked> + bsc::event<coin> = bsc::state<Unlocked>,
    bsc::state<Unlocked> + bsc::event<push> = bsc::state<Locked>);
using machine = bsc::machine<decltype(chart)>;
}  // namespace turnstile

int main() {
    bsc::verify::event_model<turnstile::machine, turnstile::coin, turnstile::push> model{
        turnstile::machine{turnstile::chart}};
    bsc::verify::explorer ex{model};
    auto const& stats = ex.run();
    auto const locked = bsc::verify::always_reachable(ex, "Locked",
                                                      [](auto const& m) { return m.template is<turnstile::Locked>(); });
    bool const ok = stats.states == 2 && locked.holds();
    std::puts(ok ? "single header verify.hpp: ok" : "single header verify.hpp: FAILED");
    return ok ? 0 : 1;
}
