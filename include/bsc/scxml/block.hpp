#pragma once
// bsc::scxml::block: the action a generated chart runs for one block of SCXML executable content
// (a transition's content, one `<onentry>` or `<onexit>`).

#include <utility>

#include <bsc/detail/config.hpp>
#include <bsc/dsl/action.hpp>
#include <bsc/dsl/delayed.hpp>

/// On the functions of a generated datamodel that hold a block's executable content: out of line.
/// A machine's dispatch inlines everything it calls (docs/performance.md); a document's
/// content, value copies and strings included, inlined into every row that runs it took four
/// times as long to compile at -O2 (a 3-state document: 13.5 s of GCC 12 user CPU, 3.2 s out
/// of line) for no gain worth it.
#define BSC_SCXML_BLOCK_FUNCTION BSC_DETAIL_NOINLINE

namespace bsc::scxml {
namespace detail {
template <bool Sends, class F>
struct block_fn : bsc::detail::action_base {
    [[no_unique_address]] F fn;
    template <class Ctx, class E, class Raise>
    constexpr void operator()(Ctx& ctx, E const& e, Raise& raise) const {
        fn(ctx, e, raise);
    }
};
}  // namespace detail

/// An action that runs `f(context, event, raise)`, where `raise` also schedules and cancels
/// delayed events (`raise.schedule(delay, e, id)`, `raise.cancel(id)`) when `Sends` is true: a
/// chart with such a block gets slots for delayed events (docs/semantics.md, "Delayed events
/// to self"). An entry or exit block receives bsc::detail::state_change as its event. A block
/// that throws stops there (SCXML: the rest of the block is skipped, error.execution raised).
template <bool Sends = false, class F>
constexpr auto block(F f) {
    return detail::block_fn<Sends, F>{{}, std::move(f)};
}

}  // namespace bsc::scxml

namespace bsc::detail {
template <class F>
inline constexpr bool sends_delayed<scxml::detail::block_fn<true, F>> = true;
}  // namespace bsc::detail
