// What the signal-service tests share: a scratch folder, a tokens registry,
// a stress classifier trained once on simulated recordings, and a running
// service on a free loopback port.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "perception/service/device_registry.h"
#include "perception/service/reading_message.h"
#include "perception/service/signal_service.h"
#include "perception/stress/stress_classifier.h"
#include "perception/stress/stress_detector.h"

namespace alplan::test {

// A fresh, empty folder under the system's temporary folder, removed when
// the object goes.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name);
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

// Devices wb-00, wb-01, ... worn by senior-00, senior-01, ..., with tokens
// "token-for-wb-00-xxxxxxxx".
perception::service::DeviceRegistry test_registry(std::size_t devices);

// Trained on first use, the same for every test of the run (immutable).
const perception::StressClassifier& test_classifier();

// The simulator's typical subject's calm or stressed window as the wristband
// core reports it (70 vs 85 bpm, HRV about halved), number `seq` of a series
// 5 s apart from `first_t_ms`.
perception::service::ReceivedReading typical_window(const std::string& device, std::uint32_t seq, bool stressed,
                                                    std::uint64_t first_t_ms);

// The stress detector over test_classifier(), with default smoothing.
std::unique_ptr<perception::ClassifierStressDetector> test_stress_detector();

// Options for a test service on 127.0.0.1, a free port, this database.
perception::service::SignalServiceOptions test_options(const std::filesystem::path& database);

// A service with the test classifier (or none), already started.
std::unique_ptr<perception::service::SignalService> start_service(
    const perception::service::DeviceRegistry& registry, const perception::service::SignalServiceOptions& options,
    bool detect_stress = true);

// A self-signed certificate (EC P-256, valid two days) naming localhost and
// 127.0.0.1, and its key, made with the openssl command line as
// <dir>/<name>-cert.pem and <dir>/<name>-key.pem (mode 0600).
struct TestCertificate {
  std::filesystem::path certificate;
  std::filesystem::path key;
};
TestCertificate make_test_certificate(const ScratchDir& dir, const std::string& name);

// Sends `bytes` on a new connection to 127.0.0.1:port and returns all that
// comes back until the server closes the connection or `timeout` passes.
std::string exchange_raw(std::uint16_t port, const std::string& bytes,
                         std::chrono::milliseconds timeout = std::chrono::milliseconds(5000));

// The status code of a raw HTTP response ("HTTP/1.1 408 ..." -> 408), 0 if none.
int status_of(const std::string& raw_response);
// The body of a raw HTTP response (after the blank line).
std::string body_of(const std::string& raw_response);

}  // namespace alplan::test
