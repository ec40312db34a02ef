#pragma once
// The display of examples/mcs/mcs.hpp for the implementations that do not use bsc: the last 16
// lines Show wrote, "+S" on entry and "-S" on exit. Shared by the workload (bench/mcs) and the
// Cortex-M4 programs (tests/cortex_m); C++17, without the heap.

#include <array>
#include <cstddef>
#include <string_view>

namespace mcs_bench {

class display {
public:
    static constexpr std::size_t capacity = 16;
    struct line {
        std::string_view state;
        bool entered = false;
        bool operator==(line const& o) const { return state == o.state && entered == o.entered; }
    };
    void show(std::string_view state, bool entered) {
        lines_[count_ % capacity] = {state, entered};
        ++count_;
    }
    std::size_t shown() const { return count_; }
    std::size_t size() const { return count_ < capacity ? count_ : capacity; }
    line operator[](std::size_t i) const {
        std::size_t const first = count_ < capacity ? 0 : count_ - capacity;
        return lines_[(first + i) % capacity];
    }

private:
    std::array<line, capacity> lines_{};
    std::size_t count_ = 0;
};

}  // namespace mcs_bench
