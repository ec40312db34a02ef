#pragma once
// Completion (SCXML 3.7.1): which states raise bsc::done<S>, and the flags a machine keeps
// while it enters a parallel state. Computed only for a chart that can take a done event (it
// names one, or takes bsc::any_event); for every other chart all of this is empty, and the
// back ends generate nothing for it.

#include <array>
#include <cstddef>

#include <bsc/detail/meta.hpp>
#include <bsc/dsl/row.hpp>
#include <bsc/detail/model/chart_model.hpp>

namespace bsc::detail {

template <class E>
inline constexpr bool is_done_event = false;
template <class S>
inline constexpr bool is_done_event<done<S>> = true;
template <>
inline constexpr bool is_done_event<any_event> = true;  // it takes done events too

template <class Model>
struct completion {
    static constexpr int N = Model::N;
    static constexpr auto const& tree = Model::tree;

    // Whether a row of the chart can take a done event.
    // clang-format off
    static constexpr bool takes_any = []<class... Es>(type_list<Es...>) {
        return any_true({is_done_event<Es>..., false});
    }(typename Model::events{});
    // clang-format on

    // trigger[s]: the trigger of bsc::done<S> for a composite or parallel state S other than
    // the root, or -1 (no row takes it, or it is never raised).
    static constexpr std::array<int, static_cast<std::size_t>(N)> trigger = [] {
        std::array<int, static_cast<std::size_t>(N)> out{};
        for (int& t : out) t = -1;
        if constexpr (takes_any)
            // clang-format off
            [&]<class... Tags>(type_list<Tags...>) {
                std::size_t s = 0;
                [[maybe_unused]] int const set[] = {  // (in order, as a list: max_fold)
                    (out[s] = s > 1 && (tree.kinds[s] == kind::composite || tree.kinds[s] == kind::parallel)
                                  ? Model::template trigger_of<done<Tags>>::value
                                  : -1,
                     ++s, 0)...};
            }(typename Model::tags{});
        // clang-format on
        return out;
    }();

    // Whether the machine ever raises a done event: then it needs a queue.
    static constexpr bool raises = [] {
        for (int t : trigger)
            if (t >= 0) return true;
        return false;
    }();

    // The parallel states whose done event is taken, numbered: while one is being entered, a
    // final state entered in one of its regions must not look at the regions not yet entered
    // (their bytes are the history of an earlier visit).
    static constexpr int parallel_count = [] {
        int n = 0;
        for (int s = 0; s < N; ++s)
            n += tree.kinds[static_cast<std::size_t>(s)] == kind::parallel && trigger[static_cast<std::size_t>(s)] >= 0;
        return n;
    }();
    static constexpr auto parallel_number = [] {
        std::array<int, static_cast<std::size_t>(N)> out{};
        int n = 0;
        for (int s = 0; s < N; ++s)
            out[static_cast<std::size_t>(s)] = tree.kinds[static_cast<std::size_t>(s)] == kind::parallel &&
                                                       trigger[static_cast<std::size_t>(s)] >= 0
                                                   ? n++
                                                   : -1;
        return out;
    }();
};

// What a machine keeps for completion: one flag per parallel state whose done event is taken,
// set while the state's regions are being entered. Nothing for other charts.
template <int Parallels>
struct entering_flags {
    std::array<bool, static_cast<std::size_t>(Parallels)> flag{};
};
template <>
struct entering_flags<0> {};

}  // namespace bsc::detail
