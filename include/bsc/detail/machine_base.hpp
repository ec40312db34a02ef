#pragma once
// What every machine derives from, whatever its back end (an empty base: it costs nothing), so
// that the member layer (detail/members.hpp) knows a machine held in a context.

#include <type_traits>

namespace bsc::detail {

struct machine_base {};
template <class T>
inline constexpr bool is_machine = std::is_base_of_v<machine_base, T>;

}  // namespace bsc::detail
