// Workload deep, Boost.MSM: D1..D7 are submachines nested seven deep (back::state_machine of
// back::state_machine ...), D8 a state; each submachine's table holds the two rows of the level
// below it, the top machine's those of level 1. MSM forwards an event to the active
// submachine first, which is how it finds the level. no_exception_thrown and no_message_queue
// are set. The counters are reached through a pointer set in every machine before start().
// C++17 (bench/CMakeLists.txt).

#include <boost/msm/back/state_machine.hpp>
#include <boost/msm/front/functor_row.hpp>
#include <boost/msm/front/state_machine_def.hpp>

#include "deep_workload.hpp"

namespace {

namespace msm = boost::msm;
namespace mpl = boost::mpl;
using msm::front::none;
using msm::front::Row;

struct counters {
    std::uint64_t count = 0;
    std::uint64_t entries = 0;
};
struct with_counters {
    counters* c = nullptr;
};

template <int K>
struct L {};

template <int K>
struct P : msm::front::state<> {};

struct D8 : msm::front::state<> {
    template <class E, class F>
    void on_entry(E const&, F& fsm) {
        ++fsm.c->entries;
    }
};

template <int K>
struct leave {
    template <class E, class F, class S, class T>
    void operator()(E const&, F& fsm, S&, T&) const {
        fsm.c->count += static_cast<std::uint64_t>(K);
    }
};
template <int K>
struct come_back {
    template <class E, class F, class S, class T>
    void operator()(E const&, F& fsm, S&, T&) const {
        fsm.c->count += 100u * static_cast<std::uint64_t>(K);
    }
};

template <int K>
struct D_;
template <int K>
struct level {
    using type = msm::back::state_machine<D_<K>>;
};
template <>
struct level<8> {
    using type = D8;
};
template <int K>
using D = typename level<K>::type;

template <class Self>
struct machine_base : msm::front::state_machine_def<Self>, with_counters {
    using no_exception_thrown = int;
    using no_message_queue = int;
    template <class E, class F>
    void no_transition(E const&, F&, int) {}
};

// Submachine Dk (k < 8): the rows of level k + 1.
template <int K>
struct D_ : machine_base<D_<K>> {
    using initial_state = D<K + 1>;
    using transition_table = mpl::vector<Row<D<K + 1>, L<K + 1>, P<K + 1>, leave<K + 1>, none>,
                                         Row<P<K + 1>, L<K + 1>, D<K + 1>, come_back<K + 1>, none>>;
    template <class E, class F>
    void on_entry(E const&, F&) {
        ++this->c->entries;
    }
};

struct R_ : machine_base<R_> {
    using initial_state = D<1>;
    using transition_table =
        mpl::vector<Row<D<1>, L<1>, P<1>, leave<1>, none>, Row<P<1>, L<1>, D<1>, come_back<1>, none>>;
};
using R = msm::back::state_machine<R_>;

class deep_machine {
public:
    deep_machine() {
        m_.c = &c_;
        wire<1>(m_.get_state<D<1>&>());
        m_.start();
    }
    deep_machine(deep_machine const&) = delete;
    deep_machine& operator=(deep_machine const&) = delete;

    void on(std::uint8_t event) {
        bench::with_index<deep_bench::levels>(event,
                                              [&](auto i) { m_.process_event(L<int(decltype(i)::value) + 1>{}); });
    }

    deep_bench::workload::observation observe() const { return {depth<1>(m_), c_.count, c_.entries}; }

private:
    template <int K, class SM>
    void wire(SM& sm) {
        sm.c = &c_;
        if constexpr (K < 7) wire<K + 1>(sm.template get_state<D<K + 1>&>());
    }
    // The depth below machine `sm`, whose active child is Dk or Pk.
    template <int K, class SM>
    static int depth(SM const& sm) {
        int const id = sm.current_state()[0];
        if (id == msm::back::get_state_id<typename SM::stt, P<K>>::value) return K - 1;
        if constexpr (K == 8)
            return 8;
        else
            return depth<K + 1>(sm.template get_state<D<K> const&>());
    }

    counters c_;
    R m_;
};

}  // namespace

BENCH_IMPL(deep_bench::workload, "boost_msm", deep_machine);
