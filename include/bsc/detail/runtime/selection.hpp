#pragma once
// The transitions one microstep selects in parallel regions, and SCXML's conflict resolution
// over them (removeConflictingTransitions): both back ends select into this buffer and keep
// what resolve_conflicts keeps.

#include <array>
#include <cstddef>
#include <cstdint>

namespace bsc::detail {

// Selected transitions, in selection order, each once. What a number stands for (a chart
// row, a position in a trigger's transitions) is the back end's business.
template <std::size_t Capacity>
struct selection {
    std::array<std::uint16_t, Capacity> rows{};
    std::size_t size = 0;

    constexpr void add(std::size_t row) {
        for (std::size_t i = 0; i < size; ++i)
            if (rows[i] == row) return;
        rows[size++] = static_cast<std::uint16_t>(row);
    }
};

// Walking the selection in order, a transition whose exit set meets that of one kept earlier
// (conflict(later, earlier)) replaces it if it preempts it (its source lies below the
// earlier one's: preempts(later, earlier)), and is dropped otherwise.
template <std::size_t Capacity, class Conflict, class Preempts>
constexpr selection<Capacity> resolve_conflicts(selection<Capacity> const& selected, Conflict conflict,
                                                Preempts preempts) {
    selection<Capacity> kept;
    for (std::size_t i = 0; i < selected.size; ++i) {
        std::size_t const later = selected.rows[i];
        bool dropped = false;
        selection<Capacity> survivors;
        for (std::size_t j = 0; j < kept.size && !dropped; ++j) {
            std::size_t const earlier = kept.rows[j];
            if (!conflict(later, earlier))
                survivors.add(earlier);
            else if (!preempts(later, earlier))
                dropped = true;
        }
        if (!dropped) {
            survivors.add(later);
            kept = survivors;
        }
    }
    return kept;
}

}  // namespace bsc::detail
