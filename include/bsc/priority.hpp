#pragma once
// bsc::priority: which of two enabled transitions a state takes when one leaves an ancestor of
// the other's source (docs/semantics.md, "Selecting transitions", "Priority").

#include <cstdint>

namespace bsc {

/// The order in which a basic state's candidate transitions are tried, chosen once per chart:
/// `bsc::make_chart<Context, bsc::parent_first>(tree, rows...)`.
/// - `child_first` (the default; SCXML, UML): the rows of the state itself first, then its
///   parent's, up to the root. An inner row overrides an outer one.
/// - `parent_first` (Stateflow, STATEMATE, IEC 61131-3 interlocks): the root's rows first, down
///   to the state's own. An outer row, an emergency stop for example, wins over every row
///   below it on the same event.
/// Among the rows of one state, declaration order either way. The choice is made at compile
/// time: dispatch tries the candidates in a fixed order, and neither order costs an instruction.
enum class priority : std::uint8_t { child_first, parent_first };

/// `bsc::make_chart<Context, bsc::child_first>`: the default, written out.
inline constexpr priority child_first = priority::child_first;
/// `bsc::make_chart<Context, bsc::parent_first>`: outer transitions first.
inline constexpr priority parent_first = priority::parent_first;

}  // namespace bsc
