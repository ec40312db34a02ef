#pragma once
// Systems of actors (the COMDES-II paper [COMDES]; the modules of the ECA paper [ECA]; see
// docs/references.md): several machines — controllers and plant models — wired by typed signals
// from output channels to input channels, stepped in a declared order with the time given from
// outside. The wiring is one list, the system's actor diagram, and it is checked where the
// system type is instantiated: a link goes from an output to an input of the same value type
// (or says how to convert with bsc::convert), one link at most drives an input, every linked
// actor is stepped once per step, and every input of a stepped actor is driven by a link or
// declared bsc::from_outside. Each defect is one compile error (bsc::error, docs/checks.md).

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include <bsc/data/channel.hpp>
#include <bsc/data/timer.hpp>
#include <bsc/detail/config.hpp>
#include <bsc/detail/member_names.hpp>
#include <bsc/detail/members.hpp>
#include <bsc/detail/meta.hpp>
#include <bsc/error.hpp>
#include <bsc/outcome.hpp>

namespace bsc {

/// What the consumer of a link reads while the link's publisher is silent, when the two actors
/// run on different nodes (<bsc/net/node.hpp>). In one process a link is never stale, and the
/// policy changes nothing.
///
/// `hold_last` (the default): the last value received stays, as a latched level would.
struct hold_last {};

/// `fail_safe<V>`: the consumer reads `V` until the publisher is heard again, e.g. a motor
/// command that reads "stop" when its controller is lost. V is a structural value of the link's
/// type (a number, an enumerator, an aggregate of those).
template <auto V>
struct fail_safe {
    static constexpr auto value = V;
};

/// `lossless`: the link is never stale; the consumer waits for every value, however long its
/// publisher is silent, and the publisher waits for the consumer. For the couplings of a
/// simulated plant (a brick handed from one machine to the next), where a missed value is a
/// lost object, not a late one.
struct lossless {};

/// `convert<F>`: the consumer of the link reads `F(value)` for the source's value: a conversion
/// made explicit where the types of the two channels differ (a link without it requires the
/// same value type on both ends). F is a constexpr callable: a captureless lambda, a function
/// pointer. What a fail_safe<V> link reads while stale is V itself, already of the target's type.
template <auto F>
struct convert {
    static constexpr auto function = F;
};

namespace detail {

template <class T>
struct is_staleness_policy : std::false_type {};
template <>
struct is_staleness_policy<hold_last> : std::true_type {};
template <>
struct is_staleness_policy<lossless> : std::true_type {};
template <auto V>
struct is_staleness_policy<fail_safe<V>> : std::true_type {};

template <class T>
struct is_conversion : std::false_type {};
template <auto F>
struct is_conversion<convert<F>> : std::true_type {};

// The identity, for a link without bsc::convert.
struct no_conversion {};

// The first of Ts for which Is holds, or Default.
template <template <class> class Is, class Default, class... Ts>
struct first_such {
    using type = Default;
};
template <template <class> class Is, class Default, class T, class... Ts>
struct first_such<Is, Default, T, Ts...>
    : std::conditional_t<Is<T>::value, std::type_identity<T>, first_such<Is, Default, Ts...>> {};

// Two pointers to members (or any two template arguments) that designate the same member.
template <auto A, auto B>
constexpr bool same_member_pointer() {
    if constexpr (std::is_same_v<decltype(A), decltype(B)>)
        return A == B;
    else
        return false;
}

}  // namespace detail

/// A signal: the published value of output channel `FromChannel` of actor `FromActor` is
/// written into input channel `ToChannel` of actor `ToActor` just before `ToActor` steps.
/// Actors are members of the system's aggregate; channels are members of their contexts.
/// `Options`, in any order and each at most once: what the consumer reads when the two run on
/// different nodes and the publisher falls silent (hold_last, the default, fail_safe<V> or
/// lossless), and `convert<F>` for channels of different value types.
template <auto FromActor, auto FromChannel, auto ToActor, auto ToChannel, class... Options>
struct link {
    static constexpr auto from_actor = FromActor;
    static constexpr auto from_channel = FromChannel;
    static constexpr auto to_actor = ToActor;
    static constexpr auto to_channel = ToChannel;
    using when_stale = typename detail::first_such<detail::is_staleness_policy, hold_last, Options...>::type;
    /// bsc::convert<F>, or detail::no_conversion.
    using conversion = typename detail::first_such<detail::is_conversion, detail::no_conversion, Options...>::type;
    using options = detail::type_list<Options...>;

    /// What the consumer reads for the source's value `v`: v, or F(v) with bsc::convert<F>.
    template <class V>
    static constexpr auto converted(V const& v) {
        if constexpr (std::is_same_v<conversion, detail::no_conversion>)
            return v;
        else
            return conversion::function(v);
    }

    template <class Actors>
    static constexpr void transfer(Actors& actors) {
        auto const& source = (actors.*FromActor).context().*FromChannel;
        // The target's input is set through its machine's const context, as the environment sets it.
        ((actors.*ToActor).context().*ToChannel).set(converted(source.get()));
    }
    template <auto Actor>
    static constexpr bool targets() {
        return detail::same_member_pointer<Actor, ToActor>();
    }
};

/// An input that no link drives and that the environment sets between steps (an operator's
/// switch, a sensor outside the system): input channel `Channel` of actor `Actor`, declared
/// among a system's links. Every input (bsc::input) of a stepped actor is driven by a link or
/// so declared.
template <auto Actor, auto Channel>
struct from_outside {
    static constexpr auto actor = Actor;
    static constexpr auto channel = Channel;
};

/// The order in which a system steps its actors, as pointers to the aggregate's members.
template <auto... Actors>
struct order {};

/// What one system step did.
struct system_report {
    int transitions = 0;  ///< condition-driven transitions fired by all actors
    bool queue_overflow = false;
    bool livelock = false;
    bool halted = false;  ///< some actor is halted (a final child of its root is active)
};

namespace detail {

template <class T>
inline constexpr bool is_link = false;
template <auto FromActor, auto FromChannel, auto ToActor, auto ToChannel, class... Options>
inline constexpr bool is_link<link<FromActor, FromChannel, ToActor, ToChannel, Options...>> = true;
template <class T>
inline constexpr bool is_from_outside = false;
template <auto Actor, auto Channel>
inline constexpr bool is_from_outside<from_outside<Actor, Channel>> = true;

template <class List>
struct tuple_of_list;
template <class... Ts>
struct tuple_of_list<type_list<Ts...>> {
    using type = std::tuple<Ts...>;
};
// The entries of a system for which Is holds, in their order, as a std::tuple.
template <template <class> class Is, class... Entries>
using entries_such = typename tuple_of_list<
    concat_t<type_list<>, std::conditional_t<Is<Entries>::value, type_list<Entries>, type_list<>>...>>::type;
template <class T>
struct link_entry : std::bool_constant<is_link<T>> {};
template <class T>
struct from_outside_entry : std::bool_constant<is_from_outside<T>> {};

// An actor of Actors that has a context (a machine), and the member Channel of that context.
template <class Actors, auto Actor>
concept actor_with_context = requires(Actors const& actors) {
    (actors.*Actor).context();
};
template <class Actors, auto Actor>
using context_of_actor = std::remove_cvref_t<decltype((std::declval<Actors const&>().*Actor).context())>;
template <class Actors, auto Actor, auto Channel>
concept actor_has_member = actor_with_context<Actors, Actor> &&
    requires(context_of_actor<Actors, Actor> const& context) {
    context.*Channel;
};
template <class Actors, auto Actor, auto Channel>
using member_of_actor = std::remove_cvref_t<decltype(std::declval<context_of_actor<Actors, Actor> const&>().*Channel)>;

// Whether Channel is a member of Actor's context that the actor publishes (an output, an
// inout), or that is written from outside it (an input, an inout).
template <class Actors, auto Actor, auto Channel>
constexpr bool publishes() {
    if constexpr (actor_has_member<Actors, Actor, Channel>) {
        using M = member_of_actor<Actors, Actor, Channel>;
        return is_output_channel<M> || is_inout_channel<M>;
    } else {
        return false;
    }
}
template <class Actors, auto Actor, auto Channel>
constexpr bool written_from_outside() {
    if constexpr (actor_has_member<Actors, Actor, Channel>) {
        using M = member_of_actor<Actors, Actor, Channel>;
        return is_input_channel<M> || is_inout_channel<M>;
    } else {
        return false;
    }
}

template <class Conversion, class From, class To>
concept conversion_applies = requires(From const& value) {
    Conversion::function(value);
}
&&std::is_convertible_v<decltype(Conversion::function(std::declval<From const&>())), To>;

// What an option of bsc::link is: 1 a staleness policy, 2 a conversion, 0 neither.
template <class Option>
constexpr int option_kind() {
    return is_staleness_policy<Option>::value ? 1 : is_conversion<Option>::value ? 2 : 0;
}

// Each option of a link is known, and none is a second of its kind.
template <class Options>
struct link_options_rules;
template <class... Options>
struct link_options_rules<type_list<Options...>> {
    static constexpr std::array<int, sizeof...(Options) + 1> kinds{option_kind<Options>()..., -1};
    template <std::size_t I>
    static constexpr bool repeated() {
        for (std::size_t j = 0; j < I; ++j)
            if (kinds[j] == kinds[I]) return true;
        return false;
    }
    template <std::size_t I, class Option>
    static constexpr bool check_one() {
        if constexpr (option_kind<Option>() == 0 || repeated<I>())
            return report<error::invalid_link_option<Option>>();
        else
            return true;
    }
    static constexpr bool check() {
        // clang-format off
        return []<std::size_t... I>(std::index_sequence<I...>) {
            return ((check_one<I, Options>() ? 0 : 1) + ... + 0) == 0;
        }(std::index_sequence_for<Options...>{});
        // clang-format on
    }
};

BSC_DETAIL_DECLARED_ONLY_BEGIN
BSC_DETAIL_DECLARED_ONLY_END

// The name of member I of Context, as a template argument.
template <class Context, std::size_t I>
constexpr auto member_name_argument() {
    constexpr std::string_view name = names_of<Context>()[I];
    fixed_string<name.size() + 1> text{};
    for (std::size_t k = 0; k < name.size(); ++k) text.chars[k] = name[k];
    return text;
}

// The checks of a system's wiring, each defect reported once (detail::report) as the error that
// names it; check() is true when there is none. A check that would only repeat an earlier
// finding in other words is not run: the inputs left undriven are looked for once every link
// and bsc::from_outside entry is right.
template <class Actors, class Order, class... Entries>
struct system_rules;

template <class Actors, auto... Steps, class... Entries>
struct system_rules<Actors, order<Steps...>, Entries...> {
    using links = entries_such<link_entry, Entries...>;
    using declared_outside = entries_such<from_outside_entry, Entries...>;

    template <std::size_t I>
    static constexpr auto step_at = std::get<I>(std::tuple{Steps...});

    template <auto Actor>
    static constexpr bool in_order() {
        return (same_member_pointer<Actor, Steps>() || ...);
    }
    // Whether the order names its I-th actor for the first time there.
    template <std::size_t I>
    static constexpr bool first_in_order() {
        // clang-format off
        return []<std::size_t... J>(std::index_sequence<J...>) {
            return !(same_member_pointer<step_at<J>, step_at<I>>() || ...);
        }(std::make_index_sequence<I>{});
        // clang-format on
    }
    // Whether a link drives Channel of Actor.
    template <auto Actor, auto Channel>
    static constexpr bool linked() {
        // clang-format off
        return []<class... L>(std::tuple<L...>*) {
            return ((same_member_pointer<L::to_actor, Actor>() && same_member_pointer<L::to_channel, Channel>()) || ...);
        }(static_cast<links*>(nullptr));
        // clang-format on
    }

    template <std::size_t I>
    static constexpr bool check_step() {
        if constexpr (!first_in_order<I>())
            return report<error::actor_twice_in_order<step_at<I>>>();
        else
            return true;
    }

    template <class L>
    static constexpr bool check_link() {
        if constexpr (!link_options_rules<typename L::options>::check()) {
            return false;
        } else {
            constexpr bool from_in = in_order<L::from_actor>();
            constexpr bool to_in = in_order<L::to_actor>();
            if constexpr (!from_in) report<error::actor_not_in_order<L::from_actor>>();
            if constexpr (!to_in) report<error::actor_not_in_order<L::to_actor>>();
            if constexpr (!from_in || !to_in) {
                return false;
            } else {
                constexpr bool source = publishes<Actors, L::from_actor, L::from_channel>();
                constexpr bool target = written_from_outside<Actors, L::to_actor, L::to_channel>();
                if constexpr (!source) report<error::link_source_not_an_output<L::from_actor, L::from_channel>>();
                if constexpr (!target) report<error::link_target_not_an_input<L::to_actor, L::to_channel>>();
                if constexpr (!source || !target) {
                    return false;
                } else {
                    using from = channel_value<member_of_actor<Actors, L::from_actor, L::from_channel>>;
                    using to = channel_value<member_of_actor<Actors, L::to_actor, L::to_channel>>;
                    using conversion = typename L::conversion;
                    if constexpr (std::is_same_v<conversion, no_conversion> && !std::is_same_v<from, to>)
                        return report<error::link_value_types_differ<L::from_channel, L::to_channel, from, to>>();
                    else if constexpr (!std::is_same_v<conversion, no_conversion> &&
                                       !conversion_applies<conversion, from, to>)
                        return report<error::link_conversion_not_applicable<conversion, from, to>>();
                    else
                        return true;
                }
            }
        }
    }

    // Link I drives an input that an earlier link drives already.
    template <std::size_t I>
    static constexpr bool check_driven_once() {
        using L = std::tuple_element_t<I, links>;
        // clang-format off
        constexpr bool earlier = []<std::size_t... J>(std::index_sequence<J...>) {
            return ((same_member_pointer<std::tuple_element_t<J, links>::to_actor, L::to_actor>() &&
                     same_member_pointer<std::tuple_element_t<J, links>::to_channel, L::to_channel>()) ||
                    ...);
        }(std::make_index_sequence<I>{});
        // clang-format on
        if constexpr (earlier)
            return report<error::input_driven_twice<L::to_actor, L::to_channel>>();
        else
            return true;
    }

    template <class F>
    static constexpr bool check_from_outside() {
        if constexpr (!in_order<F::actor>())
            return report<error::actor_not_in_order<F::actor>>();
        else if constexpr (!written_from_outside<Actors, F::actor, F::channel>())
            return report<error::from_outside_not_an_input<F::actor, F::channel>>();
        else if constexpr (linked<F::actor, F::channel>())
            return report<error::input_linked_and_from_outside<F::actor, F::channel>>();
        else
            return true;
    }

    template <class Entry>
    static constexpr bool check_entry() {
        if constexpr (is_link<Entry>)
            return check_link<Entry>();
        else if constexpr (is_from_outside<Entry>)
            return check_from_outside<Entry>();
        else
            return report<error::not_a_link<Entry>>();
    }

    // The members of Actor's context that a link or a from_outside entry drives (one more
    // than the members, for a channel found nowhere).
    template <auto Actor, class Context>
    static constexpr auto driven_members() {
        std::array<bool, member_count<Context> + 1> driven{};
        auto mark = [&]<auto A, auto Channel>() {
            if constexpr (same_member_pointer<A, Actor>()) driven[member_index<Channel>()] = true;
        };
        // clang-format off
        []<class... L>(std::tuple<L...>*, auto& m) {
            (m.template operator()<L::to_actor, L::to_channel>(), ...);
        }(static_cast<links*>(nullptr), mark);
        // clang-format on
        // clang-format off
        []<class... F>(std::tuple<F...>*, auto& m) {
            (m.template operator()<F::actor, F::channel>(), ...);
        }(static_cast<declared_outside*>(nullptr), mark);
        // clang-format on
        return driven;
    }
    template <auto Actor, class Context>
    static constexpr auto driven_of = driven_members<Actor, Context>();

    template <auto Actor, class Context, std::size_t K>
    static constexpr bool check_input_driven() {
        using member = std::tuple_element_t<K, typename tuple_of_list<member_types<Context>>::type>;
        if constexpr (is_input_channel<std::remove_cv_t<member>> && !driven_of<Actor, Context>[K])
            return report<
                error::input_not_driven<Actor, error::member_number<K>, member_name_argument<Context, K>()>>();
        else
            return true;
    }
    template <auto Actor, class Context, std::size_t... K>
    static constexpr bool check_members_driven(std::index_sequence<K...>) {
        return ((check_input_driven<Actor, Context, K>() ? 0 : 1) + ... + 0) == 0;
    }

    // Every bsc::input member of the context of the order's I-th actor is driven. Only an
    // aggregate context is looked into: one described by bsc::fields or Boost.Hana may keep its
    // channels private, where neither a link nor from_outside can name them. Inputs nested in a
    // struct or a std::array of the context are not looked for: no link can name them.
    template <std::size_t I>
    static constexpr bool check_inputs_driven() {
        constexpr auto actor = step_at<I>;
        if constexpr (!first_in_order<I>() || !actor_with_context<Actors, actor>) {
            return true;
        } else {
            using context = context_of_actor<Actors, actor>;
            if constexpr (!std::is_class_v<context> || !std::is_aggregate_v<context> || described_by_fields<context> ||
                          kind_of<context>() != member_kind::record)
                return true;
            else
                return check_members_driven<actor, context>(std::make_index_sequence<member_count<context>>{});
        }
    }

    static constexpr bool check() {
        // clang-format off
        constexpr bool steps = []<std::size_t... I>(std::index_sequence<I...>) {
            return ((check_step<I>() ? 0 : 1) + ... + 0) == 0;
        }(std::index_sequence_for<decltype(Steps)...>{});
        // clang-format on
        constexpr bool entries = ((check_entry<Entries>() ? 0 : 1) + ... + 0) == 0;
        // clang-format off
        constexpr bool once = []<std::size_t... I>(std::index_sequence<I...>) {
            return ((check_driven_once<I>() ? 0 : 1) + ... + 0) == 0;
        }(std::make_index_sequence<std::tuple_size_v<links>>{});
        // clang-format on
        if constexpr (!entries || !once) {
            return false;
        } else {
            // clang-format off
            constexpr bool inputs = []<std::size_t... I>(std::index_sequence<I...>) {
                return ((check_inputs_driven<I>() ? 0 : 1) + ... + 0) == 0;
            }(std::index_sequence_for<decltype(Steps)...>{});
            // clang-format on
            return steps && inputs;
        }
    }
};

}  // namespace detail

template <class Actors, class Order, class... Links>
struct system;

/// A system: the aggregate `Actors` of machines (anything with `context()` and `step(now)`),
/// stepped in `Order`, with `Links` delivering signals and `bsc::from_outside` entries naming the
/// inputs the environment sets. `actors` is a public member, so a system is itself an aggregate
/// that the explorer can encode. No heap. The wiring is checked where the type is instantiated
/// (detail::system_rules): each defect is one compile error, and a system with one does nothing.
template <class Actors, auto... Steps, class... Links>
struct system<Actors, order<Steps...>, Links...> {
    using actors_type = Actors;
    using order_type = order<Steps...>;
    /// The links, in their order (the bsc::from_outside entries left out).
    using links_type = detail::entries_such<detail::link_entry, Links...>;
    /// The bsc::from_outside entries, in their order.
    using from_outside_type = detail::entries_such<detail::from_outside_entry, Links...>;
    /// Whether the wiring passed every check.
    static constexpr bool well_formed = detail::system_rules<Actors, order<Steps...>, Links...>::check();
    static_assert(well_formed || true);  // instantiates the checks here (their errors are the report)

    Actors actors;

    /// One step of every actor, in order: each first receives the signals linked to it (the
    /// outputs its senders published, this step for senders earlier in the order, the last
    /// step for the others), then runs one cycle at `now`.
    constexpr system_report step(duration now) {
        system_report report;
        if constexpr (well_formed)
            (step_one<Steps>(now, report), ...);
        else
            (void)now;
        return report;
    }

private:
    template <auto Actor>
    constexpr void step_one(duration now, system_report& report) {
        // clang-format off
        []<class... L>(std::tuple<L...>*, Actors& all) {
            ((L::template targets<Actor>() ? L::transfer(all) : void()), ...);
        }(static_cast<links_type*>(nullptr), actors);
        // clang-format on
        auto const r = (actors.*Actor).step(now);
        report.transitions += r.transitions;
        report.queue_overflow = report.queue_overflow || r.status == outcome::queue_overflow;
        report.livelock = report.livelock || r.status == outcome::livelock;
        report.halted = report.halted || r.status == outcome::halted || (actors.*Actor).halted();
    }
};

}  // namespace bsc
