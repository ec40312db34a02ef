#pragma once
// A named part of an explored state's key: where the explorer's codec put a member of a context
// (at any depth), a machine's configuration, timeouts or pending events. What the explorer reports
// when a bound stops it: which parts took the most values.

#include <cstddef>
#include <string>

namespace bsc::detail {

struct encoded_field {
    std::string name;
    std::size_t first_bit = 0;
    std::size_t bits = 0;
};

}  // namespace bsc::detail
