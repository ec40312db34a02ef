// Workload sml_simple, hand-written: the switch of cd_player_switch.hpp.

#include "sml_simple_workload.hpp"

namespace {

using namespace sml_simple_bench;

// The switch of cd_player_switch.hpp, observed as the harness observes.
class cd_player_hand {
public:
    void on(std::uint8_t e) { player_.on(e); }
    workload::observation observe() const { return {player_.current()}; }

private:
    cd_player_switch player_;
};

}  // namespace

BENCH_IMPL(sml_simple_bench::workload, "hand_written", cd_player_hand);
