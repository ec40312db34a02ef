#pragma once
// The bounded internal event queue: a ring buffer of the chart's event types. No heap;
// a push onto a full queue is refused and remembered, never written out of bounds.

#include <array>
#include <cstddef>
#include <type_traits>
#include <variant>

#include <bsc/error.hpp>
#include <bsc/detail/assume.hpp>
#include <bsc/detail/meta.hpp>
#include <bsc/detail/model/event_families.hpp>

namespace bsc::detail {

// What every bounded queue keeps: its slots (Slots, first, where a machine's members of large
// alignment go), where the oldest event is, how many there are, and whether a raise found the
// queue full.
template <std::size_t Capacity, class Slots>
class ring {
public:
    constexpr bool empty() const { return size_ == 0; }
    constexpr std::size_t size() const { return size_; }
    static constexpr std::size_t capacity() { return Capacity; }
    constexpr bool overflowed() const { return overflowed_; }
    constexpr void clear_overflow() { overflowed_ = false; }
    constexpr void clear() { head_ = size_ = 0; }

    // Between runs a machine's queue is empty, rewound and without overflow: every run ends so
    // (detail/runtime/settling.hpp: settled, abandon; run_control.hpp: end_run_by_exception). Said to the optimiser at
    // the start of a dispatch, so that it places the events a dispatch raises at known slots
    // and drops the tests of a queue it sees nothing raised into: a raise then costs about a
    // store, its processing a load (docs/performance.md,
    // rule "Tell the optimiser what a run guarantees"). A hidden friend, not a member: the
    // queue is the raise argument of every action, which should not be handed a promise it
    // can break.
    friend constexpr void assume_idle(ring const& q) { detail::assume(q.size_ == 0 && q.head_ == 0 && !q.overflowed_); }
    // Puts the oldest event back at the first slot; only for an empty queue (at the end of a
    // run), where it costs one store and no test.
    friend constexpr void rewind_empty(ring& q) { q.head_ = 0; }

protected:
    // True, and the overflow marked, if the queue is full: the raise then stores nothing.
    constexpr bool refuse_when_full() {
        if (size_ == Capacity) {
            overflowed_ = true;
            return true;
        }
        return false;
    }
    // The slot after the newest event; added() counts the event once it is stored there.
    constexpr std::size_t back() const { return (head_ + size_) % Capacity; }
    constexpr void added() { ++size_; }
    // The slot of the oldest event; drop_front() takes it out once it is read. (A queue whose
    // slots hold nothing only counts: removed().)
    constexpr std::size_t front() const { return head_; }
    constexpr void drop_front() {
        head_ = (head_ + 1) % Capacity;
        removed();
    }
    constexpr void removed() { --size_; }

    [[no_unique_address]] Slots items_{};

private:
    std::size_t head_ = 0;
    std::size_t size_ = 0;
    bool overflowed_ = false;
};

// The position among Events of the event an event E is queued as: E itself, or its nearest
// family (detail/model/event_families.hpp): the rows that take it see no more of it than that. -1: none.
template <class E, class... Es>
constexpr int queued_index(type_list<Es...>) {
    return trigger_in<E, type_list<Es...>>::value;  // its own position first, as a chart's trigger
}

// Raises e into a queue of Events: push(f) with the event e is queued as, or, for an event the
// chart does not name, the error that says so (and false).
template <class Events, class E, class Push>
constexpr bool raise_into(E const& e, Push&& push) {
    constexpr int as = queued_index<E>(Events{});
    if constexpr (as < 0) {
        detail::report<error::raised_event_not_in_chart<E>>();
        return false;
    } else {
        return push(event_as<at<static_cast<std::size_t>(as), Events>>(e));
    }
}

template <std::size_t Capacity, class Events>
class event_queue;

template <std::size_t Capacity, class... Es>
class event_queue<Capacity, type_list<Es...>>
    : public ring<Capacity, std::array<std::variant<std::monostate, Es...>, Capacity>> {
    using ring<Capacity, std::array<std::variant<std::monostate, Es...>, Capacity>>::items_;

public:
    using value_type = std::variant<std::monostate, Es...>;

    /// Raises e: queues it for processing after the current step. False if the queue is full.
    /// An event the chart does not name is queued as its nearest family (detail/model/event_families.hpp):
    /// the rows that take it see no more of it than that.
    template <class E>
    constexpr bool operator()(E const& e) noexcept(std::is_nothrow_copy_constructible_v<E>) {
        return raise_into<type_list<Es...>>(e, [this]<class F>(F const& f) { return this->template push<F>(f); });
    }

    // Removes the oldest event and calls f with it.
    template <class F>
    constexpr void pop(F&& f) {
        value_type item = std::move(items_[this->front()]);
        this->drop_front();
        visit_index<static_cast<int>(sizeof...(Es))>(static_cast<int>(item.index()) - 1,
                                                     [&](auto i) { f(*std::get_if<decltype(i)::value + 1>(&item)); });
    }

    // ---- what the queue holds between runs: for the retentive state and the explorer -------
    // Calls f(item) for each event held, oldest first.
    template <class F>
    constexpr void for_each_held(F&& f) const {
        for (std::size_t i = 0; i < this->size(); ++i) f(items_[(this->front() + i) % Capacity]);
    }
    // Queues an item already held as the queue's variant (a delayed event coming due, an event
    // restored).
    constexpr bool push_item(value_type const& item) {
        if (this->refuse_when_full()) return false;
        items_[this->back()] = item;
        this->added();
        return true;
    }

private:
    template <class E>
    constexpr bool push(E const& e) {
        if (this->refuse_when_full()) return false;
        auto& slot = items_[this->back()];
        // Emplacing spares GCC a false -Wmaybe-uninitialized on a temporary variant; Clang
        // 14 cannot emplace into a variant in a constant expression, so that assigns.
        if (std::is_constant_evaluated())
            slot = value_type{std::in_place_type<E>, e};
        else
            slot.template emplace<E>(e);
        this->added();  // (after the copy, which may throw)
        return true;
    }
};

// The slots of a single_event_queue: the events, or for an empty event none.
template <std::size_t Capacity, class E>
struct single_event_slots {
    std::array<E, Capacity> value{};
};
template <std::size_t Capacity, class E>
    requires std::is_empty_v<E>
struct single_event_slots<Capacity, E> {};

// The queue of a chart that raises one event type only, a trivially copyable one whose default
// construction is a constant expression (queue_for.hpp picks it): the events themselves,
// without a variant's index to store, load and switch on; for an empty event, not even the
// events, only their count (a raise is then an increment, as a hand-written flag would be).
template <std::size_t Capacity, class E>
class single_event_queue : public ring<Capacity, single_event_slots<Capacity, E>> {
    static_assert(Capacity > 0 && std::is_trivially_copyable_v<E>);
    static constexpr bool stores_events = !std::is_empty_v<E>;
    using ring<Capacity, single_event_slots<Capacity, E>>::items_;

public:
    /// Raises e, as event_queue does: E itself, or an event of E's family queued as E.
    template <class R>
    constexpr bool operator()(R const& e) noexcept(std::is_nothrow_copy_constructible_v<R>) {
        return raise_into<type_list<E>>(e, [this](E const& f) { return this->push(f); });
    }

    // Removes the oldest event and calls f with it.
    template <class F>
    constexpr void pop(F&& f) {
        if constexpr (stores_events) {
            E const item = items_.value[this->front()];
            this->drop_front();
            f(item);
        } else {
            this->removed();
            f(E{});
        }
    }

private:
    constexpr bool push(E const& e) {
        if (this->refuse_when_full()) return false;
        if constexpr (stores_events) items_.value[this->back()] = e;
        this->added();
        return true;
    }
};

// A chart whose queue capacity is zero raises nothing: every raise is an overflow.
template <class... Es>
class event_queue<0, type_list<Es...>> {
public:
    using value_type = std::variant<std::monostate, Es...>;
    template <class F>
    constexpr void for_each_held(F&&) const {}
    constexpr bool push_item(value_type const&) {
        overflowed_ = true;
        return false;
    }
    template <class E>
    constexpr bool operator()(E const&) noexcept {
        overflowed_ = true;
        return false;
    }
    constexpr bool empty() const { return true; }
    constexpr std::size_t size() const { return 0; }
    static constexpr std::size_t capacity() { return 0; }
    constexpr bool overflowed() const { return overflowed_; }
    constexpr void clear_overflow() { overflowed_ = false; }
    constexpr void clear() {}
    template <class F>
    constexpr void pop(F&&) {}

private:
    bool overflowed_ = false;
};

// The queue of a chart none of whose actions can raise (detail::raised_by_chart): it is always
// empty, and saying so at compile time spares every dispatch the checks for raised events.
// (Not a template: its name is part of the symbols of every action the machine calls.)
class no_event_queue {
public:
    template <class E>
    constexpr bool operator()(E const&) noexcept {  // never called: no action takes the raise argument
        return false;
    }
    static constexpr bool empty() { return true; }
    static constexpr std::size_t size() { return 0; }
    static constexpr std::size_t capacity() { return 0; }
    static constexpr bool overflowed() { return false; }
    constexpr void clear_overflow() {}
    constexpr void clear() {}
    template <class F>
    constexpr void pop(F&&) {}
};

}  // namespace bsc::detail
