// Twin of machine_of_not_a_statechart.fail.cpp: the machine is declared on the chart's type.
#include "two_states.hpp"

bsc::machine<decltype(cf::chart)>* declared = nullptr;

int main() { return declared == nullptr ? 0 : 1; }
