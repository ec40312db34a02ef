#pragma once
// Event families: a row on event U also takes every event E derived from U, and a row on
// bsc::any_event takes every event (SCXML's event descriptors, which match by prefix, written
// as C++ inheritance). U is then a family of E. Computed from the chart's events by the model,
// the queue (which stores an event the chart does not name as its nearest family) and the
// back ends (which hand a row the event as its own type).

#include <array>
#include <cstddef>
#include <type_traits>

#include <bsc/detail/config.hpp>
#include <bsc/detail/meta.hpp>
#include <bsc/dsl/row.hpp>

namespace bsc::detail {

// A row on event U also takes every event E derived from U (publicly or not: the conversion is
// checked where the row is called), and a row on bsc::any_event takes every event: U is then
// E's family. The families of an event must form one chain (each family below the next), so
// that an event's rows are those of its own type and of its chain, and an event the chart does
// not name behaves as the most derived chart event of its chain.
// The chart events (Us) that are E's families. (Built-in traits, not std::is_base_of_v: a
// chart of K events asks K * K times, and no template is instantiated per pair.)
template <class E, class... Us>
constexpr std::array<bool, sizeof...(Us)> families_of() {
    return {(!BSC_DETAIL_IS_SAME(Us, E) && (BSC_DETAIL_IS_SAME(Us, any_event) || BSC_DETAIL_IS_BASE_OF(Us, E)))...};
}

// Of the families `of` (a row of the matrix below), the nearest to the event: the one with
// the most families of its own (`counts`). -1 if there is none; -2 if the families do not
// form a chain.
template <std::size_t K>
constexpr int nearest_family(std::array<bool, K> const& of, std::array<std::array<bool, K>, K> const& family,
                             std::array<int, K> const& counts) {
    int nearest = -1;
    for (std::size_t u = 0; u < K; ++u)
        if (of[u] && (nearest < 0 || counts[u] > counts[static_cast<std::size_t>(nearest)]))
            nearest = static_cast<int>(u);
    if (nearest < 0) return -1;
    // A chain: the nearest family's own families are all the others.
    for (std::size_t u = 0; u < K; ++u)
        if (of[u] && static_cast<int>(u) != nearest && !family[static_cast<std::size_t>(nearest)][u]) return -2;
    return nearest;
}

template <class Events>
struct event_families;
template <class... Us>
struct event_families<type_list<Us...>> {
    static constexpr std::size_t K = sizeof...(Us);
    // Whether the chart names bsc::any_event, every other event's family.
    static constexpr bool names_any_event = position_in<any_event, type_list<Us...>>::value >= 0;
#if defined(BSC_DETAIL_BASES_OF)
    // How many of class E's proper bases are chart events (a base reached by two paths counts
    // twice: the callers ask only whether there are none). Classes, not functions or variables,
    // which would be symbols named by spelling every event of the chart, one per event.
    template <class... B>
    struct base_list {
        enum : int{in_chart = count_true({(position_in<B, type_list<Us...>>::value >= 0)..., false})};
    };
    template <class E, bool = BSC_DETAIL_IS_CLASS(E)>
    struct bases_below {
        enum : int{value = base_list<BSC_DETAIL_BASES_OF(E)...>::in_chart};
    };
    template <class E>
    struct bases_below<E, false> {
        enum : int{value = 0};
    };
#endif
    // How many chart events E derives from, E itself included if it is one (a class is its own
    // base): one built-in per chart event, or, where the compiler lists a class's bases, E's
    // bases looked up among the chart's events. (A list, not a fold: detail::max_fold.)
    template <class E>
    static constexpr int chart_bases = [] {
#if defined(BSC_DETAIL_BASES_OF)
        if constexpr (!BSC_DETAIL_IS_CLASS(E))
            return 0;
        else
            return static_cast<int>(position_in<E, type_list<Us...>>::value >= 0) + bases_below<E>::value;
#else
        return count_true({BSC_DETAIL_IS_BASE_OF(Us, E)...});
#endif
    }();
    // Whether event E, which the chart does not name (trigger_of asks only then), has a family
    // among the chart's events; any: whether a chart event has.
    template <class E>
    static constexpr bool has_family = (names_any_event && !BSC_DETAIL_IS_SAME(E, any_event)) || chart_bases<E> > 0;
#if defined(BSC_DETAIL_BASES_OF)
    static constexpr bool any = (names_any_event && K > 1) || any_true({(bases_below<Us>::value > 0)..., false});
#else
    static constexpr bool any = (names_any_event && K > 1) ||
                                any_true({(chart_bases<Us> > static_cast<int>(BSC_DETAIL_IS_CLASS(Us)))..., false});
#endif
    // family[t][u]: chart event u is a family of chart event t. (Built only where some event
    // has a family: a chart of K events would otherwise hold K * K flags for nothing.)
    static constexpr auto family = [] {
        if constexpr (any)
            return std::array<std::array<bool, K>, K>{families_of<Us, Us...>()...};
        else
            return std::array<std::array<bool, K>, 0>{};
    }();
    // counts[u]: how many families chart event u has.
    static constexpr std::array<int, K> counts = [] {
        std::array<int, K> out{};
        if constexpr (any)
            for (std::size_t u = 0; u < K; ++u)
                for (bool b : family[u]) out[u] += b ? 1 : 0;
        return out;
    }();
    // nearest[t]: the nearest family of chart event t, -1 if none, -2 if not a chain.
    static constexpr std::array<int, K> nearest = [] {
        std::array<int, K> out{};
        for (std::size_t t = 0; t < K; ++t) {
            if constexpr (any)
                out[t] = nearest_family(family[t], family, counts);
            else
                out[t] = -1;
        }
        return out;
    }();
    // Where no chart event has a family, an event's families form a chain only if it has one.
    static constexpr int single_family(std::array<bool, K> const& of) {
        int found = -1;
        for (std::size_t u = 0; u < K; ++u)
            if (of[u]) found = found == -1 ? static_cast<int>(u) : -2;
        return found;
    }
    // The trigger of event E: its own position if the chart names it, else its nearest family's
    // (-1: none; -2: its families are not a chain).
    template <class E>
    static constexpr int trigger_of() {
        constexpr int own = position_in<E, type_list<Us...>>::value;
        if constexpr (own >= 0)
            return own;
        else if constexpr (!has_family<E>)
            return -1;
        else if constexpr (any)
            return nearest_family(families_of<E, Us...>(), family, counts);
        else
            return single_family(families_of<E, Us...>());
    }
};

// The trigger of event E among a chart's events: its own position if the chart names it, else
// its nearest family's (-1: none; -2: its families are not a chain). A class, which makes no
// symbol, for the events the chart names; event_families::trigger_of only for the others.
template <class E, class Events>
struct unnamed_trigger : std::integral_constant<int, event_families<Events>::template trigger_of<E>()> {};
template <class E, class Events>
struct trigger_in;
template <class E, class... Us>
struct trigger_in<E, type_list<Us...>> {
    enum : int { own = position_in<E, type_list<Us...>>::value };
    enum : int {
        value = std::conditional_t<(own >= 0), std::integral_constant<int, own>,
                                   unnamed_trigger<E, type_list<Us...>>>::value
    };
};

// The event as row Row's guard and action see it, whatever event E took the row: as the row's
// own event type (a row on a family sees the family), or bsc::any_event.
template <class Seen, class E>
constexpr decltype(auto) event_as(E const& e) {
    if constexpr (BSC_DETAIL_IS_SAME(Seen, E))
        return (e);
    else if constexpr (BSC_DETAIL_IS_SAME(Seen, any_event))
        return any_event{};
    else
        return static_cast<Seen const&>(e);
}

}  // namespace bsc::detail
