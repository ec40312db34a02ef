#pragma once
// Deprecated: the compiled back end's header is <bsc/machine.hpp>. This one includes it, so that
// code written for bsc 0.1 still compiles; it goes in a later version (CHANGELOG.md, 0.2.0).
#include <bsc/machine.hpp>
