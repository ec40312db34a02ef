// Twin of member_not_retainable.fail.cpp: cf::display is declared not retained, so the
// restored machine keeps its own, and the rest of the context is saved.
#include <bsc/bsc.hpp>
#include <bsc/retain.hpp>

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Busy;
class display {
public:
    display() = default;
    explicit display(int v) : shown_(v) {}
    int shown() const { return shown_; }

private:
    int shown_ = 0;
};
struct ctx {
    int count = 0;
    display screen;
};
}  // namespace cf

template <>
inline constexpr bool bsc::transient<cf::display> = true;

namespace cf {
inline constexpr auto chart = bsc::make_chart<ctx>(bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
                                                   bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
                                                   bsc::state<Busy> + bsc::event<go> = bsc::state<Idle>);

std::size_t run() {
    bsc::machine m{chart, ctx{}};
    return bsc::save(m).size();
}
}  // namespace cf
