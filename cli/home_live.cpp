#include "cli/home_live.h"

#include <CLI/CLI.hpp>

#include <atomic>
#include <chrono>
#include <fstream>
#include <iostream>
#include <memory>
#include <thread>

#include "cli/perceive_common.h"
#include "home/given_face.h"
#include "home/live_goal_source.h"
#include "home/run_clock.h"
#include "perception/service/home_event_store.h"

namespace alplan::cli {
namespace {

namespace service = perception::service;

std::int64_t unix_ms_now() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

service::HomeEventRow row_of(const home::LogEvent& e) {
  return {e.time, e.type, e.senior, e.robot, e.payload.dump()};
}

std::vector<std::string> seniors_of(const service::DeviceRegistry& registry) {
  std::vector<std::string> seniors;
  for (const service::Device& d : registry.devices()) seniors.push_back(d.senior);
  return seniors;
}

// Takes SIGINT/SIGTERM for the run and stops its clock; ends when the run
// does. Joined on destruction, whatever ends the run.
class StopWatcher {
 public:
  StopWatcher(const sigset_t& signals, home::WallClock& clock)
      : thread_([this, signals, &clock] {
          wait_for_stop(signals, 0.0, [this] { return finished_.load(); });
          clock.stop();
        }) {}
  ~StopWatcher() {
    finished_ = true;
    thread_.join();
  }
  StopWatcher(const StopWatcher&) = delete;
  StopWatcher& operator=(const StopWatcher&) = delete;

 private:
  std::atomic<bool> finished_{false};
  std::thread thread_;
};

}  // namespace

void add_live_flags(CLI::App& command, LiveFlags& flags) {
  command.add_flag("--live", flags.live,
                   "Stress from wristbands through the signal service in this process, in real time");
  add_service_flags(command, flags.service);
  command.add_option("--face", flags.face, "--live: an image of the seniors' face, read by the emotion network at every look");
  command.add_option("--emotion", flags.emotion, "--live: the seniors' emotion, given (terrified, sad, bored, ...)");
}

void check_live_flags(const LiveFlags& f) {
  const ServiceFlags none;
  const ServiceFlags& s = f.service;
  const bool service_flags = s.port != none.port || s.bind != none.bind || !s.db.empty() || !s.tokens.empty() ||
                             !s.model.empty() || s.sync != none.sync || !s.tls_cert.empty() || !s.tls_key.empty() ||
                             s.insecure_http || s.admin_bind != none.admin_bind || s.admin_port != none.admin_port;
  if (!f.live) {
    if (service_flags || !f.face.empty() || !f.emotion.empty()) {
      throw CommandInputError("the signal service's flags, --face and --emotion go with --live");
    }
    return;
  }
  if (s.tokens.empty()) throw CommandInputError("--live needs --tokens FILE: the wristbands' tokens, as alplan serve takes");
  if (s.db.empty()) throw CommandInputError("--live needs --db FILE: the service's database (readings and the home's events)");
  if (f.face.empty() && f.emotion.empty()) {
    throw CommandInputError("--live needs the seniors' face (--face IMAGE) or their emotion (--emotion NAME): "
                            "the home has no camera");
  }
}

home::HomeSummary run_live_home(const home::HomeSettings& settings, const LiveFlags& flags, const std::string& log_file,
                                const home::EventLog::Echo& narrate) {
  const sigset_t signals = block_stop_signals();
  check_transport(flags.service);
  service::DeviceRegistry registry = read_private_registry(flags.service.tokens);
  const std::vector<std::string> seniors = seniors_of(registry);
  service::SignalService signal_service(std::move(registry), load_classifier(flags.service.model, "home"),
                                        service_options(flags.service));
  // After the service: it made the file private and its readings' schema.
  service::HomeEventStore store(flags.service.db, service_options(flags.service).durability);
  auto face = std::make_shared<home::GivenFace>(flags.face, flags.emotion);
  std::ofstream file;
  if (!log_file.empty()) {
    file.open(log_file, std::ios::binary | std::ios::trunc);
    if (!file) throw CommandInputError(log_file + ": cannot write the log");
  }
  home::EventLog log(log_file.empty() ? nullptr : &file, [&](const home::LogEvent& e) {
    store.insert(row_of(e), unix_ms_now());
    if (narrate) narrate(e);
  });
  // The service listens once the home is loaded and its seniors match the
  // wristbands': a bad home stops the command before anyone can post.
  const home::GoalSourceMaker wristbands = [&](const home::HomeMap& map, home::EventLog& to) {
    const auto read_face = [face](const std::string&, double) {
      std::string note;
      return face->look(note);
    };
    auto source = std::make_unique<home::LiveGoalSource>(signal_service.events(), read_face, map, seniors, settings, to);
    signal_service.start();
    std::cout << "serving on " << signal_service.url() << " (database " << flags.service.db << ", "
              << signal_service.registry().size() << " devices; the home runs in real time)" << std::endl;
    std::cerr << "home: admin on " << signal_service.admin_url() << " (GET /healthz, /metrics)" << std::endl;
    return source;
  };
  home::WallClock clock(settings.until);
  const StopWatcher watcher(signals, clock);
  const home::HomeSummary summary = home::run_home(settings, log, wristbands, clock);
  signal_service.stop();
  const service::IngestCounters c = signal_service.counters();
  std::cerr << "home: stopped; stored " << c.stored << " readings, " << c.became_stressed + c.became_calm
            << " stress events; " << log.events().size() << " home events in " << flags.service.db << "\n";
  return summary;
}

}  // namespace alplan::cli
