// The CD player's driver with a subject that does nothing (cd_player.hpp, cd::floor): the image
// the report measures the CD player's flash from.

#include "cd_player.hpp"

cd::floor subject;

int main(int argc, char** argv) { return cm::run_events<cd::workload, cd::hand_adapter<subject>>(argc, argv); }
