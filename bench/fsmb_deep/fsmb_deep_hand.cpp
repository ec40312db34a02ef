// Workload fsmb_deep, hand-written: a switch on the event, and in each case the one basic state
// that takes it. What the chart does through its final states and completions (leave the
// composites whose last child is done, enter the next one at its initial state) is, written by
// hand, a move to the next basic state in document order.

#include <cstdint>

#include "fsmb_deep_workload.hpp"

namespace {

class deep_switch {
public:
    void on(std::uint8_t e) {
        switch (e) {
        case 0:
            if (leaf_ == 0) {
                counter_ += 1;
                leaf_ = 1;
            }
            break;
        case 1:
            if (leaf_ == 1) {
                counter_ += 2;
                leaf_ = 2;
            }
            break;
        case 2:
            if (leaf_ == 2) {
                counter_ += 3;
                leaf_ = 3;
            }
            break;
        case 3:
            if (leaf_ == 3) {
                counter_ += 2;
                leaf_ = 4;
            }
            break;
        case 4:
            if (leaf_ == 4) {
                counter_ += 3;
                leaf_ = 5;
            }
            break;
        case 5:
            if (leaf_ == 5) {
                counter_ += 4;
                leaf_ = 6;
            }
            break;
        case 6:
            if (leaf_ == 6) {
                counter_ += 3;
                leaf_ = 7;
            }
            break;
        case 7:
            if (leaf_ == 7) {
                counter_ += 4;
                leaf_ = 8;
            }
            break;
        case 8:
            if (leaf_ == 8) {
                counter_ += 5;
                leaf_ = 9;
            }
            break;
        case 9:
            if (leaf_ == 9) {
                counter_ += 2;
                leaf_ = 10;
            }
            break;
        case 10:
            if (leaf_ == 10) {
                counter_ += 3;
                leaf_ = 11;
            }
            break;
        case 11:
            if (leaf_ == 11) {
                counter_ += 4;
                leaf_ = 12;
            }
            break;
        case 12:
            if (leaf_ == 12) {
                counter_ += 3;
                leaf_ = 13;
            }
            break;
        case 13:
            if (leaf_ == 13) {
                counter_ += 4;
                leaf_ = 14;
            }
            break;
        case 14:
            if (leaf_ == 14) {
                counter_ += 5;
                leaf_ = 15;
            }
            break;
        case 15:
            if (leaf_ == 15) {
                counter_ += 4;
                leaf_ = 16;
            }
            break;
        case 16:
            if (leaf_ == 16) {
                counter_ += 5;
                leaf_ = 17;
            }
            break;
        case 17:
            if (leaf_ == 17) {
                counter_ += 6;
                leaf_ = 18;
            }
            break;
        case 18:
            if (leaf_ == 18) {
                counter_ += 3;
                leaf_ = 19;
            }
            break;
        case 19:
            if (leaf_ == 19) {
                counter_ += 4;
                leaf_ = 20;
            }
            break;
        case 20:
            if (leaf_ == 20) {
                counter_ += 5;
                leaf_ = 21;
            }
            break;
        case 21:
            if (leaf_ == 21) {
                counter_ += 4;
                leaf_ = 22;
            }
            break;
        case 22:
            if (leaf_ == 22) {
                counter_ += 5;
                leaf_ = 23;
            }
            break;
        case 23:
            if (leaf_ == 23) {
                counter_ += 6;
                leaf_ = 24;
            }
            break;
        case 24:
            if (leaf_ == 24) {
                counter_ += 5;
                leaf_ = 25;
            }
            break;
        case 25:
            if (leaf_ == 25) {
                counter_ += 6;
                leaf_ = 26;
            }
            break;
        case 26:
            if (leaf_ == 26) {
                counter_ += 7;
                leaf_ = 0;
            }
            break;
        default: break;
        }
    }
    fsmb_deep_bench::workload::observation observe() const { return {leaf_, counter_}; }

private:
    std::size_t leaf_ = 0;
    std::uint64_t counter_ = 0;
};

}  // namespace

BENCH_IMPL(fsmb_deep_bench::workload, "hand_written", deep_switch);
