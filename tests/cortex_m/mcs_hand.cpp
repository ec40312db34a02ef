// The Mode Control Supervisor written by hand (mcs_supervisor.hpp).

#include "mcs_supervisor.hpp"

supervisor::hand_written subject;

int main(int argc, char** argv) {
    return cm::run_events<supervisor::workload, supervisor::hand_adapter<subject>>(argc, argv);
}
