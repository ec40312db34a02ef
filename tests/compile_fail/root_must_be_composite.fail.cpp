// EXPECT: defect=root_must_be_composite<bsc::detail::state_ref<cf::Idle> ?>
// The root of the state tree is a basic state, bsc::state<Idle>.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct Root;
struct Idle;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(bsc::state<Idle>,
                                                   bsc::state<Idle> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
