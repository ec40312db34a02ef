#pragma once
// Deprecated: bsc::action_failed is declared in <bsc/events.hpp>, with the other events bsc
// defines. This header includes it, so that code written for bsc 0.1 still compiles; it goes in a
// later version (CHANGELOG.md, 0.2.0).
#include <bsc/events.hpp>
