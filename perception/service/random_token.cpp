#include "perception/service/random_token.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <sys/random.h>
#include <vector>

namespace alplan::perception::service {

std::string random_token(std::size_t bytes) {
  std::vector<unsigned char> raw(bytes);
  std::size_t filled = 0;
  while (filled < bytes) {
    // Blocks only until the kernel's pool is first initialised, at boot.
    const ssize_t n = ::getrandom(raw.data() + filled, bytes - filled, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw std::runtime_error(std::string("getrandom failed: ") + std::strerror(errno));
    filled += static_cast<std::size_t>(n);
  }
  static constexpr char kHex[] = "0123456789abcdef";
  std::string token;
  token.reserve(2 * bytes);
  for (const unsigned char b : raw) {
    token += kHex[b >> 4];
    token += kHex[b & 0x0f];
  }
  return token;
}

}  // namespace alplan::perception::service
