// The Mode Control Supervisor's driver with a subject that does nothing (supervisor::floor):
// the image the report measures the supervisor's flash from.

#include "mcs_supervisor.hpp"

supervisor::floor subject;

int main(int argc, char** argv) {
    return cm::run_events<supervisor::workload, supervisor::hand_adapter<subject>>(argc, argv);
}
