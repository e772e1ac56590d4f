#include "cli/paper_format.h"

#include <cstdio>
#include <sstream>

namespace alplan::cli {

// "0.000: (move ...) [30.000]" lines become "a1  : 0.000   : (move ...)".
std::string paper_format(const std::string& ipc_plan) {
  std::istringstream in(ipc_plan);
  std::string out;
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    const std::size_t colon = line.find(": ");
    const std::size_t bracket = line.rfind(" [");
    if (colon == std::string::npos) continue;
    const std::string time = line.substr(0, colon);
    const std::string action = line.substr(colon + 2, bracket == std::string::npos ? std::string::npos : bracket - colon - 2);
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, "a%-3d: %-8s: %s\n", ++n, time.c_str(), action.c_str());
    out += buffer;
  }
  return out;
}

}  // namespace alplan::cli
