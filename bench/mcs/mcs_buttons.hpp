#pragma once
// The MCS's buttons by position (mcs::buttons of examples/mcs/mcs.hpp): button_at<I>::type is
// the event the workload's index I presses. Shared by the bsc implementations of the workload
// and by bench/trace.

#include <cstddef>

#include "../../examples/mcs/mcs.hpp"

namespace mcs_bench {

template <std::size_t I, class List = mcs::buttons>
struct button_at;
template <std::size_t I, class B, class... Bs>
struct button_at<I, mcs::button_list<B, Bs...>> : button_at<I - 1, mcs::button_list<Bs...>> {};
template <class B, class... Bs>
struct button_at<0, mcs::button_list<B, Bs...>> {
    using type = B;
};

}  // namespace mcs_bench
