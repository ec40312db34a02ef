#pragma once
// The bounded internal event queue: a ring buffer of the chart's event types. No heap;
// a push onto a full queue is refused and remembered, never written out of bounds.

#include <array>
#include <cstddef>
#include <type_traits>
#include <variant>

#include <bsc/error.hpp>
#include <bsc/detail/meta.hpp>
#include <bsc/model/event_families.hpp>

namespace bsc::detail {

template <std::size_t Capacity, class Events>
class event_queue;

template <std::size_t Capacity, class... Es>
class event_queue<Capacity, type_list<Es...>> {
public:
    using value_type = std::variant<std::monostate, Es...>;

    /// Raises e: queues it for processing after the current step. False if the queue is full.
    /// An event the chart does not name is queued as its nearest family (model/event_families.hpp):
    /// the rows that take it see no more of it than that.
    template <class E>
    constexpr bool operator()(E const& e) noexcept(std::is_nothrow_copy_constructible_v<E>) {
        constexpr int own = index_in<E, Es...>();
        if constexpr (own >= 0) {
            return push<E>(e);
        } else {
            constexpr int family = event_families<type_list<Es...>>::template trigger_of<E>();
            if constexpr (family < 0) {
                detail::report<error::raised_event_not_in_chart<E>>();
                return false;
            } else {
                using F = at<static_cast<std::size_t>(family), type_list<Es...>>;
                return push<F>(event_as<F>(e));
            }
        }
    }

    constexpr bool empty() const { return size_ == 0; }
    constexpr std::size_t size() const { return size_; }
    static constexpr std::size_t capacity() { return Capacity; }
    constexpr bool overflowed() const { return overflowed_; }
    constexpr void clear_overflow() { overflowed_ = false; }
    constexpr void clear() { head_ = size_ = 0; }

    // Removes the oldest event and calls f with it.
    template <class F>
    constexpr void pop(F&& f) {
        value_type item = std::move(items_[head_]);
        head_ = (head_ + 1) % Capacity;
        --size_;
        visit_index<static_cast<int>(sizeof...(Es))>(static_cast<int>(item.index()) - 1,
                                                     [&](auto i) { f(*std::get_if<decltype(i)::value + 1>(&item)); });
    }

protected:
    // Queues an item already held as the queue's variant (a delayed event coming due).
    constexpr bool push_item(value_type const& item) {
        if (size_ == Capacity) {
            overflowed_ = true;
            return false;
        }
        items_[(head_ + size_) % Capacity] = item;
        ++size_;
        return true;
    }
    // The chart's event an event E is queued as: E itself, or its nearest family (-1: none).
    template <class E>
    static constexpr int queued_as = index_in<E, Es...>() >= 0
                                         ? index_in<E, Es...>()
                                         : event_families<type_list<Es...>>::template trigger_of<E>();

private:
    template <class E>
    constexpr bool push(E const& e) {
        if (size_ == Capacity) {
            overflowed_ = true;
            return false;
        }
        auto& slot = items_[(head_ + size_) % Capacity];
        // Emplacing spares GCC a false -Wmaybe-uninitialized on a temporary variant; Clang
        // 14 cannot emplace into a variant in a constant expression, so that assigns.
        if (std::is_constant_evaluated())
            slot = value_type{std::in_place_type<E>, e};
        else
            slot.template emplace<E>(e);
        ++size_;
        return true;
    }

    std::array<value_type, Capacity> items_{};
    std::size_t head_ = 0;
    std::size_t size_ = 0;
    bool overflowed_ = false;
};

// A chart whose queue capacity is zero raises nothing: every raise is an overflow.
template <class... Es>
class event_queue<0, type_list<Es...>> {
public:
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
