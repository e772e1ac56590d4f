#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "firmware/core/beat_tracker.h"
#include "firmware/core/beat_window.h"
#include "firmware/core/window_features.h"

using namespace alplan::firmware;

namespace {

std::vector<BeatEvent> track(BeatTracker& tracker, const std::vector<double>& times_ms, float amplitude = 1.0f) {
  std::vector<BeatEvent> events;
  for (double t : times_ms) events.push_back(tracker.on_peak(t, amplitude));
  return events;
}

std::vector<double> regular(double start_ms, double interval_ms, int count) {
  std::vector<double> times;
  for (int i = 0; i < count; ++i) times.push_back(start_ms + i * interval_ms);
  return times;
}

}  // namespace

TEST_CASE("regular beats are accepted with their intervals and successive differences") {
  BeatTracker tracker({});
  const auto events = track(tracker, {0, 800, 1610, 2400});
  CHECK(events[0].kind == BeatKind::First);
  CHECK(events[1].kind == BeatKind::Accepted);
  CHECK(events[1].ibi_ms == 800.0f);
  CHECK_FALSE(events[1].has_successive_difference);
  CHECK(events[2].ibi_ms == 810.0f);
  CHECK(events[2].has_successive_difference);
  CHECK(events[2].successive_difference_ms == 10.0f);
  CHECK(events[3].successive_difference_ms == -20.0f);
  CHECK(tracker.accepted_count() == 3);
  CHECK(tracker.rejected_count() == 0);
}

TEST_CASE("intervals outside 0.3-2.0 s are rejected even before a median is known") {
  BeatTracker tracker({});
  const auto events = track(tracker, {0, 250, 800, 2900});
  CHECK(events[1].kind == BeatKind::RejectedShort);  // the peak at 250 is dropped...
  CHECK(events[2].kind == BeatKind::Accepted);       // ...so 800 is measured from 0
  CHECK(events[2].ibi_ms == 800.0f);
  CHECK(events[3].kind == BeatKind::RejectedLong);
}

TEST_CASE("a false peak is dropped and a missed beat restarts the chain") {
  BeatTracker tracker({});
  std::vector<double> times = regular(0, 800, 6);  // median 800 known after five intervals
  times.push_back(4000 + 350);                     // false peak
  times.push_back(4800);
  times.push_back(6400);  // the beat at 5600 was missed
  times.push_back(7200);
  const auto events = track(tracker, times);
  CHECK(events[6].kind == BeatKind::RejectedShort);
  CHECK(events[7].kind == BeatKind::Accepted);
  CHECK(events[7].ibi_ms == 800.0f);
  CHECK(events[7].has_successive_difference);  // still adjacent to the interval before the false peak
  CHECK(events[8].kind == BeatKind::RejectedLong);
  CHECK(events[9].kind == BeatKind::Accepted);
  CHECK_FALSE(events[9].has_successive_difference);  // the interval before it is unknown
}

TEST_CASE("intervals far from the running median are rejected") {
  BeatTracker tracker({});
  std::vector<double> times = regular(0, 1000, 6);
  times.push_back(5000 + 1350);  // +35 %
  const auto events = track(tracker, times);
  CHECK(events.back().kind == BeatKind::RejectedLong);
}

TEST_CASE("a median locked on doubled intervals is relearned from the rejected half") {
  BeatTracker tracker({});
  // The median learns 1000 ms (e.g. from a motion burst's rhythm), then the
  // true rhythm of 500 ms shows: every other peak is "too short".
  std::vector<double> times = regular(0, 1000, 6);
  for (int i = 1; i <= 30; ++i) times.push_back(5000 + 500.0 * i);
  const auto events = track(tracker, times);
  int accepted_500 = 0;
  for (std::size_t i = events.size() - 10; i < events.size(); ++i) {
    if (events[i].kind == BeatKind::Accepted && std::abs(events[i].ibi_ms - 500.0f) < 1.0f) ++accepted_500;
  }
  CHECK(accepted_500 == 10);
}

TEST_CASE("peaks of implausible amplitude are rejected and restart the chain") {
  BeatTracker tracker({});
  track(tracker, regular(0, 800, 6), 1.0f);
  CHECK(tracker.on_peak(4800, 3.0f).kind == BeatKind::RejectedAmplitude);  // motion: 3x the pulse
  CHECK(tracker.on_peak(5600, 1.0f).kind == BeatKind::First);
  CHECK(tracker.on_peak(6400, 1.1f).kind == BeatKind::Accepted);
  CHECK(tracker.on_peak(7200, 0.3f).kind == BeatKind::Accepted);  // small peaks are left to the interval tests
}

TEST_CASE("after 10 s without an accepted beat both medians are relearned") {
  BeatTracker tracker({});
  track(tracker, regular(0, 800, 6), 1.0f);
  // The sensor was re-seated: from now on the pulse is four times larger.
  std::vector<BeatEvent> events;
  for (double t = 4800; t < 20000; t += 800) events.push_back(tracker.on_peak(t, 4.0f));
  CHECK(events.front().kind == BeatKind::RejectedAmplitude);
  CHECK(events.back().kind == BeatKind::Accepted);
}

TEST_CASE("window statistics follow the Task Force definitions over the accepted intervals ending inside the window") {
  BeatWindow window;
  BeatTracker tracker({});
  const std::vector<double> times = {0, 800, 1700, 2300, 2450, 3100, 3900};  // 2450 is a false peak
  for (double t : times) window.add(tracker.on_peak(t, 1.0f));
  // Accepted intervals: 900 (ends 1700), 600 (2300), 800 (3100), 800 (3900);
  // the first, 800 (ends 800), is outside (800, 3900].
  const BeatStatistics stats = window.statistics(800, 3900);
  CHECK(stats.accepted == 4);
  CHECK(stats.rejected == 1);
  CHECK(stats.mean_ibi_ms == Approx(775.0));
  const double sdnn = std::sqrt((125.0 * 125 + 175.0 * 175 + 25.0 * 25 + 25.0 * 25) / 3.0);
  CHECK(stats.sdnn_ms == Approx(sdnn).epsilon(1e-5));
  // Successive differences with both intervals in the window: -300, 200, 0.
  CHECK(stats.successive_differences == 3);
  CHECK(stats.rmssd_ms == Approx(std::sqrt((300.0 * 300 + 200.0 * 200) / 3.0)).epsilon(1e-5));

  const BeatStatistics empty = window.statistics(5000, 6000);
  CHECK(empty.accepted == 0);
  CHECK(empty.mean_ibi_ms == 0.0f);
}

TEST_CASE("features need enough beats covering the window, and flag motion from either evidence") {
  BeatStatistics beats;
  beats.accepted = 36;
  beats.rejected = 4;
  beats.successive_differences = 35;
  beats.mean_ibi_ms = 800.0f;
  beats.sdnn_ms = 40.0f;
  beats.rmssd_ms = 30.0f;
  QualityStatistics quality;
  quality.segments = 15;
  const FeatureThresholds thresholds;

  WindowFeatures f = window_features(beats, quality, 30000, thresholds);
  CHECK(f.has_heart_rate);
  CHECK(f.has_rmssd);
  CHECK(f.mean_hr_bpm == Approx(75.0));
  CHECK(f.rejected_fraction == Approx(0.1));
  CHECK_FALSE(f.motion_artefact);

  beats.accepted = 12;  // 9.6 s of 30: under half the window
  f = window_features(beats, quality, 30000, thresholds);
  CHECK_FALSE(f.has_heart_rate);
  CHECK_FALSE(f.has_rmssd);
  CHECK(f.mean_hr_bpm == 0.0f);
  CHECK(f.motion_artefact);  // 4 of 16 rejected

  beats.accepted = 36;
  quality.disturbed = 2;  // 2 of 15 segments > 10 %
  CHECK(window_features(beats, quality, 30000, thresholds).motion_artefact);
  quality.disturbed = 1;
  CHECK_FALSE(window_features(beats, quality, 30000, thresholds).motion_artefact);

  beats.successive_differences = 1;
  CHECK_FALSE(window_features(beats, quality, 30000, thresholds).has_rmssd);
}
