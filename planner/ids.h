// Dense integer ids of the grounded world. Every id indexes a vector owned by
// the task; ids are assigned deterministically (same input, same ids).
#pragma once

#include <cstdint>
#include <limits>

namespace alplan {

using ObjectId = std::uint32_t;
using TypeId = std::uint32_t;
using PredicateId = std::uint32_t;
using FunctionId = std::uint32_t;
using FactId = std::uint32_t;
using NumericVarId = std::uint32_t;
using ActionId = std::uint32_t;

constexpr std::uint32_t kNoId = std::numeric_limits<std::uint32_t>::max();

}  // namespace alplan
