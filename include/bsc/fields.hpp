#pragma once
// bsc::fields<T>: what the members of a context type are, for a type that is not a plain
// aggregate (a class with private members, constructors or base classes, or more than 128
// members). Every part of bsc that walks a machine's state uses it: channels' latch and commit,
// timers' update, retentive state, the explorer, the waveform and the network. Aggregates need
// nothing: their members are found without it. <bsc/adapt/hana.hpp> specialises it for every
// type adapted with Boost.Hana.

namespace bsc {

/// Specialise for a type whose members bsc cannot find by itself:
///
///     template <> struct bsc::fields<axis> {
///         static constexpr std::array<std::string_view, 2> names{"speed", "limit"};
///         template <class Self, class F>   // Self: axis or axis const
///         static constexpr decltype(auto) apply(Self& self, F&& f) { return f(self.speed_, self.limit_); }
///     };
///
/// Requirements: `names` holds one name per member, in the order in which `apply` passes them
/// to `f`, each as an lvalue of the object. Members left out are not part of the machine's state
/// (neither saved, explored nor recorded) and their channels and timers are not driven.
template <class T>
struct fields {};

}  // namespace bsc
