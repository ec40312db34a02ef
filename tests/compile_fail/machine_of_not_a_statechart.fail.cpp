// EXPECT: (does not satisfy 'statechart'|statechart\.hpp:[0-9:]+ note: no operand of the disjunction is satisfied)
// A machine declared on a type that is not a chart fails at its declaration, naming the
// concept bsc::statechart and the type, not deep inside the driver.
#include <bsc/bsc.hpp>

bsc::machine<int>* declared = nullptr;

int main() { return declared == nullptr ? 0 : 1; }
