// Workload deep, hand-written, two ways. The configuration is the depth d of the active D
// states (D1..Dd active, and P(d+1) when d < 8).
//
// hand_written: the reference: a switch on the event, and in each case the two transitions of
// that level as an if on the depth.
//
// hand_minimal: the shortest code for this particular chart, for context: the level is the
// event number, so no switch is needed at all.

#include "deep_workload.hpp"

namespace {

class deep_switch {
public:
    void on(std::uint8_t event) {
        switch (event) {
        case 0:  // L1
            if (depth_ >= 1) {
                count_ += 1;
                depth_ = 0;
            } else if (depth_ == 0) {
                count_ += 100;
                entries_ += 8;
                depth_ = 8;
            }
            break;
        case 1:  // L2
            if (depth_ >= 2) {
                count_ += 2;
                depth_ = 1;
            } else if (depth_ == 1) {
                count_ += 200;
                entries_ += 7;
                depth_ = 8;
            }
            break;
        case 2:  // L3
            if (depth_ >= 3) {
                count_ += 3;
                depth_ = 2;
            } else if (depth_ == 2) {
                count_ += 300;
                entries_ += 6;
                depth_ = 8;
            }
            break;
        case 3:  // L4
            if (depth_ >= 4) {
                count_ += 4;
                depth_ = 3;
            } else if (depth_ == 3) {
                count_ += 400;
                entries_ += 5;
                depth_ = 8;
            }
            break;
        case 4:  // L5
            if (depth_ >= 5) {
                count_ += 5;
                depth_ = 4;
            } else if (depth_ == 4) {
                count_ += 500;
                entries_ += 4;
                depth_ = 8;
            }
            break;
        case 5:  // L6
            if (depth_ >= 6) {
                count_ += 6;
                depth_ = 5;
            } else if (depth_ == 5) {
                count_ += 600;
                entries_ += 3;
                depth_ = 8;
            }
            break;
        case 6:  // L7
            if (depth_ >= 7) {
                count_ += 7;
                depth_ = 6;
            } else if (depth_ == 6) {
                count_ += 700;
                entries_ += 2;
                depth_ = 8;
            }
            break;
        case 7:  // L8
            if (depth_ >= 8) {
                count_ += 8;
                depth_ = 7;
            } else if (depth_ == 7) {
                count_ += 800;
                entries_ += 1;
                depth_ = 8;
            }
            break;

        default: break;
        }
    }
    deep_bench::workload::observation observe() const { return {depth_, count_, entries_}; }

private:
    int depth_ = 8;
    std::uint64_t count_ = 0;
    std::uint64_t entries_ = 8;  // D1..D8 entered at construction
};

class deep_minimal {
public:
    void on(std::uint8_t event) {
        int const k = event + 1;  // Lk
        if (k <= depth_) {        // Dk active: Dk + Lk = Pk
            count_ += static_cast<std::uint64_t>(k);
            depth_ = k - 1;
        } else if (k == depth_ + 1) {  // Pk active: Pk + Lk = Dk, entered down to D8
            count_ += 100u * static_cast<std::uint64_t>(k);
            entries_ += static_cast<std::uint64_t>(9 - k);
            depth_ = 8;
        }
    }
    deep_bench::workload::observation observe() const { return {depth_, count_, entries_}; }

private:
    int depth_ = 8;
    std::uint64_t count_ = 0;
    std::uint64_t entries_ = 8;
};

}  // namespace

BENCH_IMPL(deep_bench::workload, "hand_written", deep_switch);
BENCH_IMPL(deep_bench::workload, "hand_minimal", deep_minimal);
