// Workload sml_complex, hand-written: a switch on the event, and in each case the one state
// that takes it (the guard holds and the action does nothing, so neither is written).

#include <cstdint>

#include "sml_complex_workload.hpp"

namespace {

class ring_switch {
public:
    void on(std::uint8_t e) {
        switch (e) {
        case 0:
            if (state_ == 0) state_ = 1;
            break;
        case 1:
            if (state_ == 1) state_ = 2;
            break;
        case 2:
            if (state_ == 2) state_ = 3;
            break;
        case 3:
            if (state_ == 3) state_ = 4;
            break;
        case 4:
            if (state_ == 4) state_ = 5;
            break;
        case 5:
            if (state_ == 5) state_ = 6;
            break;
        case 6:
            if (state_ == 6) state_ = 7;
            break;
        case 7:
            if (state_ == 7) state_ = 8;
            break;
        case 8:
            if (state_ == 8) state_ = 9;
            break;
        case 9:
            if (state_ == 9) state_ = 10;
            break;
        case 10:
            if (state_ == 10) state_ = 11;
            break;
        case 11:
            if (state_ == 11) state_ = 12;
            break;
        case 12:
            if (state_ == 12) state_ = 13;
            break;
        case 13:
            if (state_ == 13) state_ = 14;
            break;
        case 14:
            if (state_ == 14) state_ = 15;
            break;
        case 15:
            if (state_ == 15) state_ = 16;
            break;
        case 16:
            if (state_ == 16) state_ = 17;
            break;
        case 17:
            if (state_ == 17) state_ = 18;
            break;
        case 18:
            if (state_ == 18) state_ = 19;
            break;
        case 19:
            if (state_ == 19) state_ = 20;
            break;
        case 20:
            if (state_ == 20) state_ = 21;
            break;
        case 21:
            if (state_ == 21) state_ = 22;
            break;
        case 22:
            if (state_ == 22) state_ = 23;
            break;
        case 23:
            if (state_ == 23) state_ = 24;
            break;
        case 24:
            if (state_ == 24) state_ = 25;
            break;
        case 25:
            if (state_ == 25) state_ = 26;
            break;
        case 26:
            if (state_ == 26) state_ = 27;
            break;
        case 27:
            if (state_ == 27) state_ = 28;
            break;
        case 28:
            if (state_ == 28) state_ = 29;
            break;
        case 29:
            if (state_ == 29) state_ = 30;
            break;
        case 30:
            if (state_ == 30) state_ = 31;
            break;
        case 31:
            if (state_ == 31) state_ = 32;
            break;
        case 32:
            if (state_ == 32) state_ = 33;
            break;
        case 33:
            if (state_ == 33) state_ = 34;
            break;
        case 34:
            if (state_ == 34) state_ = 35;
            break;
        case 35:
            if (state_ == 35) state_ = 36;
            break;
        case 36:
            if (state_ == 36) state_ = 37;
            break;
        case 37:
            if (state_ == 37) state_ = 38;
            break;
        case 38:
            if (state_ == 38) state_ = 39;
            break;
        case 39:
            if (state_ == 39) state_ = 40;
            break;
        case 40:
            if (state_ == 40) state_ = 41;
            break;
        case 41:
            if (state_ == 41) state_ = 42;
            break;
        case 42:
            if (state_ == 42) state_ = 43;
            break;
        case 43:
            if (state_ == 43) state_ = 44;
            break;
        case 44:
            if (state_ == 44) state_ = 45;
            break;
        case 45:
            if (state_ == 45) state_ = 46;
            break;
        case 46:
            if (state_ == 46) state_ = 47;
            break;
        case 47:
            if (state_ == 47) state_ = 48;
            break;
        case 48:
            if (state_ == 48) state_ = 49;
            break;
        case 49:
            if (state_ == 49) state_ = 0;
            break;
        default: break;
        }
    }
    sml_complex_bench::workload::observation observe() const { return {state_}; }

private:
    std::size_t state_ = 0;
};

}  // namespace

BENCH_IMPL(sml_complex_bench::workload, "hand_written", ring_switch);
