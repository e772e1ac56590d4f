#include "planner/address_space.h"

#include <fstream>

#include <unistd.h>

namespace alplan {

std::size_t address_space_bytes() {
  std::ifstream statm("/proc/self/statm");
  std::size_t pages = 0;
  if (!(statm >> pages)) return 0;
  const long page = sysconf(_SC_PAGESIZE);
  return page > 0 ? pages * static_cast<std::size_t>(page) : 0;
}

}  // namespace alplan
