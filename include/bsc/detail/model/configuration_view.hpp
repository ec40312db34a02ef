#pragma once
// What a guard that tests the configuration (bsc::in<S>, dsl/guard.hpp) sees of it: a view of the
// configuration bytes that answers is_active<S>(), for the guard of one row. Both back ends hand
// it to such guards (the compiled machine's guard_holds, the table's guard thunks).
//
// The test is resolved at compile time. A guard is evaluated only while its row's source is
// active (it is one of the candidates of an active state, or of an active component), so every
// common ancestor of S and the source is known to be active: only the states from S up to, not
// including, their lowest common ancestor remain, and of those only the ones whose parent is a
// composite need a byte compared (a region of a parallel state is active with its parent). For S
// a child of another region of a parallel state above the source that is one compare; for S the source
// or one of its ancestors, none (true); for S below another child of a composite above the
// source, none either (false: the composite's active child is the source's).

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace bsc::detail {

// One compare: the byte at `slot` selects the child at `ordinal`.
struct byte_test {
    int slot = 0;
    int ordinal = 0;
};

// Whether state s can never be active while state `known` is: they lie below different children
// of a composite, whose byte selects one (the states with a byte; a parallel state has none).
template <class Tree>
constexpr bool exclusive_states(Tree const& tree, int s, int known) {
    int const top = tree.lca(s, known);
    return top != s && top != known && tree.slot[static_cast<std::size_t>(top)] >= 0;
}

// The compares that tell whether state s is active while state `known` is: one per composite
// on the path from s up to, not including, their lowest common ancestor; innermost first.
template <class Tree>
constexpr int in_test_count(Tree const& tree, int s, int known) {
    int const top = tree.lca(s, known);
    int n = 0;
    for (int x = s; x != top; x = tree.parent[static_cast<std::size_t>(x)])
        n += tree.slot[static_cast<std::size_t>(tree.parent[static_cast<std::size_t>(x)])] >= 0;
    return n;
}
template <class Model, int S, int Known>
inline constexpr auto in_tests = [] {
    constexpr auto const& tree = Model::tree;
    std::array<byte_test, static_cast<std::size_t>(in_test_count(tree, S, Known))> out{};
    std::size_t n = 0;
    for (int x = S; x != tree.lca(S, Known); x = tree.parent[static_cast<std::size_t>(x)]) {
        int const slot = tree.slot[static_cast<std::size_t>(tree.parent[static_cast<std::size_t>(x)])];
        if (slot >= 0) out[n++] = {slot, tree.ordinal[static_cast<std::size_t>(x)]};
    }
    return out;
}();

/// The configuration as the guard of a row from state Source sees it: `active` points at the
/// configuration bytes (bsc::configuration::active; null for a chart without composites, where
/// no test reads a byte).
template <class Model, int Source>
struct configuration_view {
    typename Model::ordinal_type const* active;

    template <class S>
    constexpr bool is_active() const noexcept {
        constexpr int s = Model::template index_of_state<S>::value;
        static_assert(s > 0, "bsc::in<S>: S is not a state of the chart (bsc::error::in_of_state_not_in_chart)");
        if constexpr (exclusive_states(Model::tree, s, Source)) {
            return false;
        } else {
            constexpr auto const& tests = in_tests<Model, s, Source>;
            // clang-format off
            return [&]<std::size_t... I>(std::index_sequence<I...>) {
                return ((active[static_cast<std::size_t>(tests[I].slot)] ==
                         static_cast<typename Model::ordinal_type>(tests[I].ordinal)) && ...);
            }(std::make_index_sequence<tests.size()>{});
            // clang-format on
        }
    }
};

}  // namespace bsc::detail
