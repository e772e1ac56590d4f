#include <catch2/catch.hpp>

#include "firmware/core/retry_backoff.h"
#include "firmware/core/upload_policy.h"

using namespace alplan::firmware;

TEST_CASE("back-off doubles from the initial delay up to the cap, with equal jitter") {
  RetryBackoff backoff(1000, 60000);
  // With zero random bits each delay is its lower end, half the nominal delay.
  const uint32_t expected_low[] = {500, 1000, 2000, 4000, 8000, 16000, 30000, 30000};
  for (uint32_t low : expected_low) CHECK(backoff.next_delay_ms(0) == low);
  CHECK(backoff.failures() == 8);
  backoff.reset();
  CHECK(backoff.next_delay_ms(0) == 500);
  // Random bits place the delay within [d/2, d].
  RetryBackoff jittered(1000, 60000);
  for (int attempt = 0; attempt < 12; ++attempt) {
    const uint32_t nominal = attempt >= 6 ? 60000 : 1000u << attempt;
    const uint32_t delay = jittered.next_delay_ms(0xFFFFFFFFu - 12345u * static_cast<uint32_t>(attempt));
    CHECK(delay >= nominal / 2);
    CHECK(delay <= nominal);
  }
}

TEST_CASE("back-off survives a very long outage without overflowing") {
  RetryBackoff backoff(1000, 300000);
  uint32_t delay = 0;
  for (int attempt = 0; attempt < 100; ++attempt) delay = backoff.next_delay_ms(7);
  CHECK(delay == 150007);
}

TEST_CASE("upload outcomes by HTTP status") {
  CHECK(classify_upload_status(200) == UploadVerdict::Delivered);
  CHECK(classify_upload_status(202) == UploadVerdict::Delivered);
  CHECK(classify_upload_status(204) == UploadVerdict::Delivered);
  CHECK(classify_upload_status(-1) == UploadVerdict::RetryLater);  // HTTPClient: connection refused
  CHECK(classify_upload_status(-11) == UploadVerdict::RetryLater);  // HTTPClient: read timeout
  CHECK(classify_upload_status(500) == UploadVerdict::RetryLater);
  CHECK(classify_upload_status(503) == UploadVerdict::RetryLater);
  CHECK(classify_upload_status(401) == UploadVerdict::RetryLater);
  CHECK(classify_upload_status(403) == UploadVerdict::RetryLater);
  CHECK(classify_upload_status(429) == UploadVerdict::RetryLater);
  CHECK(classify_upload_status(408) == UploadVerdict::RetryLater);
  CHECK(classify_upload_status(400) == UploadVerdict::Discard);
  CHECK(classify_upload_status(413) == UploadVerdict::Discard);
  CHECK(classify_upload_status(422) == UploadVerdict::Discard);
  CHECK(classify_upload_status(301) == UploadVerdict::RetryLater);
}
