#pragma once
// bsc::transient<T> and bsc::transient_member<T>: data a context holds that is not part of the
// machine's state (a log, a display buffer, statistics, a handle): not saved by bsc::save, not
// explored, not recorded in waveforms, not sent over the network. Channels and timers inside a
// transient member are still driven by the machine.

namespace bsc {

/// Specialise as true for a member type that is never part of the state.
template <class T>
inline constexpr bool transient = false;

/// One member left out of the state, whatever its type: `bsc::transient_member<int> scans;`.
/// Reads and writes as the T it holds (`++ctx.scans.value`, or through its conversions).
template <class T>
struct transient_member {
    T value{};

    constexpr operator T&() & { return value; }             // NOLINT(google-explicit-constructor)
    constexpr operator T const&() const& { return value; }  // NOLINT(google-explicit-constructor)
    constexpr transient_member& operator=(T const& v) {
        value = v;
        return *this;
    }
    constexpr T* operator->() { return &value; }
    constexpr T const* operator->() const { return &value; }
};

template <class T>
inline constexpr bool transient<transient_member<T>> = true;

}  // namespace bsc
