#pragma once
// A string as a template argument: the names of bsc::named<"released"> and the rows that
// errors reproduce (bsc::error::as_written).

#include <cstddef>
#include <string_view>

namespace bsc::detail {

/// N characters including the terminating zero, usable as a non-type template argument.
template <std::size_t N>
struct fixed_string {
    char chars[N]{};
    constexpr fixed_string() = default;
    // Implicit, so that a string literal converts to it as a template argument.
    constexpr fixed_string(char const (&text)[N]) {  // NOLINT(google-explicit-constructor)
        for (std::size_t i = 0; i < N; ++i) chars[i] = text[i];
    }
    constexpr std::string_view view() const { return {chars, N - 1}; }
};

}  // namespace bsc::detail
