#include "home/home_settings.h"

#include <stdexcept>

namespace alplan::home {

nlohmann::json HomeSettings::json() const {
  nlohmann::json script_json = nlohmann::json::array();
  for (const ScriptedEpisode& e : script) {
    script_json.push_back({{"senior", e.senior}, {"start", e.start}, {"emotion", e.emotion}});
  }
  nlohmann::json breakdowns_json = nlohmann::json::array();
  for (const ScriptedBreakdown& b : breakdowns) breakdowns_json.push_back({{"robot", b.robot}, {"time", b.time}});
  nlohmann::json devices_json = nlohmann::json::array();
  for (const HomeDevice& d : devices) devices_json.push_back({{"name", d.name}, {"type", d.type}, {"room", d.room}});
  nlohmann::json j = {{"log_version", kHomeLogVersion},
                      {"domains_dir", domains_dir},
                      {"home_file", home_file},
                      {"generate", {{"seniors", generate_seniors}, {"robots", generate_robots},
                                    {"rooms", generate_rooms}, {"objects", generate_objects}}},
                      {"strategy", strategy},
                      {"observe", observe},
                      {"until", until},
                      {"seed", seed},
                      {"seniors_model",
                       {{"episodes_per_hour", seniors.episodes_per_hour}, {"calm_start_s", seniors.calm_start_s},
                        {"face_accuracy", seniors.face_accuracy}, {"recovery_s", seniors.recovery_s},
                         {"drift_bpm", seniors.drift_bpm},
                        {"terrified_share", seniors.terrified_share}, {"sad_share", seniors.sad_share}}},
                      {"script", script_json},
                      {"breakdowns", breakdowns_json},
                      {"devices", devices_json},
                      {"failure_chance", failure_chance},
                      {"failure_kinds", failure_kinds},
                      {"step_s", step_s},
                      {"look_interval_s", look_interval_s},
                      {"grace_s", grace_s},
                      {"windows", {{"terrified_s", terrified_window_s}, {"other_s", other_window_s}}},
                      {"planner_expansions", planner_expansions},
                      {"planner_node_limit", planner_node_limit},
                      {"fleet", fleet},
                      {"urgency_weights", {{"terrified", terrified_weight}, {"sad", sad_weight}, {"bored", bored_weight}}},
                      {"service_estimate_s", service_estimate_s},
                      {"soft_windows", soft_windows},
                      {"window_cost_s", window_cost_s},
                      {"robot_repair_s", robot_repair_s},
                      {"dispatch", dispatch},
                      {"replan_expansions", replan_expansions},
                      {"object_return_s", object_return_s},
                      {"stress_follow_readings", stress_follow_readings},
                      {"planning_time", planning_time}};
  // Only when set: a simulated run's settings stay as logs before --live
  // had them, so those logs still replay.
  if (live) j["live"] = true;
  // Likewise only with batteries: runs without them keep their settings.
  if (battery) j["battery"] = battery_options.json();
  // And only with breakdowns at random: older logs replay unchanged.
  if (breakdown_rate_per_hour > 0.0) j["breakdown_rate_per_hour"] = breakdown_rate_per_hour;
  return j;
}

HomeSettings HomeSettings::from_json(const nlohmann::json& j) {
  HomeSettings s;
  int version = 0;  // not settings at all
  if (j.is_object()) {
    const auto v = j.find("log_version");
    version = v == j.end() ? 1 : v->is_number_integer() ? v->get<int>() : 0;
  }
  if (version != kHomeLogVersion) {
    throw std::invalid_argument("the run's settings are of home log version " + std::to_string(version) +
                                "; this alplan replays version " + std::to_string(kHomeLogVersion) +
                                " (the planner and the simulation have changed since: run the home again)");
  }
  try {
    s.domains_dir = j.at("domains_dir").get<std::string>();
    s.home_file = j.at("home_file").get<std::string>();
    const nlohmann::json& g = j.at("generate");
    s.generate_seniors = g.at("seniors").get<int>();
    s.generate_robots = g.at("robots").get<int>();
    s.generate_rooms = g.at("rooms").get<int>();
    s.generate_objects = g.at("objects").get<int>();
    s.strategy = j.at("strategy").get<std::string>();
    s.observe = j.at("observe").get<std::string>();
    s.live = j.value("live", false);  // written only for live runs
    if (j.contains("battery")) {  // written only for runs with batteries
      s.battery = true;
      s.battery_options = domains::BatteryOptions::from_json(j.at("battery"));
    }
    s.until = j.at("until").get<double>();
    s.seed = j.at("seed").get<std::uint64_t>();
    s.breakdown_rate_per_hour = j.value("breakdown_rate_per_hour", 0.0);  // written only when set
    const nlohmann::json& m = j.at("seniors_model");
    s.seniors.episodes_per_hour = m.at("episodes_per_hour").get<double>();
    s.seniors.calm_start_s = m.at("calm_start_s").get<double>();
    s.seniors.face_accuracy = m.at("face_accuracy").get<double>();
    s.seniors.recovery_s = m.at("recovery_s").get<double>();
    s.seniors.drift_bpm = m.at("drift_bpm").get<double>();
    s.seniors.terrified_share = m.at("terrified_share").get<double>();
    s.seniors.sad_share = m.at("sad_share").get<double>();
    for (const nlohmann::json& e : j.at("script")) {
      s.script.push_back({e.at("senior").get<std::string>(), e.at("start").get<double>(),
                          e.at("emotion").get<std::string>()});
    }
    for (const nlohmann::json& b : j.at("breakdowns")) {
      s.breakdowns.push_back({b.at("robot").get<std::string>(), b.at("time").get<double>()});
    }
    for (const nlohmann::json& d : j.at("devices")) {
      s.devices.push_back({d.at("name").get<std::string>(), d.at("type").get<std::string>(),
                           d.at("room").get<std::string>()});
    }
    s.failure_chance = j.at("failure_chance").get<double>();
    s.failure_kinds = j.at("failure_kinds").get<std::vector<std::string>>();
    s.step_s = j.at("step_s").get<double>();
    s.look_interval_s = j.at("look_interval_s").get<double>();
    s.grace_s = j.at("grace_s").get<double>();
    s.terrified_window_s = j.at("windows").at("terrified_s").get<double>();
    s.other_window_s = j.at("windows").at("other_s").get<double>();
    s.planner_expansions = j.at("planner_expansions").get<std::uint64_t>();
    s.planner_node_limit = j.at("planner_node_limit").get<std::size_t>();
    s.fleet = j.at("fleet").get<std::string>();
    const nlohmann::json& w = j.at("urgency_weights");
    s.terrified_weight = w.at("terrified").get<double>();
    s.sad_weight = w.at("sad").get<double>();
    s.bored_weight = w.at("bored").get<double>();
    s.service_estimate_s = j.at("service_estimate_s").get<double>();
    s.soft_windows = j.at("soft_windows").get<bool>();
    s.window_cost_s = j.at("window_cost_s").get<double>();
    s.robot_repair_s = j.at("robot_repair_s").get<double>();
    s.dispatch = j.at("dispatch").get<bool>();
    s.replan_expansions = j.at("replan_expansions").get<std::uint64_t>();
    s.object_return_s = j.at("object_return_s").get<double>();
    s.stress_follow_readings = j.at("stress_follow_readings").get<std::size_t>();
    s.planning_time = j.at("planning_time").get<double>();
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(std::string("the run's settings: ") + e.what());
  }
  return s;
}

double HomeSettings::weight_of(const std::string& emotion) const {
  if (emotion == "terrified") return terrified_weight;
  if (emotion == "sad") return sad_weight;
  return bored_weight;
}

HomeSettings default_home_settings(const std::string& domains_dir) {
  HomeSettings s;
  s.domains_dir = domains_dir;
  s.home_file = domains_dir + "/home.pddl";
  s.until = 3600.0;
  s.script = {{"senior1", 300.0, "terrified"},
              {"senior3", 1200.0, "sad"},
              {"senior5", 1260.0, "bored"},
              {"senior7", 2400.0, "sad"},
              {"senior2", 2460.0, "terrified"}};
  // robot2 breaks down on its way to senior7, while robot1 serves senior2:
  // senior7's goal goes to robot1 (issue 31's fleet).
  s.breakdowns = {{"robot2", 2500.0}};
  // Speakers where the terrified seniors of the script are, lamps where the
  // sad ones are (the library's TV is the problem's own).
  s.devices = {{"speaker1", "speaker", "bedroom1"}, {"speaker2", "speaker", "bedroom2"},
               {"lamp1", "lamp", "bedroom3"}, {"lamp2", "lamp", "library1"}};
  s.failure_chance = 0.8;
  s.failure_kinds = {"sibling", "arrival", "moves"};
  return s;
}

}  // namespace alplan::home
