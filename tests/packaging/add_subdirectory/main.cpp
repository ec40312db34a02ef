// A turnstile, with bsc added as a subdirectory.
#include <bsc/bsc.hpp>

#include <cstdio>

namespace turnstile {
struct coin {};
struct push {};
struct Turnstile;
struct Locked;
struct Unlocked;
struct counter {
    int coins = 0;
};
inline constexpr auto chart = bsc::make_chart<counter>(
    bsc::composite<Turnstile>(bsc::initial<Locked>, bsc::state<Unlocked>),
    bsc::state<Locked> + bsc::event<coin> / [](counter& c) { ++c.coins; } = bsc::state<Unlocked>,
    bsc::state<Unlocked> + bsc::event<push> = bsc::state<Locked>);
}  // namespace turnstile

int main() {
    bsc::machine m{turnstile::chart, turnstile::counter{}};
    m.dispatch(turnstile::coin{});
    m.dispatch(turnstile::push{});
    m.dispatch(turnstile::coin{});
    bool const ok = m.is<turnstile::Unlocked>() && m.context().coins == 2;
    std::puts(ok ? "add_subdirectory: ok" : "add_subdirectory: FAILED");
    return ok ? 0 : 1;
}
