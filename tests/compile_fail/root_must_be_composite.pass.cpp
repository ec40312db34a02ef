// Twin of root_must_be_composite.fail.cpp: Idle is the initial child of a composite root.
#include "two_states.hpp"
