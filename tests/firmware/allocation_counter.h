// Counts the calls of the global operator new in the firmware test
// executable (allocation_counter.cpp replaces it there), so that a test can
// show that the wristband core allocates nothing after construction.
#pragma once

#include <cstddef>

namespace alplan::test {

// Allocations through ::operator new since the program started.
std::size_t allocation_count();

}  // namespace alplan::test
