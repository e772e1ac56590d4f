#include "domains/home_generator.h"

#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace alplan::domains {
namespace {

struct Room {
  std::string name, type;
};

std::string numbered(const std::string& base, int n) { return base + std::to_string(n); }

std::vector<Room> make_rooms(int count, std::mt19937_64& random) {
  std::vector<Room> rooms{{"kitchen1", "kitchen"}, {"dinning_room1", "dinning_room"},
                          {"music_room1", "music_room"}, {"library1", "library"}};
  int bedrooms = 0, sunrooms = 0;
  for (int i = 4; i < count; ++i) {
    if (std::uniform_int_distribution<int>(0, 3)(random) == 0) {
      rooms.push_back({numbered("sunroom", ++sunrooms), "sunroom"});
    } else {
      rooms.push_back({numbered("bedroom", ++bedrooms), "bedroom"});
    }
  }
  if (bedrooms == 0) rooms.push_back({"bedroom1", "bedroom"});
  return rooms;
}

// Portable object kinds: type, the room type it lives in, name stem.
struct Kind {
  const char* type;
  const char* home;
  const char* stem;
};
constexpr Kind kKinds[] = {
    {"drinking_glass", "kitchen", "glass_id"}, {"glass_bottle", "kitchen", "bottle_id"},
    {"violin", "music_room", "violin_id"},     {"guitar", "music_room", "guitar_id"},
    {"book", "library", "book_id"},            {"magazine", "library", "magazine_id"},
    {"puzzle", "library", "puzzle_id"},        {"tv", "library", "tv_id"},
    {"desktop", "library", "pc_id"},
};

std::string two_digits(int n) { return (n < 10 ? "0" : "") + std::to_string(n); }

struct Layout {
  std::vector<Room> rooms;
  int corridors = 1;
  std::vector<std::pair<std::string, std::string>> paths;
  std::vector<int> times;
  std::vector<std::string> senior_rooms;   // of every senior
  std::vector<std::string> robot_rooms;
  std::vector<int> windows;                // per stressed senior: when it closes
};

// As the command line would give it ("0.35"), and only when objects move,
// so that the homes made before the option existed keep their text.
std::string scatter_flag(double scatter) {
  if (scatter <= 0.0) return "";
  std::ostringstream out;
  out << " --scatter " << scatter;
  return out.str();
}

std::string problem_text(const GeneratedHome& home, const Layout& l, const HomeOptions& o) {
  std::string out = "; A generated assisted-living home: alplan gen home --rooms " + std::to_string(o.rooms) +
                    " --seniors " + std::to_string(o.seniors) + " --robots " + std::to_string(o.robots) +
                    " --objects " + std::to_string(o.objects) + " --stressed " + std::to_string(o.stressed) +
                    " --seed " + std::to_string(o.seed) + scatter_flag(o.scatter) + "\n";
  out += "(define (problem home-" + std::to_string(o.seed) + ") (:domain assisted_living)\n  (:objects\n   ";
  for (int r = 1; r <= o.robots; ++r) out += " " + numbered("robot", r);
  out += " - robot\n   ";
  for (int s = 1; s <= o.seniors; ++s) out += " " + numbered("senior", s);
  out += " - senior\n   ";
  for (int c = 1; c <= l.corridors; ++c) out += " " + numbered("corridor", c);
  out += " - corridor";
  for (const Room& r : l.rooms) out += "\n    " + r.name + " - " + r.type;
  for (const GeneratedHome::Object& obj : home.objects) out += "\n    " + obj.name + " - " + obj.type;
  out += ")\n  (:init\n";
  for (int r = 0; r < o.robots; ++r) out += "    (be " + numbered("robot", r + 1) + " " + l.robot_rooms[static_cast<std::size_t>(r)] + ")\n";
  for (int s = 0; s < o.seniors; ++s) out += "    (be " + numbered("senior", s + 1) + " " + l.senior_rooms[static_cast<std::size_t>(s)] + ")\n";
  for (const GeneratedHome::Object& obj : home.objects) {
    out += "    (be " + obj.name + " " + obj.room + ")" + (obj.available ? " (available " + obj.name + ")" : "") +
           (obj.iot ? " (iot_tagged " + obj.name + ")" : "") + "\n";
  }
  for (std::size_t s = 0; s < home.stressed.size(); ++s) {
    const StressedSenior& senior = home.stressed[s];
    const std::string window = senior.emotion == "terrified" ? "hydration_time" : "comfort_time";
    out += "    (" + senior.emotion + " " + senior.name + ") (" + window + " " + senior.name + ") (at " +
           std::to_string(l.windows[s]) + " (not (" + window + " " + senior.name + ")))\n";
  }
  for (std::size_t p = 0; p < l.paths.size(); ++p) {
    const auto& [a, b] = l.paths[p];
    const std::string t = std::to_string(l.times[p]);
    out += "    (path " + a + " " + b + ") (path " + b + " " + a + ") (= (moving_time " + a + " " + b + ") " + t +
           ") (= (moving_time " + b + " " + a + ") " + t + ")\n";
  }
  out += "    (= (handling_time) 10) (= (receiving_time) 10) (= (suggesting_time) 5)\n";
  out += "    (= (suggestion_cost) 500) (= (total-cost) 0))\n  (:goal (and";
  for (const StressedSenior& senior : home.stressed) out += " " + senior.goal;
  out += "))\n  (:metric minimize (+ (total-time) (total-cost))))\n";
  return out;
}

void scatter_objects(GeneratedHome& home, const HomeOptions& o) {
  if (o.scatter <= 0.0) return;
  std::mt19937_64 random(o.seed ^ 0x5CA77E40ULL);
  for (GeneratedHome::Object& obj : home.objects) {
    if (std::uniform_real_distribution<double>(0.0, 1.0)(random) >= o.scatter) continue;
    std::vector<const std::string*> elsewhere;
    for (const std::string& room : home.rooms) {
      if (room != obj.room) elsewhere.push_back(&room);
    }
    obj.room = *elsewhere[std::uniform_int_distribution<std::size_t>(0, elsewhere.size() - 1)(random)];
  }
}

}  // namespace

GeneratedHome generate_home(const HomeOptions& o) {
  if (o.rooms < 4) throw std::invalid_argument("a home needs at least 4 rooms (kitchen, dining room, music room, library)");
  if (o.seniors < 1 || o.robots < 1) throw std::invalid_argument("a home needs a senior and a robot");
  if (o.stressed < 1 || o.stressed > o.seniors) throw std::invalid_argument("--stressed must be 1..seniors");
  if (!(o.iot_share >= 0.0 && o.iot_share <= 1.0)) throw std::invalid_argument("--iot-share must be within 0..1");
  if (!(o.scatter >= 0.0 && o.scatter <= 1.0)) throw std::invalid_argument("--scatter must be within 0..1");
  if (o.objects < 0 || o.rooms > 500 || o.seniors > 500 || o.objects > 2000 || o.robots > 50) {
    throw std::invalid_argument("the home is too large (rooms <= 500, seniors <= 500, objects <= 2000, robots <= 50)");
  }
  std::mt19937_64 random(o.seed);
  auto uniform = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(random); };
  GeneratedHome home;
  Layout l;
  l.rooms = make_rooms(o.rooms, random);
  l.corridors = std::max(1, static_cast<int>(l.rooms.size() + 3) / 4);
  for (int c = 2; c <= l.corridors; ++c) {  // a random tree of corridors
    l.paths.emplace_back(numbered("corridor", uniform(1, c - 1)), numbered("corridor", c));
    l.times.push_back(uniform(6, 12) * 5);
  }
  for (const Room& r : l.rooms) {
    home.rooms.push_back(r.name);
    if (r.type == "kitchen") {
      l.paths.emplace_back("dinning_room1", "kitchen1");
      l.times.push_back(uniform(2, 6) * 5);
    } else {
      l.paths.emplace_back(numbered("corridor", uniform(1, l.corridors)), r.name);
      l.times.push_back(uniform(4, 10) * 5);
    }
  }
  std::vector<std::string> private_rooms;
  for (const Room& r : l.rooms) {
    if (r.type == "bedroom" || r.type == "sunroom") private_rooms.push_back(r.name);
  }
  auto pick = [&](const std::vector<std::string>& from) {
    return from[static_cast<std::size_t>(uniform(0, static_cast<int>(from.size()) - 1))];
  };
  for (int s = 0; s < o.seniors; ++s) l.senior_rooms.push_back(pick(private_rooms));
  for (int r = 0; r < o.robots; ++r) l.robot_rooms.push_back(pick(home.rooms));
  const char* emotions[] = {"terrified", "sad", "bored"};
  for (int s = 0; s < o.stressed; ++s) {
    const std::string emotion = emotions[uniform(0, 2)];
    const std::string name = numbered("senior", s + 1);
    const std::string goal = emotion == "terrified" ? "soothed" : emotion == "sad" ? "cheerful" : "entertained";
    home.stressed.push_back({name, emotion, "(" + goal + " " + name + ")", l.senior_rooms[static_cast<std::size_t>(s)]});
    // Urgency: water within 10-15 minutes; company within 25-40.
    l.windows.push_back(emotion == "terrified" ? uniform(60, 90) * 10 : uniform(150, 240) * 10);
  }
  // Every kind at least once (a repair needs alternatives), then at random.
  std::map<std::string, int> per_kind;
  for (int i = 0; i < o.objects; ++i) {
    const int kinds = static_cast<int>(std::size(kKinds));
    const Kind& k = kKinds[i < kinds ? i : uniform(0, kinds - 1)];
    std::string room;
    for (const Room& r : l.rooms) {
      if (r.type == k.home) room = r.name;
    }
    home.objects.push_back({k.stem + two_digits(++per_kind[k.type]), k.type, room, uniform(0, 9) < 8});
  }
  scatter_objects(home, o);
  std::mt19937_64 tags(o.seed ^ 0x10700000ULL);
  for (GeneratedHome::Object& obj : home.objects) obj.iot = std::uniform_real_distribution<double>(0.0, 1.0)(tags) < o.iot_share;
  home.problem = problem_text(home, l, o);
  return home;
}

}  // namespace alplan::domains
