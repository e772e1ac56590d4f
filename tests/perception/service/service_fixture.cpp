#include "service_fixture.h"

#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <stdexcept>
#include <system_error>

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/write.hpp>
#include <boost/beast/core/tcp_stream.hpp>

#include "perception/stress/simulated_stress_model.h"

namespace alplan::test {

namespace service = perception::service;

ScratchDir::ScratchDir(const std::string& name) {
  std::random_device entropy;
  path_ = std::filesystem::temp_directory_path() / ("alplan-" + name + "-" + std::to_string(entropy()));
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}

ScratchDir::~ScratchDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

service::DeviceRegistry test_registry(std::size_t devices) {
  std::vector<service::Device> list;
  for (std::size_t i = 0; i < devices; ++i) {
    char id[32];
    std::snprintf(id, sizeof id, "wb-%02zu", i);
    const std::string number = std::string(id).substr(3);
    list.push_back({id, "token-for-" + std::string(id) + "-" + std::to_string(1000003 * (i + 7)), "senior-" + number});
  }
  return service::DeviceRegistry(std::move(list));
}

const perception::StressClassifier& test_classifier() {
  static const perception::StressClassifier classifier = perception::train_simulated_stress_classifier({});
  return classifier;
}

service::ReceivedReading typical_window(const std::string& device, std::uint32_t seq, bool stressed,
                                        std::uint64_t first_t_ms) {
  service::ReceivedReading r;
  r.device = device;
  r.seq = seq;
  r.t_ms = first_t_ms + 5000ULL * seq;
  r.window_ms = 30000;
  r.hr_bpm = stressed ? 85.0 : 70.0;
  r.ibi_ms = 60000.0 / *r.hr_bpm;
  r.sdnn_ms = stressed ? 25.0 : 48.0;
  r.rmssd_ms = stressed ? 18.0 : 40.0;
  r.beats = stressed ? 42 : 35;
  return r;
}

// Without a per-senior baseline, as the service runs (signal_service.h):
// these tests are about ingest, and typical_window's readings are typical
// of everybody.
std::unique_ptr<perception::ClassifierStressDetector> test_stress_detector() {
  return std::make_unique<perception::ClassifierStressDetector>(test_classifier(), perception::StressSmoothing{},
                                                                perception::StressCalibration{0});
}

service::SignalServiceOptions test_options(const std::filesystem::path& database) {
  service::SignalServiceOptions options;
  options.database = database;
  options.durability = service::Durability::Normal;  // tests kill no machine; keep them quick
  return options;
}

std::unique_ptr<service::SignalService> start_service(const service::DeviceRegistry& registry,
                                                       const service::SignalServiceOptions& options,
                                                       bool detect_stress) {
  std::optional<perception::StressClassifier> classifier;
  if (detect_stress) classifier = test_classifier();
  auto s = std::make_unique<service::SignalService>(registry, classifier, options);
  s->start();
  return s;
}

std::string exchange_raw(std::uint16_t port, const std::string& bytes, std::chrono::milliseconds timeout) {
  namespace net = boost::asio;
  net::io_context io;
  boost::beast::tcp_stream stream(io);
  stream.connect(net::ip::tcp::endpoint(net::ip::make_address("127.0.0.1"), port));
  // Beast's deadlines bind asynchronous operations only, hence the async reads.
  stream.expires_after(timeout);
  std::string received;
  char chunk[4096];
  std::function<void(boost::beast::error_code, std::size_t)> on_read = [&](boost::beast::error_code error,
                                                                            std::size_t n) {
    received.append(chunk, n);
    if (!error) stream.async_read_some(net::buffer(chunk), on_read);
  };
  net::async_write(stream, net::buffer(bytes), [&](boost::beast::error_code error, std::size_t) {
    if (!error) stream.async_read_some(net::buffer(chunk), on_read);
  });
  io.run();
  return received;
}

TestCertificate make_test_certificate(const ScratchDir& dir, const std::string& name) {
  TestCertificate made{dir / (name + "-cert.pem"), dir / (name + "-key.pem")};
  const std::string command = "openssl req -x509 -newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes -days 2"
                              " -subj /CN=localhost -addext subjectAltName=DNS:localhost,IP:127.0.0.1 -keyout '" +
                              made.key.string() + "' -out '" + made.certificate.string() + "' 2>/dev/null";
  if (std::system(command.c_str()) != 0) throw std::runtime_error("cannot make a certificate: " + command);
  std::filesystem::permissions(made.key, std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
  return made;
}

int status_of(const std::string& raw) {
  if (raw.rfind("HTTP/1.", 0) != 0 || raw.size() < 12) return 0;
  return std::atoi(raw.substr(9, 3).c_str());
}

std::string body_of(const std::string& raw) {
  const auto end = raw.find("\r\n\r\n");
  return end == std::string::npos ? std::string() : raw.substr(end + 4);
}

}  // namespace alplan::test
