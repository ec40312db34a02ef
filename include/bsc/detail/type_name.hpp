#pragma once
// Compile-time type names without RTTI, read from the compiler's function signature.

#include <string_view>

#include <bsc/detail/config.hpp>

namespace bsc::detail {

template <class T>
constexpr std::string_view signature() {
    return BSC_DETAIL_FUNCTION_SIGNATURE;
}

// GCC: "... [with T = ns::Name; std::string_view = ...]", Clang: "... [T = ns::Name]".
constexpr std::string_view type_from_signature(std::string_view sig) {
    constexpr std::string_view key = "T = ";
    const auto start = sig.find(key) + key.size();
    auto end = start;
    int depth = 0;
    for (; end < sig.size(); ++end) {
        const char c = sig[end];
        if (c == '<' || c == '(' || c == '[') ++depth;
        if (c == '>' || c == ')') --depth;
        if (depth < 0 || (depth == 0 && (c == ';' || c == ']'))) break;
        if (c == ']') --depth;
    }
    return sig.substr(start, end - start);
}

// "ns::outer::Name<ns::X>" -> "Name<ns::X>": the last scope at bracket depth zero.
constexpr std::string_view unqualified(std::string_view name) {
    std::size_t cut = 0;
    int depth = 0;
    for (std::size_t i = 0; i + 1 < name.size(); ++i) {
        if (name[i] == '<') ++depth;
        if (name[i] == '>') --depth;
        if (depth == 0 && name[i] == ':' && name[i + 1] == ':') cut = i + 2;
    }
    return name.substr(cut);
}

}  // namespace bsc::detail

namespace bsc {

/// The fully qualified name of a type, e.g. "mcs::Tape", computed at compile time.
template <class T>
inline constexpr std::string_view qualified_name = detail::type_from_signature(detail::signature<T>());

/// The name of a type without its namespaces, e.g. "Tape"; used for states in traces.
template <class T>
inline constexpr std::string_view name_of = detail::unqualified(qualified_name<T>);

}  // namespace bsc
