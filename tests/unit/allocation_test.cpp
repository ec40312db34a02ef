// Construction and dispatch allocate nothing: every operator new in this program is counted.

#include <doctest/doctest.h>

#include <cstdlib>
#include <new>

#include <bsc/bsc.hpp>

namespace {
std::size_t allocations = 0;
}

void* operator new(std::size_t size) {
    ++allocations;
    if (void* p = std::malloc(size ? size : 1)) return p;
    throw std::bad_alloc{};
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace alloc {
struct go {};
struct ping {};
struct Root;
struct A;
struct B;
struct P;
struct R1;
struct R2;
struct X1;
struct X2;
struct Y1;
struct Y2;
struct ctx {
    int n = 0;
};
inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<A>,
                         bsc::composite<A>(bsc::shallow_history, bsc::initial<B>,
                                           bsc::parallel<P>(bsc::composite<R1>(bsc::initial<X1>, bsc::state<X2>),
                                                            bsc::composite<R2>(bsc::initial<Y1>, bsc::state<Y2>)))),
    bsc::state<B> + bsc::event<go> / bsc::raise(ping{}) = bsc::state<P>,
    bsc::state<X1> + bsc::event<go> = bsc::state<X2>, bsc::state<Y1> + bsc::event<go> = bsc::state<Y2>,
    bsc::state<X2> + bsc::event<go> = bsc::state<X1>, bsc::state<Y2> + bsc::event<go> = bsc::state<Y1>,
    bsc::state<P> + bsc::event<ping> / [](ctx& c) { ++c.n; }, bsc::state<B> + bsc::event<ping> = bsc::state<B>);
}  // namespace alloc

TEST_CASE("construction and dispatch allocate nothing") {
    std::size_t const before = allocations;
    int n = 0;
    {
        bsc::machine m{alloc::chart, alloc::ctx{}};
        for (int i = 0; i < 100; ++i) {
            m.dispatch(alloc::go{});
            m.dispatch(alloc::ping{});
        }
        n = m.context().n;
    }
    std::size_t const after = allocations;
    CHECK(n == 101);
    CHECK(after == before);
}

TEST_CASE("the table-driven machine allocates nothing either") {
    std::size_t const before = allocations;
    int n = 0;
    {
        bsc::table::machine m{alloc::chart, alloc::ctx{}};
        for (int i = 0; i < 100; ++i) {
            m.dispatch(alloc::go{});
            m.dispatch(alloc::ping{});
        }
        n = m.context().n;
    }
    std::size_t const after = allocations;
    CHECK(n == 101);
    CHECK(after == before);
}
