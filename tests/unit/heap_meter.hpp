#pragma once
// The heap this test program holds: operator new and delete are replaced in
// allocation_test.cpp, which counts the bytes of every block.

#include <cstddef>

namespace heap_meter {
std::size_t live();  ///< bytes held now
std::size_t peak();  ///< the most held since the last reset_peak()
void reset_peak();
}  // namespace heap_meter
