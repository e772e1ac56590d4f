#include "domains/home_generator.h"

#include <catch2/catch.hpp>

#include <map>
#include <regex>
#include <set>

#include "domains/pddl_files.h"
#include "planner/grounder.h"
#include "planner/planner.h"
#include "tests/support/test_paths.h"

using namespace alplan;

TEST_CASE("a generated home is valid PDDL for the domain, the same for the same seed") {
  const std::string dir = test::source_dir() + "/domains/assisted_living/";
  for (std::uint64_t seed : {1u, 2u, 3u, 4u, 5u}) {
    domains::HomeOptions o;
    o.seed = seed;
    o.stressed = 2;
    const domains::GeneratedHome home = domains::generate_home(o);
    CHECK(home.problem == domains::generate_home(o).problem);
    const std::string domain = test::read_text(dir + "domain.pddl");
    const domains::LoadedFiles files = domains::load_pddl_text(domain, "domain.pddl", home.problem, "home.pddl");
    PlannerOptions options;
    options.time_limit = 10.0;
    const PlannerResult result = Planner(ground(*files.domain, *files.problem), options).plan();
    INFO("seed " << seed << ": " << result.message);
    CHECK(result.status == PlannerResult::Status::Solved);
  }
  domains::HomeOptions a, b;
  b.seed = 2;
  CHECK(domains::generate_home(a).problem != domains::generate_home(b).problem);
}

TEST_CASE("a terrified senior's window closes sooner than a sad or bored one's") {
  double terrified = 0.0, other = 1e9;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    domains::HomeOptions o;
    o.seed = seed;
    o.stressed = 3;
    const domains::GeneratedHome home = domains::generate_home(o);
    const std::regex window(R"(\(at (\d+) \(not \((hydration_time|comfort_time) )");
    for (std::sregex_iterator it(home.problem.begin(), home.problem.end(), window), end; it != end; ++it) {
      const double at = std::stod((*it)[1]);
      if ((*it)[2] == "hydration_time") terrified = std::max(terrified, at);
      else other = std::min(other, at);
    }
  }
  CHECK(terrified > 0.0);
  CHECK(terrified < other);
}

TEST_CASE("impossible homes are refused with a reason") {
  domains::HomeOptions o;
  o.rooms = 2;
  CHECK_THROWS_WITH(domains::generate_home(o), Catch::Contains("at least 4 rooms"));
  o = {};
  o.stressed = 9;
  CHECK_THROWS_WITH(domains::generate_home(o), Catch::Contains("--stressed"));
}

TEST_CASE("scatter leaves objects in other rooms, and none leaves the home as it was") {
  domains::HomeOptions o;
  o.objects = 60;
  const domains::GeneratedHome kept = domains::generate_home(o);
  o.scatter = 1.0;
  const domains::GeneratedHome all = domains::generate_home(o);
  o.scatter = 0.5;
  const domains::GeneratedHome half = domains::generate_home(o);
  REQUIRE(kept.objects.size() == 60);
  REQUIRE(all.objects.size() == 60);
  std::map<std::string, std::set<std::string>> rooms_of_type;
  std::size_t moved = 0;
  for (std::size_t i = 0; i < kept.objects.size(); ++i) {
    // The objects, their tags and the rest of the home do not depend on the scatter.
    CHECK(all.objects[i].name == kept.objects[i].name);
    CHECK(all.objects[i].iot == kept.objects[i].iot);
    CHECK(all.objects[i].room != kept.objects[i].room);
    moved += half.objects[i].room != kept.objects[i].room ? 1 : 0;
    rooms_of_type[kept.objects[i].type].insert(kept.objects[i].room);
  }
  for (const auto& [type, rooms] : rooms_of_type) CHECK(rooms.size() == 1);
  CHECK(moved > 15);
  CHECK(moved < 45);
  CHECK(kept.problem.find("--scatter") == std::string::npos);
  CHECK(half.problem.find("--scatter 0.5") != std::string::npos);
  // A scattered home is still a valid problem the planner solves.
  const std::string dir = test::source_dir() + "/domains/assisted_living/";
  const domains::LoadedFiles files =
      domains::load_pddl_text(test::read_text(dir + "domain.pddl"), "domain.pddl", half.problem, "home.pddl");
  PlannerOptions options;
  options.time_limit = 10.0;
  CHECK(Planner(ground(*files.domain, *files.problem), options).plan().status == PlannerResult::Status::Solved);
  o.scatter = 1.5;
  CHECK_THROWS_WITH(domains::generate_home(o), Catch::Contains("--scatter"));
}
