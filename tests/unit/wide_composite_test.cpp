// A composite with more than 255 children: the configuration then keeps each composite's active
// child in two bytes (bsc::configuration<N, std::uint16_t>), on both back ends, through history,
// bsc::in<S>, save and restore, and the explorer.

#include <doctest/doctest.h>

#include <bsc/bsc.hpp>
#include <bsc/retain.hpp>
#include <bsc/verify.hpp>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "backends.hpp"

namespace wide {
struct Root;
struct Ring;  // 300 children: S<0> .. S<299>
struct Side;  // a composite with shallow history beside the ring
struct Left;
struct Right;
template <int I>
struct S {};
struct next {};
struct jump {};       // from any S<I> to S<280>, guarded by nothing
struct swap_side {};  // toggles Side's child
struct leave {};      // Ring -> Side (history keeps Side's child)
struct enter {};      // Side -> Ring: Ring's shallow history returns to the last child
struct ctx {
    int laps = 0;  // modulo 4, so that the explorer's space is finite
};
constexpr int n = 300;

template <int... I>
constexpr auto make(std::integer_sequence<int, I...>) {
    return bsc::make_chart<ctx>(
        bsc::composite<Root>(bsc::initial<Ring>,
                             bsc::composite<Ring>(bsc::shallow_history, bsc::initial<S<0>>, bsc::state<S<I + 1>>...),
                             bsc::composite<Side>(bsc::shallow_history, bsc::initial<Left>, bsc::state<Right>)),
        (bsc::state<S<I>> + bsc::event<next> = bsc::state<S<I + 1>>)...,
        bsc::state<S<n - 1>> + bsc::event<next> / [](ctx& c) { c.laps = (c.laps + 1) % 4; } = bsc::state<S<0>>,
        bsc::state<Ring> + bsc::event<jump> = bsc::state<S<280>>,
        // bsc::in<Left> reads Side's entry, a two-byte one in this chart.
        bsc::state<Side> + bsc::event<swap_side>[bsc::in<Left>] = bsc::state<Right>,
        bsc::state<Right> + bsc::event<swap_side> = bsc::state<Left>,
        bsc::state<Ring> + bsc::event<leave> = bsc::state<Side>,
        bsc::state<Side> + bsc::event<enter> = bsc::state<Ring>);
}
inline constexpr auto chart = make(std::make_integer_sequence<int, n - 1>{});
}  // namespace wide

TEST_CASE_TEMPLATE("a composite of 300 children: two-byte configuration entries, history, save and restore", Backend,
                   bsc_test::compiled, bsc_test::table) {
    using namespace wide;
    using machine = bsc_test::machine_t<Backend, decltype(chart)>;
    using configuration = typename machine::configuration_type;
    static_assert(std::is_same_v<typename configuration::ordinal_type, std::uint16_t>);
    CHECK(sizeof(configuration) == 3 * sizeof(std::uint16_t));  // Root, Ring, Side

    machine m{chart};
    for (int k = 0; k < 290; ++k) REQUIRE(m.dispatch(next{}) == bsc::outcome::consumed);
    CHECK(m.template is<S<290>>());
    CHECK(m.active_states().joined() == "Root Ring S<290>");
    for (int k = 0; k < 10; ++k) m.dispatch(next{});
    CHECK(m.template is<S<0>>());  // past 299, back to the start
    CHECK(m.context().laps == 1);
    m.dispatch(jump{});
    CHECK(m.template is<S<280>>());
    CHECK_FALSE(m.template is<S<24>>());  // 280 and 24 share their low byte

    // Ring's shallow history keeps S<280> while Side is active.
    m.dispatch(leave{});
    CHECK(m.template is<Left>());
    m.dispatch(swap_side{});
    CHECK(m.template is<Right>());
    m.dispatch(enter{});
    CHECK(m.template is<S<280>>());

    // Saved in two bytes per composite, and restored.
    auto const bytes = bsc::save(m);
    CHECK(bytes.size() == bsc::saved_size<machine>);
    machine copy{chart};
    auto const restored = bsc::restore(copy, bytes);
    REQUIRE_MESSAGE(restored, bsc::to_string(restored));
    CHECK(copy.template is<S<280>>());
    CHECK(copy.active_configuration() == m.active_configuration());
    for (int k = 0; k < 19; ++k) copy.dispatch(next{});
    CHECK(copy.template is<S<299>>());
    copy.dispatch(next{});
    CHECK(copy.context().laps == 2);
    copy.dispatch(leave{});
    CHECK(copy.template is<Right>());  // Side's history, restored too
}

TEST_CASE("a composite of 300 children: the explorer encodes the two-byte entries and visits every child") {
    using namespace wide;
    using machine = bsc::machine<bsc::chart_ref<chart>>;
    bsc::verify::explorer ex{bsc::verify::event_model<machine, next, jump, leave, enter, swap_side>{machine{chart}}};
    auto const& st = ex.run();
    REQUIRE(st.complete);
    // Ring active at each of its 300 children with Side remembering either child (before Side is
    // first entered, its entry holds Left, its initial state, as when it remembers Left), or Side
    // active at either child with Ring remembering any of its 300; the laps modulo 4. An entry cut
    // to one byte would merge children 256 apart.
    CHECK(st.states == (300 * 2 + 2 * 300) * 4);
    CHECK(bsc::verify::reachable(ex, "S<299> after Right", [](auto const& m) {
              return m.template is<S<299>>() && m.context().laps == 3;
          }).holds());
    CHECK(bsc::verify::always(ex, "Ring and Side exclusive", [](auto const& m) {
              return !(m.template is<Ring>() && m.template is<Side>());
          }).holds());
}
