// Workload fsmb_deep, Boost.MSM: back::state_machine with the functor front end; every lvl0_x and
// lvl1_xy is a submachine (generated with templates) whose final state is a plain state. MSM
// raises no completion event when a submachine reaches it: the completion of lvl1_xy (of lvl0_x)
// is an anonymous transition (event none) from the submachine in its containing machine, guarded
// by `completed`, which holds when the submachine's active state is its final state; MSM tries a
// machine's anonymous transitions after every event that machine handles. Leaving lvl2_xyz adds
// to the counter, reached through a pointer set in every lvl1_xy before start().
// no_exception_thrown and no_message_queue are set. C++17 (bench/CMakeLists.txt).

#include <boost/msm/back/state_machine.hpp>
#include <boost/msm/front/functor_row.hpp>
#include <boost/msm/front/state_machine_def.hpp>
#include <utility>

#include "fsmb_deep_workload.hpp"

namespace {

namespace msm = boost::msm;
namespace mpl = boost::mpl;
using msm::front::none;
using msm::front::Row;

template <int K>
struct event {};  // the event of basic state 9x + 3y + z

template <class Self>
struct machine_base : msm::front::state_machine_def<Self> {
    using no_exception_thrown = int;
    using no_message_queue = int;
    template <class E, class F>
    void no_transition(E const&, F&, int) {}
};

// The guard of a completion: the submachine that is the transition's source is in its final state.
template <class Final>
struct completed {
    template <class E, class F, class S, class T>
    bool operator()(E const&, F&, S& sub, T&) const {
        return sub.current_state()[0] == msm::back::get_state_id<typename S::stt, Final>::value;
    }
};

// ---- lvl1_xy ----------------------------------------------------------------------------------
template <int X, int Y, int Z>
struct lvl2 : msm::front::state<> {
    template <class E, class F>
    void on_exit(E const&, F& fsm) {
        *fsm.counter += X + Y + Z + 1;
    }
};
template <int X, int Y>
struct final1 : msm::front::state<> {};  // lvl1_xy's final state

template <int X, int Y>
struct lvl1_ : machine_base<lvl1_<X, Y>> {
    using initial_state = lvl2<X, Y, 0>;
    using transition_table = mpl::vector<Row<lvl2<X, Y, 0>, event<9 * X + 3 * Y>, lvl2<X, Y, 1>, none, none>,
                                         Row<lvl2<X, Y, 1>, event<9 * X + 3 * Y + 1>, lvl2<X, Y, 2>, none, none>,
                                         Row<lvl2<X, Y, 2>, event<9 * X + 3 * Y + 2>, final1<X, Y>, none, none>>;
    std::uint64_t* counter = nullptr;
};
template <int X, int Y>
using lvl1 = msm::back::state_machine<lvl1_<X, Y>>;

// ---- lvl0_x -----------------------------------------------------------------------------------
template <int X>
struct final0 : msm::front::state<> {};  // lvl0_x's final state

template <int X>
struct lvl0_ : machine_base<lvl0_<X>> {
    using initial_state = lvl1<X, 0>;
    using transition_table = mpl::vector<Row<lvl1<X, 0>, none, lvl1<X, 1>, none, completed<final1<X, 0>>>,
                                         Row<lvl1<X, 1>, none, lvl1<X, 2>, none, completed<final1<X, 1>>>,
                                         Row<lvl1<X, 2>, none, final0<X>, none, completed<final1<X, 2>>>>;
};
template <int X>
using lvl0 = msm::back::state_machine<lvl0_<X>>;

// ---- Root -------------------------------------------------------------------------------------
struct root_ : machine_base<root_> {
    using initial_state = lvl0<0>;
    using transition_table = mpl::vector<Row<lvl0<0>, none, lvl0<1>, none, completed<final0<0>>>,
                                         Row<lvl0<1>, none, lvl0<2>, none, completed<final0<1>>>,
                                         Row<lvl0<2>, none, lvl0<0>, none, completed<final0<2>>>>;
};
using root = msm::back::state_machine<root_>;

class deep_machine {
public:
    deep_machine() {
        wire(std::make_integer_sequence<int, 9>{});
        m_.start();
    }
    deep_machine(deep_machine const&) = delete;
    deep_machine& operator=(deep_machine const&) = delete;

    void on(std::uint8_t e) {
        bench::with_index<fsmb_deep_bench::workload::leaves>(
            e, [&](auto k) { m_.process_event(event<static_cast<int>(decltype(k)::value)>{}); });
    }

    fsmb_deep_bench::workload::observation observe() const {
        int const id = m_.current_state()[0];
        std::size_t const leaf = id == state_id<root, lvl0<0>>   ? leaf_of(m_.get_state<lvl0<0> const&>())
                                 : id == state_id<root, lvl0<1>> ? leaf_of(m_.get_state<lvl0<1> const&>())
                                                                 : leaf_of(m_.get_state<lvl0<2> const&>());
        return {leaf, counter_};
    }

private:
    template <class SM, class S>
    static constexpr int state_id = msm::back::get_state_id<typename SM::stt, S>::value;

    // Every lvl1_xy (K = 3x + y) gets the counter.
    template <int... K>
    void wire(std::integer_sequence<int, K...>) {
        ((m_.get_state<lvl0<K / 3>&>().template get_state<lvl1<K / 3, K % 3>&>().counter = &counter_), ...);
    }

    template <int X, int Y>
    static std::size_t leaf_of(lvl1<X, Y> const& m) {
        int const id = m.current_state()[0];
        int const z = id == state_id<lvl1<X, Y>, lvl2<X, Y, 0>> ? 0 : id == state_id<lvl1<X, Y>, lvl2<X, Y, 1>> ? 1 : 2;
        return static_cast<std::size_t>(9 * X + 3 * Y + z);
    }
    template <int X>
    static std::size_t leaf_of(lvl0<X> const& m) {
        int const id = m.current_state()[0];
        if (id == state_id<lvl0<X>, lvl1<X, 0>>) return leaf_of(m.template get_state<lvl1<X, 0> const&>());
        if (id == state_id<lvl0<X>, lvl1<X, 1>>) return leaf_of(m.template get_state<lvl1<X, 1> const&>());
        return leaf_of(m.template get_state<lvl1<X, 2> const&>());
    }

    std::uint64_t counter_ = 0;
    root m_;
};

}  // namespace

BENCH_IMPL(fsmb_deep_bench::workload, "boost_msm", deep_machine);
