// A turnstile, with bsc found by find_package: the machine and the Mermaid export.
#include <bsc/bsc.hpp>
#include <bsc/export.hpp>

#include <cstdio>
#include <string>

#define BSC_STRINGIFY_(x) #x
#define BSC_STRINGIFY(x) BSC_STRINGIFY_(x)

namespace turnstile {
struct coin {};
struct push {};
struct Turnstile;
struct Locked;
struct Unlocked;
struct counter {
    int coins = 0;
};
inline constexpr auto add_coin = bsc::named<"add_coin">([](counter& c) { ++c.coins; });
inline constexpr auto chart = bsc::make_chart<counter>(
    bsc::composite<Turnstile>(bsc::initial<Locked>, bsc::state<Unlocked>),
    bsc::state<Locked> + bsc::event<coin> / add_coin = bsc::state<Unlocked>,
    bsc::state<Unlocked> + bsc::event<push> = bsc::state<Locked>);
}  // namespace turnstile

int main() {
    bsc::machine m{turnstile::chart, turnstile::counter{}};
    m.dispatch(turnstile::coin{});
    m.dispatch(turnstile::push{});
    m.dispatch(turnstile::coin{});
    std::string const diagram = bsc::to_mermaid(turnstile::chart);
    // The header's version is the package's.
    std::string const header_version = BSC_STRINGIFY(BSC_VERSION_MAJOR) "." BSC_STRINGIFY(
        BSC_VERSION_MINOR) "." BSC_STRINGIFY(BSC_VERSION_PATCH);
    bool const ok = m.is<turnstile::Unlocked>() && m.context().coins == 2 &&
                    diagram.find("Locked --> Unlocked : coin / add_coin") != std::string::npos &&
                    header_version == BSC_PACKAGE_VERSION;
    std::puts(ok ? "find_package: ok" : "find_package: FAILED");
    return ok ? 0 : 1;
}
