// The CD player written by hand (cd_player.hpp).

#include "cd_player.hpp"

cd::hand_written subject;

int main(int argc, char** argv) { return cm::run_events<cd::workload, cd::hand_adapter<subject>>(argc, argv); }
