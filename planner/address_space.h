// How much address space the process holds, for a search that must stop
// before the operating system's limit does it for it: an allocation refused
// under RLIMIT_AS throws bad_alloc, and unwinding frees millions of nodes one
// by one (seconds on pathways; benchmarks/README.md), past any time limit.
#pragma once

#include <cstddef>

namespace alplan {

// Bytes of virtual memory mapped by this process (Linux: /proc/self/statm,
// what RLIMIT_AS counts); 0 where that cannot be read.
std::size_t address_space_bytes();

}  // namespace alplan
