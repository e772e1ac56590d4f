#include "perception/service/service_soak.h"

#include <atomic>
#include <future>
#include <map>
#include <mutex>
#include <ostream>
#include <random>
#include <set>
#include <stdexcept>
#include <thread>

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/write.hpp>

#include "perception/service/signal_service.h"
#include "perception/service/wristband_fleet.h"
#include "perception/stress/simulated_stress_model.h"

namespace alplan::perception::service {
namespace {

namespace net = boost::asio;
using tcp = net::ip::tcp;
using namespace std::chrono_literals;

DeviceRegistry soak_registry(std::size_t devices) {
  std::vector<Device> list;
  for (std::size_t i = 0; i < devices; ++i) {
    const std::string number = std::to_string(i);
    // Loopback only: tokens need to be distinct, not secret.
    list.push_back({"soak-" + number, "soak-token-" + std::string(8 - std::min<std::size_t>(8, number.size()), '0') +
                                          number + "-x",
                    "senior-" + number});
  }
  return DeviceRegistry(std::move(list));
}

// Vetoes a random fraction of commits; shared by every service instance.
class CommitFaults {
 public:
  CommitFaults(double rate, std::uint64_t seed) : rate_(rate), random_(seed) {}
  bool operator()() {
    const std::lock_guard lock(mutex_);
    const bool fail = std::uniform_real_distribution<double>(0.0, 1.0)(random_) < rate_;
    if (fail) failures_ += 1;
    return fail;
  }
  std::uint64_t failures() const {
    const std::lock_guard lock(mutex_);
    return failures_;
  }

 private:
  const double rate_;
  mutable std::mutex mutex_;
  std::mt19937_64 random_;
  std::uint64_t failures_ = 0;
};

// Clients that connect, send the header and a little of a body, and wait
// until the service gives up on them (408), then do it again.
class StallingClients {
 public:
  StallingClients(std::uint16_t port, std::size_t count) : port_(port) {
    for (std::size_t i = 0; i < count; ++i) sockets_.emplace_back(io_);
    timers_.reserve(count);
    for (std::size_t i = 0; i < count; ++i) timers_.emplace_back(io_);
    for (std::size_t i = 0; i < count; ++i) connect(i);
    thread_ = std::thread([this] { io_.run(); });
  }
  ~StallingClients() {
    io_.stop();
    thread_.join();
  }
  StallingClients(const StallingClients&) = delete;
  StallingClients& operator=(const StallingClients&) = delete;
  std::uint64_t connections() const { return connections_.load(); }

 private:
  void connect(std::size_t i) {
    boost::system::error_code ignored;
    sockets_[i].close(ignored);
    sockets_[i].async_connect({net::ip::make_address("127.0.0.1"), port_}, [this, i](boost::system::error_code ec) {
      if (ec) return later(i);  // the service is restarting
      connections_.fetch_add(1);
      net::async_write(sockets_[i], net::buffer(kHalfRequest, sizeof kHalfRequest - 1),
                       [this, i](boost::system::error_code write_ec, std::size_t) {
                         if (write_ec) return later(i);
                         wait_for_close(i);
                       });
    });
  }
  void wait_for_close(std::size_t i) {
    sockets_[i].async_read_some(net::buffer(sink_), [this, i](boost::system::error_code ec, std::size_t) {
      if (ec) return later(i);
      wait_for_close(i);
    });
  }
  void later(std::size_t i) {
    timers_[i].expires_after(200ms);
    timers_[i].async_wait([this, i](boost::system::error_code ec) {
      if (!ec) connect(i);
    });
  }

  static constexpr char kHalfRequest[] =
      "POST /v1/readings HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\nContent-Length: 400\r\n\r\n[{\"dev";
  std::uint16_t port_;
  net::io_context io_;
  std::vector<tcp::socket> sockets_;
  std::vector<net::steady_timer> timers_;
  char sink_[512];
  std::atomic<std::uint64_t> connections_{0};
  std::thread thread_;
};

SignalServiceOptions service_options(const SoakOptions& o, const std::filesystem::path& db, std::uint16_t port,
                                     CommitFaults& faults) {
  SignalServiceOptions options;
  options.database = db;
  options.durability = Durability::Full;
  options.server.port = port;
  options.server.handler_threads = o.handler_threads;
  options.server.request_timeout = 2000ms;  // the stalling clients are let go after 2 s
  options.admin_listener = false;
  options.commit_veto = [&faults] { return faults(); };
  options.error_log = [](const std::string&) {};  // thousands of injected failures
  return options;
}

// Events per senior in order: each state change once, so two equal states
// in a row are a duplicate.
std::uint64_t duplicates_in(const std::map<std::string, std::vector<bool>>& by_senior) {
  std::uint64_t duplicates = 0;
  for (const auto& [senior, states] : by_senior) {
    for (std::size_t i = 1; i < states.size(); ++i) duplicates += states[i] == states[i - 1] ? 1 : 0;
  }
  return duplicates;
}

void drain(SignalService& service, std::map<std::string, std::vector<bool>>& published, std::uint64_t& count) {
  while (const auto e = service.events().try_pop()) {
    published[e->senior].push_back(e->stressed);
    count += 1;
  }
}

void check(const SoakOptions& o) {
  if (o.devices == 0) throw std::invalid_argument("--devices must be at least 1");
  if (!(o.commit_failure_rate >= 0.0 && o.commit_failure_rate < 1.0)) {
    throw std::invalid_argument("--commit-failures must be in [0, 1)");
  }
  if (!(o.restart_every_s >= 0.0)) throw std::invalid_argument("--restart-every must not be negative");
}

FleetOptions fleet_options(const SoakOptions& o, std::uint16_t port) {
  FleetOptions f;
  f.url = "http://127.0.0.1:" + std::to_string(port);
  f.devices = o.devices;
  f.rate_hz = o.rate_hz;
  f.duration_s = o.duration_s;
  f.speed = o.speed;
  f.stressed = o.devices / 4;
  f.typical_subjects = true;
  f.seed = o.seed;
  f.sample_rate_hz = 25.0;  // the cheapest the core takes: the simulation shares the CPU with the service
  f.connections = o.connections;
  f.drain_timeout_s = 120.0;
  return f;
}

// Reads the database back: lost readings, stored events.
void account(const std::filesystem::path& db, const FleetSummary& fleet, std::size_t stressed_seniors,
             const std::map<std::string, std::vector<bool>>& published, SoakReport& r) {
  ReadingStore store(db, Durability::Normal, StoreAccess::ReadOnly);
  r.stored = store.count_readings();
  std::uint64_t acknowledged_missing = 0;
  for (const DeviceOutcome& d : fleet.devices) {
    std::set<std::uint32_t> stored;
    for (const ReceivedReading& reading : store.readings_of(d.device)) stored.insert(reading.seq);
    for (const std::uint32_t seq : d.acknowledged) acknowledged_missing += stored.count(seq) == 0 ? 1 : 0;
  }
  r.lost = acknowledged_missing + (fleet.total.made - std::min(fleet.total.made, fleet.total.acknowledged));
  std::map<std::string, std::vector<bool>> stored_events;
  for (const StressEvent& e : store.stress_events()) stored_events[e.senior].push_back(e.stressed);
  r.events_stored = store.stress_events().size();
  r.duplicate_events = duplicates_in(stored_events) + duplicates_in(published) +
                       (r.events_published > r.events_stored ? r.events_published - r.events_stored : 0);
  // An event stored but never published is one the deliberation never heard of.
  r.missed_events = r.events_stored > r.events_published ? r.events_stored - r.events_published : 0;
  for (std::size_t i = 0; i < fleet.devices.size(); ++i) {
    const auto it = stored_events.find(fleet.devices[i].senior);
    const bool raised = it != stored_events.end() && !it->second.empty() && it->second.front();
    const bool expected = i < stressed_seniors;
    r.missed_events += raised == expected ? 0 : 1;  // a stressed senior unannounced, or a calm one announced
  }
}

}  // namespace

SoakReport run_soak(const SoakOptions& o) {
  check(o);
  std::filesystem::create_directories(o.work_dir);
  const std::filesystem::path db = o.work_dir / "soak.db";
  for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(db.string() + suffix);
  const DeviceRegistry registry = soak_registry(o.devices);
  const StressClassifier model = train_simulated_stress_classifier({});
  CommitFaults faults(o.commit_failure_rate, o.seed);
  SoakReport report;
  const auto start = std::chrono::steady_clock::now();
  auto service = std::make_unique<SignalService>(registry, model, service_options(o, db, 0, faults));
  service->start();
  const std::uint16_t port = service->port();
  const FleetOptions fleet_opts = fleet_options(o, port);
  WristbandFleet fleet(registry, fleet_opts);
  std::map<std::string, std::vector<bool>> published;
  FleetSummary summary;
  {
    StallingClients stalling(port, o.stalled_clients);
    auto running = std::async(std::launch::async, [&fleet] { return fleet.run(); });
    auto last_restart = std::chrono::steady_clock::now();
    while (running.wait_for(100ms) != std::future_status::ready) {
      drain(*service, published, report.events_published);
      if (o.restart_every_s <= 0.0 ||
          std::chrono::steady_clock::now() - last_restart < std::chrono::duration<double>(o.restart_every_s)) {
        continue;
      }
      service->stop();  // answers what it committed, then closes everything
      drain(*service, published, report.events_published);
      service = std::make_unique<SignalService>(registry, model, service_options(o, db, port, faults));
      service->start();
      report.restarts += 1;
      last_restart = std::chrono::steady_clock::now();
    }
    summary = running.get();
    report.stalled_connections = stalling.connections();
  }
  service->stop();
  drain(*service, published, report.events_published);
  service.reset();
  report.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  report.offered = summary.total.made;
  report.acknowledged = summary.total.acknowledged;
  report.retries = summary.total.retries;
  report.commit_failures = faults.failures();
  report.client_p50_ms = summary.latency_p50_s * 1e3;
  report.client_p99_ms = summary.latency_p99_s * 1e3;
  report.client_max_ms = summary.latency_max_s * 1e3;
  account(db, summary, fleet_opts.stressed, published, report);
  return report;
}

void print_soak_report(std::ostream& out, const SoakOptions& o, const SoakReport& r) {
  out << "| wristbands | signal s | wall s | offered | acknowledged | stored | lost | events stored | events published "
         "| duplicate events | missed events | commit failures | restarts | stalled connections | retries "
         "| client p50 ms | client p99 ms | client max ms | pass |\n"
      << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  char line[512];
  std::snprintf(line, sizeof line,
                "| %zu | %.0f | %.0f | %llu | %llu | %llu | %llu | %llu | %llu | %llu | %llu | %llu | %llu | %llu | "
                "%llu | %.1f | %.1f | %.1f | %s |\n",
                o.devices, o.duration_s, r.wall_s, static_cast<unsigned long long>(r.offered),
                static_cast<unsigned long long>(r.acknowledged), static_cast<unsigned long long>(r.stored),
                static_cast<unsigned long long>(r.lost), static_cast<unsigned long long>(r.events_stored),
                static_cast<unsigned long long>(r.events_published),
                static_cast<unsigned long long>(r.duplicate_events), static_cast<unsigned long long>(r.missed_events),
                static_cast<unsigned long long>(r.commit_failures), static_cast<unsigned long long>(r.restarts),
                static_cast<unsigned long long>(r.stalled_connections), static_cast<unsigned long long>(r.retries),
                r.client_p50_ms, r.client_p99_ms, r.client_max_ms, r.passed() ? "yes" : "NO");
  out << line << std::flush;
}

}  // namespace alplan::perception::service
