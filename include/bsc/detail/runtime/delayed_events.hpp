#pragma once
// Delayed events to self (SCXML's <send delay> to the machine): bsc::raise_after(delay, e, id)
// schedules e, bsc::cancel_delayed(id) cancels what was scheduled under id. The internal queue
// of a chart that sends them (detail/runtime/queue_for.hpp) is a delaying_queue: the ring of raised
// events plus a fixed number of slots, each an event with the time it comes due. step(now)
// moves the events due into the ring, earliest first; a pending event does not belong to the
// state that sent it, so leaving that state does not cancel it.
//
// An event whose due time would lie past duration::max() (a delay near duration::max() from a
// clock already far from zero) never comes due: no step(now) can reach that time. It is not
// kept: schedule() accepts it (no overflow) and it takes no slot, so it is neither saved,
// restored nor explored, and there is nothing for its id to cancel. The same holds where the
// due time moves: when the clock starts (start_clock: what was sent before the first cycle
// counts from it) and when a saved machine resumes at a later time (bsc::resume_at,
// detail/state_bytes.hpp).

#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include <bsc/detail/meta.hpp>
#include <bsc/duration.hpp>
#include <bsc/error.hpp>
#include <bsc/detail/runtime/event_queue.hpp>

namespace bsc::detail {

template <std::size_t Capacity, std::size_t Slots, class Events>
class delaying_queue;

template <std::size_t Capacity, std::size_t Slots, class... Es>
class delaying_queue<Capacity, Slots, type_list<Es...>> : public event_queue<Capacity, type_list<Es...>> {
    using base = event_queue<Capacity, type_list<Es...>>;

public:
    using typename base::value_type;

    /// Schedules e to come due `delay` after the machine's clock (the time of its last cycle).
    /// False, and an overflow reported at the end of the run, if every slot is taken. An event
    /// due past duration::max() never comes due: it is not kept, and true is returned.
    template <class E>
    constexpr bool schedule(duration delay, E const& e, int id) noexcept(std::is_nothrow_copy_constructible_v<E>) {
        constexpr int as = queued_index<E>(type_list<Es...>{});
        if constexpr (as < 0) {
            detail::report<error::raised_event_not_in_chart<E>>();
            return false;
        } else {
            using F = at<static_cast<std::size_t>(as), type_list<Es...>>;
            if (shifted_past_max(clock_, delay)) return true;  // never due
            for (auto& s : slots_)
                if (!s.pending) {
                    s.pending = true;
                    s.due = clock_ + delay;
                    s.sent = sent_++;
                    s.id = id;
                    s.event = value_type{std::in_place_type<F>, event_as<F>(e)};
                    return true;
                }
            delayed_overflow_ = true;
            return false;
        }
    }

    /// Cancels every pending event scheduled under `id` (0, no id: none; bsc::cancel_delayed
    /// refuses it).
    constexpr void cancel(int id) noexcept {
        if (id == 0) return;
        for (auto& s : slots_)
            if (s.pending && s.id == id) s.pending = false;
    }

    // ---- for the machine -----------------------------------------------------------------------
    constexpr void set_clock(duration now) { clock_ = now; }
    // The machine's clock started at `now` (its first cycle): what was scheduled before counts
    // from there, as the timeouts armed before it do (until then a due time is the delay, the
    // clock being zero). An event then due past duration::max() never comes due: dropped.
    constexpr void start_clock(duration now) {
        for (auto& s : slots_)
            if (s.pending) {
                if (shifted_past_max(s.due, now))
                    s.pending = false;
                else
                    s.due = shifted(s.due, now);
            }
        clock_ = now;
    }
    // Moves the events due at `now` into the queue of raised events, earliest first, and among
    // those due at once in the order they were sent.
    constexpr void release_due(duration now) {
        for (;;) {
            slot* next = nullptr;
            for (auto& s : slots_)
                if (s.pending && s.due <= now &&
                    (next == nullptr || s.due < next->due || (s.due == next->due && s.sent < next->sent)))
                    next = &s;
            if (next == nullptr) return;
            next->pending = false;
            (void)this->push_item(next->event);
        }
    }
    // ---- what the queue holds between runs: for the retentive state and the explorer -------
    // The time of the machine's last cycle, as the queue knows it.
    constexpr duration clock() const { return clock_; }
    // The number of pending events.
    constexpr std::size_t scheduled() const {
        std::size_t n = 0;
        for (auto const& s : slots_) n += s.pending ? 1 : 0;
        return n;
    }
    // Calls f(due, id, item) for each pending event, in the order they were sent.
    template <class F>
    constexpr void for_each_scheduled(F&& f) const {
        std::uint32_t after = 0;
        bool first = true;
        for (;;) {
            slot const* next = nullptr;
            for (auto const& s : slots_)
                if (s.pending && (first || s.sent > after) && (next == nullptr || s.sent < next->sent)) next = &s;
            if (next == nullptr) return;
            f(next->due, next->id, next->event);
            after = next->sent;
            first = false;
        }
    }
    // Forgets every pending event and the count of events sent.
    constexpr void clear_scheduled() {
        for (auto& s : slots_) s.pending = false;
        sent_ = 0;
    }
    // Keeps an event due at `due`, as the last one sent. False if every slot is taken.
    constexpr bool put_scheduled(duration due, int id, value_type const& item) {
        for (auto& s : slots_)
            if (!s.pending) {
                s = slot{true, due, sent_++, id, item};
                return true;
            }
        return false;
    }
    static constexpr std::size_t slot_count() { return Slots; }

    constexpr bool overflowed() const { return base::overflowed() || delayed_overflow_; }
    constexpr void clear_overflow() {
        base::clear_overflow();
        delayed_overflow_ = false;
    }

private:
    struct slot {
        bool pending = false;
        duration due{};
        std::uint32_t sent = 0;  // (not "order": in a template, `s.order <` would name bsc::order)
        int id = 0;
        value_type event{};
    };
    std::array<slot, Slots> slots_{};
    duration clock_{};
    std::uint32_t sent_ = 0;
    bool delayed_overflow_ = false;
};

}  // namespace bsc::detail
