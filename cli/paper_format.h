// Plans as the paper's figures print them: "a1  : 0.000   : (move ...)".
#pragma once

#include <string>

namespace alplan::cli {

// "0.000: (move ...) [30.000]" lines become "a1  : 0.000   : (move ...)".
std::string paper_format(const std::string& ipc_plan);

}  // namespace alplan::cli
