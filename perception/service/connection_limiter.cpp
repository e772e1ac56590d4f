#include "perception/service/connection_limiter.h"

#include <stdexcept>

namespace alplan::perception::service {

ConnectionLimiter::ConnectionLimiter(std::size_t per_client) : per_client_(per_client) {
  if (per_client == 0) throw std::invalid_argument("the connection limit per client must be at least 1");
}

ConnectionLimiter::Ticket::~Ticket() {
  if (limiter_ != nullptr) limiter_->release(client_);
}

ConnectionLimiter::Ticket::Ticket(Ticket&& other) noexcept
    : limiter_(other.limiter_), client_(std::move(other.client_)) {
  other.limiter_ = nullptr;
}

ConnectionLimiter::Ticket ConnectionLimiter::admit(const std::string& client) {
  const std::lock_guard lock(mutex_);
  std::size_t& held = held_[client];
  if (held >= per_client_) return {};
  held += 1;
  return {this, client};
}

std::size_t ConnectionLimiter::held_by(const std::string& client) const {
  const std::lock_guard lock(mutex_);
  const auto it = held_.find(client);
  return it == held_.end() ? 0 : it->second;
}

void ConnectionLimiter::release(const std::string& client) {
  const std::lock_guard lock(mutex_);
  const auto it = held_.find(client);
  if (it == held_.end()) return;
  if (--it->second == 0) held_.erase(it);
}

}  // namespace alplan::perception::service
