// EXPECT: defect=too_many_fields<cf::ctx>
// ctx has 130 members, more than bsc finds in an aggregate (128).
#include <bsc/bsc.hpp>

// Ten int members, p0 to p9.
#define CF_TEN(p) \
    int p##0 = 0, p##1 = 0, p##2 = 0, p##3 = 0, p##4 = 0, p##5 = 0, p##6 = 0, p##7 = 0, p##8 = 0, p##9 = 0;

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Busy;
struct ctx {
    // clang-format off
    CF_TEN(a) CF_TEN(b) CF_TEN(c) CF_TEN(d) CF_TEN(e) CF_TEN(f) CF_TEN(g) CF_TEN(h) CF_TEN(i) CF_TEN(j) CF_TEN(k)
    CF_TEN(l) CF_TEN(m)
    // clang-format on
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
    bsc::state<Idle> + bsc::event<go> / [](ctx& c) { ++c.a0; } = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf

bool run() {
    bsc::machine m{cf::chart, cf::ctx{}};
    m.dispatch(cf::go{});
    return m.is<cf::Busy>();
}
