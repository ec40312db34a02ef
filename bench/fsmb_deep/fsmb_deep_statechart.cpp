// Workload fsmb_deep, Boost.Statechart: lvl0_x and lvl1_xy are sc::simple_state with inner
// states, lvl2_xyz sc::simple_state whose exit() adds to the counter, all generated with
// templates. Statechart has no completion events: each final state is an sc::state whose entry
// action (its constructor) posts its composite's completion event (lvl1_done<x, y>,
// lvl0_done<x>), which the composite takes with an sc::transition once the current event is
// done. The completion events are built once, held by the machine through intrusive_ptrs and
// posted by them (posting a temporary would copy it to the heap every time).

#include <boost/intrusive_ptr.hpp>
#include <boost/mpl/list.hpp>
#include <boost/statechart/event.hpp>
#include <boost/statechart/simple_state.hpp>
#include <boost/statechart/state.hpp>
#include <boost/statechart/state_machine.hpp>
#include <boost/statechart/transition.hpp>
#include <tuple>
#include <type_traits>
#include <utility>

#include "fsmb_deep_workload.hpp"

// The events have external linkage: an sc::transition without an action names, as a template
// argument, a member function of Statechart's that is declared for its event type and never
// defined, which Clang rejects when that type has internal linkage.
namespace fsmb_deep_statechart_events {
template <int K>
struct event : boost::statechart::event<event<K>> {};  // the event of basic state 9x + 3y + z
template <int X, int Y>
struct lvl1_done : boost::statechart::event<lvl1_done<X, Y>> {};  // the completion event of lvl1_xy
template <int X>
struct lvl0_done : boost::statechart::event<lvl0_done<X>> {};  // the completion event of lvl0_x
}  // namespace fsmb_deep_statechart_events

namespace {

namespace sc = boost::statechart;
namespace mpl = boost::mpl;
using namespace fsmb_deep_statechart_events;

template <int X>
struct lvl0;
template <int X, int Y>
struct lvl1;
template <int X, int Y, int Z>
struct lvl2;

// Events to post, each built once and held through an intrusive_ptr.
template <class... E>
struct prebuilt {
    std::tuple<boost::intrusive_ptr<E const>...> events{boost::intrusive_ptr<E const>(new E)...};
    template <class E1>
    boost::intrusive_ptr<E1 const> const& get() const {
        return std::get<boost::intrusive_ptr<E1 const>>(events);
    }
};

struct Machine : sc::state_machine<Machine, lvl0<0>> {
    std::uint64_t counter = 0;
    prebuilt<lvl1_done<0, 0>, lvl1_done<0, 1>, lvl1_done<0, 2>, lvl1_done<1, 0>, lvl1_done<1, 1>, lvl1_done<1, 2>,
             lvl1_done<2, 0>, lvl1_done<2, 1>, lvl1_done<2, 2>, lvl0_done<0>, lvl0_done<1>, lvl0_done<2>> const done{};
};

// A final state of Composite: its entry action posts Completion, Composite's completion event.
template <class Self, class Composite, class Completion>
struct final_state : sc::state<Self, Composite> {
    using base = sc::state<Self, Composite>;
    explicit final_state(typename base::my_context ctx) : base(ctx) {
        this->post_event(this->outermost_context().done.template get<Completion>());
    }
};

template <int X>
struct final0;  // lvl0_x's final state
template <int X, int Y>
struct final1;  // lvl1_xy's final state

// The composites name their inner initial state in a one-element mpl::list, which Statechart
// accepts too: named directly, a specialization of a class template would be instantiated by
// Statechart's test of whether it is a list, while its outer state is still incomplete.
template <int X>
struct lvl0 : sc::simple_state<lvl0<X>, Machine, mpl::list<lvl1<X, 0>>> {
    using reactions = sc::transition<lvl0_done<X>, lvl0<(X + 1) % 3>>;
};
template <int X>
struct final0 : final_state<final0<X>, lvl0<X>, lvl0_done<X>> {
    using final_state<final0<X>, lvl0<X>, lvl0_done<X>>::final_state;
};

template <int X, int Y>
struct lvl1 : sc::simple_state<lvl1<X, Y>, lvl0<X>, mpl::list<lvl2<X, Y, 0>>> {
    using reactions = sc::transition<lvl1_done<X, Y>, std::conditional_t<(Y < 2), lvl1<X, Y + 1>, final0<X>>>;
};
template <int X, int Y>
struct final1 : final_state<final1<X, Y>, lvl1<X, Y>, lvl1_done<X, Y>> {
    using final_state<final1<X, Y>, lvl1<X, Y>, lvl1_done<X, Y>>::final_state;
};

template <int X, int Y, int Z>
struct lvl2 : sc::simple_state<lvl2<X, Y, Z>, lvl1<X, Y>> {
    using reactions =
        sc::transition<event<9 * X + 3 * Y + Z>, std::conditional_t<(Z < 2), lvl2<X, Y, Z + 1>, final1<X, Y>>>;
    void exit() { this->outermost_context().counter += X + Y + Z + 1; }
};

template <class Seq>
struct events_of;
template <int... K>
struct events_of<std::integer_sequence<int, K...>> {
    using type = std::tuple<event<K>...>;
};

class deep_machine {
public:
    deep_machine() { m_.initiate(); }
    deep_machine(deep_machine const&) = delete;
    deep_machine& operator=(deep_machine const&) = delete;

    void on(std::uint8_t e) {
        bench::with_index<leaves>(e, [&](auto k) { m_.process_event(std::get<decltype(k)::value>(events_)); });
    }

    fsmb_deep_bench::workload::observation observe() const {
        std::size_t leaf = 0;
        find(leaf, std::make_integer_sequence<int, int(leaves)>{});
        return {leaf, m_.counter};
    }

private:
    static constexpr std::size_t leaves = fsmb_deep_bench::workload::leaves;

    template <int... K>
    void find(std::size_t& leaf, std::integer_sequence<int, K...>) const {
        ((m_.state_cast<lvl2<K / 9, K / 3 % 3, K % 3> const*>() ? (void)(leaf = K) : (void)0), ...);
    }

    Machine m_;
    // Statechart events are reference-counted objects: built once, dispatched by reference.
    typename events_of<std::make_integer_sequence<int, int(leaves)>>::type events_;
};

}  // namespace

BENCH_IMPL(fsmb_deep_bench::workload, "boost_statechart", deep_machine);
