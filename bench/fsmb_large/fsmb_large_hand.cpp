// Workload fsmb_large, hand-written: a switch on the event; the exit action's ievent is a flag
// that the code after the transition tests, as a queue of at most one event.

#include <cstdint>

#include "fsmb_large_workload.hpp"

namespace {

struct sevent {
    int two = 2;
};
struct ievent {
    int two = 2;
};

class large_switch {
public:
    void on(std::uint8_t e) {
        switch (e) {
        case 0: take(sevent{}, 0, 1); break;
        case 1: take(sevent{}, 1, 2); break;
        case 2: take(sevent{}, 2, 3); break;
        case 3: take(sevent{}, 3, 4); break;
        case 4: take(sevent{}, 4, 5); break;
        case 5: take(sevent{}, 5, 6); break;
        case 6: take(sevent{}, 6, 7); break;
        case 7: take(sevent{}, 7, 8); break;
        case 8: take(sevent{}, 8, 9); break;
        case 9: take(sevent{}, 9, 10); break;
        case 10: take(sevent{}, 10, 11); break;
        case 11: take(sevent{}, 11, 12); break;
        case 12: take(sevent{}, 12, 13); break;
        case 13: take(sevent{}, 13, 14); break;
        case 14: take(sevent{}, 14, 15); break;
        case 15: take(sevent{}, 15, 16); break;
        case 16: take(sevent{}, 16, 17); break;
        case 17: take(sevent{}, 17, 18); break;
        case 18: take(sevent{}, 18, 19); break;
        case 19: take(sevent{}, 19, 20); break;
        case 20: take(sevent{}, 20, 21); break;
        case 21: take(sevent{}, 21, 22); break;
        case 22: take(sevent{}, 22, 23); break;
        case 23: take(sevent{}, 23, 24); break;
        case 24: take(sevent{}, 24, 0); break;
        default: break;
        }
        while (pending_) {  // the raised ievent, in the new state: its internal transition
            pending_ = false;
            counter_ /= ievent{}.two;
        }
    }
    fsmb_large_bench::workload::observation observe() const { return {state_, counter_}; }

private:
    void take(sevent e, std::size_t from, std::size_t to) {
        if (state_ != from || e.two < 0) return;
        pending_ = true;  // state from's exit action raises ievent
        counter_ = (counter_ + 1) * e.two;
        state_ = to;
    }
    std::size_t state_ = 0;
    int counter_ = 0;
    bool pending_ = false;
};

}  // namespace

BENCH_IMPL(fsmb_large_bench::workload, "hand_written", large_switch);
