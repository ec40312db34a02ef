// Workload wide, hand-written: one state byte per region and a loop over the regions, each
// switching on its state for the event.

#include "wide_workload.hpp"

namespace {

using namespace wide_bench;

class wide_machine {
public:
    wide_machine() {
        for (std::size_t r = 0; r < regions; ++r) s_[r] = static_cast<std::uint8_t>(initial_of(int(r)));
    }

    void on(std::uint8_t event) {
        switch (event) {
        case 0:  // step
            for (std::size_t r = 0; r < regions; ++r) {
                s_[r] = s_[r] == 2 ? 0 : static_cast<std::uint8_t>(s_[r] + 1);
                n_[r] += 1;
            }
            break;
        case 1:  // reset
            for (std::size_t r = 0; r < regions; ++r)
                if (s_[r] != 0) {
                    s_[r] = 0;
                    n_[r] += 16;
                }
            break;
        case 2:  // flip
            for (std::size_t r = 0; r < regions; ++r)
                if (s_[r] == 0) {
                    s_[r] = static_cast<std::uint8_t>(flip_target(int(r)));
                    n_[r] += 4;
                }
            break;
        default: break;
        }
    }

    workload::observation observe() const { return {s_, n_}; }

private:
    std::array<std::uint8_t, regions> s_{};
    std::array<std::uint64_t, regions> n_{};
};

}  // namespace

BENCH_IMPL(wide_bench::workload, "hand_written", wide_machine);
