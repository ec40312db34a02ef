// Twin of not_a_state_declaration.fail.cpp: the int argument is removed.
#include "two_states.hpp"
