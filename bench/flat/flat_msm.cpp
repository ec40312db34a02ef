// Workload flat, Boost.MSM: back::state_machine, functor rows, the generated table of
// flat/flat_chart_msm.hpp (no_exception_thrown and no_message_queue, MSM's options for speed).
// C++17 (bench/CMakeLists.txt).

#include "flat_workload.hpp"
#define BENCH_FLAT_N 50
#include "flat_chart_msm.hpp"

namespace {

static_assert(flat_msm::N == flat_bench::workload::states);

class flat_machine {
public:
    flat_machine() { m_.start(); }
    flat_machine(flat_machine const&) = delete;
    flat_machine& operator=(flat_machine const&) = delete;

    void on(std::uint8_t event) {
        bench::with_index<flat_msm::N>(event, [&](auto i) { m_.process_event(flat_msm::E<decltype(i)::value>{}); });
    }

    flat_bench::workload::observation observe() const {
        std::size_t state = 0;
        int const id = m_.current_state()[0];
        observe_each(id, state, std::make_index_sequence<flat_msm::N>{});
        return {state, m_.count};
    }

private:
    template <std::size_t... I>
    static void observe_each(int id, std::size_t& state, std::index_sequence<I...>) {
        ((id == boost::msm::back::get_state_id<flat_msm::machine::stt, flat_msm::S<I>>::value ? (void)(state = I)
                                                                                              : (void)0),
         ...);
    }

    flat_msm::machine m_;
};

}  // namespace

BENCH_IMPL(flat_bench::workload, "boost_msm", flat_machine);
