// Twin of too_many_fields.fail.cpp: the 130 members are grouped into two nested structs of 65,
// which bsc walks at any depth.
#include <bsc/bsc.hpp>

// Ten int members, p0 to p9.
#define CF_TEN(p) \
    int p##0 = 0, p##1 = 0, p##2 = 0, p##3 = 0, p##4 = 0, p##5 = 0, p##6 = 0, p##7 = 0, p##8 = 0, p##9 = 0;

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Busy;
struct first_half {
    CF_TEN(a) CF_TEN(b) CF_TEN(c) CF_TEN(d) CF_TEN(e) CF_TEN(f) int g0 = 0, g1 = 0, g2 = 0, g3 = 0, g4 = 0;
};
struct second_half {
    int g5 = 0, g6 = 0, g7 = 0, g8 = 0, g9 = 0;
    CF_TEN(h) CF_TEN(i) CF_TEN(j) CF_TEN(k) CF_TEN(l) CF_TEN(m)
};
struct ctx {
    first_half first;
    second_half second;
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
    bsc::state<Idle> + bsc::event<go> / [](ctx& c) { ++c.first.a0; } = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf

int main() {
    bsc::machine m{cf::chart, cf::ctx{}};
    m.dispatch(cf::go{});
    return m.is<cf::Busy>() && m.context().first.a0 == 1 ? 0 : 1;
}
