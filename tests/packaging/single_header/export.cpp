// The exports from the single header export.hpp alone (it includes bsc.hpp beside it).
#include <bsc/export.hpp>

#include <cstdio>
#include <string>

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
}  // namespace turnstile

int main() {
    bool const ok = bsc::to_mermaid(turnstile::chart).find("Unlocked --> Locked : push") != std::string::npos &&
                    bsc::to_scxml(turnstile::chart).find("<transition event=\"coin\" target=\"Unlocked\"/>") !=
                        std::string::npos &&
                    bsc::to_dot(turnstile::chart).find("\"Locked\" -> \"Unlocked\" [label=\"  coin  \"];") !=
                        std::string::npos &&
                    bsc::to_plantuml(turnstile::chart).find("Locked --> Unlocked : coin") != std::string::npos;
    std::puts(ok ? "single header export.hpp: ok" : "single header export.hpp: FAILED");
    return ok ? 0 : 1;
}
