// Construction and dispatch allocate nothing, on either back end: every operator new in this
// program is counted, and the bytes it holds (heap_meter.hpp, for the other tests).

#include <doctest/doctest.h>

#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <new>

#include <bsc/bsc.hpp>

#include "backends.hpp"
#include "heap_meter.hpp"

namespace {
std::size_t allocations = 0;
std::size_t live_bytes = 0;
std::size_t peak_bytes = 0;
// Each block carries its size in front of it, so that operator delete can count it off.
constexpr std::size_t header = alignof(std::max_align_t);
}  // namespace

void* operator new(std::size_t size) {
    ++allocations;
    auto* block = static_cast<unsigned char*>(std::malloc(size + header));
    if (block == nullptr) throw std::bad_alloc{};
    std::memcpy(block, &size, sizeof size);
    live_bytes += size;
    if (live_bytes > peak_bytes) peak_bytes = live_bytes;
    return block + header;
}
void operator delete(void* p) noexcept {
    if (p == nullptr) return;
    auto* block = static_cast<unsigned char*>(p) - header;
    std::size_t size = 0;
    std::memcpy(&size, block, sizeof size);
    live_bytes -= size;
    std::free(block);
}
void operator delete(void* p, std::size_t) noexcept { operator delete(p); }

namespace heap_meter {
std::size_t live() { return live_bytes; }
std::size_t peak() { return peak_bytes; }
void reset_peak() { peak_bytes = live_bytes; }
}  // namespace heap_meter

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

TEST_CASE_TEMPLATE("construction and dispatch allocate nothing", Backend, bsc_test::compiled, bsc_test::table) {
    std::size_t const before = allocations;
    int n = 0;
    {
        bsc_test::machine_t<Backend, decltype(alloc::chart)> m{alloc::chart, alloc::ctx{}};
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
