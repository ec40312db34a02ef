#pragma once
// The active configuration, and the list of active state names it yields for traces.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace bsc {

/// The active configuration: one ordinal per composite state, the position of its active child
/// (a byte; two bytes in a chart where a composite has more than 255 children). An inactive
/// composite keeps the child it had when it was last active, which is all that shallow and deep
/// history need. Parallel and basic states take no storage.
template <std::size_t Composites, class Ordinal = std::uint8_t>
struct configuration {
    using ordinal_type = Ordinal;
    std::array<Ordinal, Composites> active{};
    friend constexpr bool operator==(configuration const&, configuration const&) = default;
};
template <class Ordinal>
struct configuration<0, Ordinal> {
    using ordinal_type = Ordinal;
    friend constexpr bool operator==(configuration const&, configuration const&) = default;
};

/// The names of the active states, outermost first in document order (no allocation).
template <std::size_t Capacity>
class state_names {
public:
    constexpr void push_back(std::string_view name) { names_[size_++] = name; }
    constexpr std::size_t size() const { return size_; }
    constexpr bool empty() const { return size_ == 0; }
    constexpr std::string_view operator[](std::size_t i) const { return names_[i]; }
    constexpr auto begin() const { return names_.begin(); }
    constexpr auto end() const { return names_.begin() + static_cast<std::ptrdiff_t>(size_); }
    constexpr bool contains(std::string_view name) const {
        for (auto n : *this)
            if (n == name) return true;
        return false;
    }
    /// The same names in the same order.
    friend constexpr bool operator==(state_names const& a, state_names const& b) {
        if (a.size_ != b.size_) return false;
        for (std::size_t i = 0; i < a.size_; ++i)
            if (a.names_[i] != b.names_[i]) return false;
        return true;
    }
    /// The names joined by `separator`, e.g. "Mcs On Auto Mem".
    std::string joined(std::string_view separator = " ") const {
        std::string out;
        for (std::size_t i = 0; i < size_; ++i) {
            if (i) out += separator;
            out += names_[i];
        }
        return out;
    }

private:
    std::array<std::string_view, Capacity> names_{};
    std::size_t size_ = 0;
};

}  // namespace bsc
