// Bearer tokens for wristbands: 128 bits from the kernel's CSPRNG
// (getrandom(2)), as 32 hex digits. std::random_device is not used: the
// standard lets it be a deterministic engine, and its 32-bit draws would
// make a token of four separate calls.
#pragma once

#include <cstddef>
#include <string>

namespace alplan::perception::service {

// `bytes` random bytes as 2 * bytes lower-case hex digits. Throws
// std::runtime_error when the kernel gives no randomness.
std::string random_token(std::size_t bytes = 16);

}  // namespace alplan::perception::service
