// How many connections each client address holds, so that one client (a
// stalled wristband, a misbehaving script) cannot take every connection
// slot. Thread-safe. A Ticket counts one connection for as long as it lives.
#pragma once

#include <cstddef>
#include <map>
#include <mutex>
#include <string>

namespace alplan::perception::service {

class ConnectionLimiter {
 public:
  // Precondition: per_client > 0.
  explicit ConnectionLimiter(std::size_t per_client);

  class Ticket {
   public:
    Ticket() = default;
    Ticket(ConnectionLimiter* limiter, std::string client) : limiter_(limiter), client_(std::move(client)) {}
    ~Ticket();
    Ticket(Ticket&& other) noexcept;
    Ticket& operator=(Ticket&&) = delete;
    Ticket(const Ticket&) = delete;
    Ticket& operator=(const Ticket&) = delete;
    explicit operator bool() const { return limiter_ != nullptr; }

   private:
    ConnectionLimiter* limiter_ = nullptr;
    std::string client_;
  };

  // A ticket for one more connection of `client`, or an empty one when the
  // client already holds per_client connections.
  Ticket admit(const std::string& client);
  std::size_t held_by(const std::string& client) const;
  std::size_t per_client() const { return per_client_; }

 private:
  void release(const std::string& client);

  const std::size_t per_client_;
  mutable std::mutex mutex_;
  std::map<std::string, std::size_t> held_;
};

}  // namespace alplan::perception::service
