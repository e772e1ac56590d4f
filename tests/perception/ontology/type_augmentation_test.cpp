#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <set>

#include "pddl_parser/parser.h"
#include "perception/ontology/type_augmentation.h"
#include "perception/ontology/wordnet.h"
#include "repair/type_ontology.h"
#include "tests/support/test_paths.h"

using namespace alplan::perception;

namespace {

const WordNet& wordnet() {
  static const WordNet wn = WordNet::load_nouns();  // read once: 82,115 synsets
  return wn;
}

TypeParents assisted_living_types() {
  const std::string path = alplan::test::source_dir() + "/domains/assisted_living/domain.pddl";
  const auto parsed = alplan::pddl::parse_domain(alplan::test::read_text(path), path);
  REQUIRE(parsed.ok());
  return type_parents(*parsed.ast);
}

std::vector<CategoryConfig> shipped_config() {
  const std::string path = alplan::test::source_dir() + "/domains/assisted_living/augmentation.txt";
  return read_category_config(alplan::test::read_text(path), path);
}

std::set<std::string> names_under(const AugmentationResult& result, const std::string& parent) {
  std::set<std::string> names;
  for (const AugmentedType& t : result.added()) {
    if (t.parent == parent) names.insert(t.name);
  }
  return names;
}

// The classes of the paper's own object dataset (its Table 4).
std::set<std::string> paper_table4_classes() {
  return {"book",     "clarinet", "cup",        "drinking_glass", "drum",      "glass_bottle",
          "guitar",   "jar",      "journal",    "magazine",       "magic_cube", "mug",
          "newspaper", "puzzle",  "story",      "sudoku",         "violin",    "yo_yo"};
}

}  // namespace

TEST_CASE("WordNet: senses by name, sense names, hyponyms and tag counts") {
  const WordNet& wn = wordnet();
  CHECK(wn.synset_count() == 82115);  // WordNet 3.0's noun synsets
  const auto instrument = wn.find_sense("musical_instrument.n.01");
  REQUIRE(instrument);
  CHECK(wn.sense_name(*instrument) == "musical_instrument.n.01");
  const auto clarinet = wn.find_sense("clarinet.n.01");
  REQUIRE(clarinet);
  CHECK(wn.is_a(*clarinet, *instrument));
  CHECK_FALSE(wn.is_a(*instrument, *clarinet));
  bool clarinet_at_5 = false;
  for (const auto& [s, depth] : wn.hyponym_closure(*instrument, 5)) clarinet_at_5 |= s == *clarinet && depth == 5;
  CHECK(clarinet_at_5);
  CHECK(wn.senses("Musical Instrument") == std::vector<SynsetOffset>{*instrument});
  CHECK(wn.tag_count(*wn.find_sense("cup.n.01")) == 14);  // cntlist.rev: cup%1:06:00:: 14
  CHECK(wn.polysemy("cup") == 8);
  CHECK_FALSE(wn.find_sense("musical_instrument.n.02"));
  CHECK_THROWS_AS(wn.synset(1), WordNetError);
}

TEST_CASE("WordNet: a malformed database is refused with the file and line") {
  const auto dir = std::filesystem::temp_directory_path() / "alplan-wordnet-bad";
  std::filesystem::create_directories(dir);
  {
    std::ofstream(dir / "data.noun") << "  licence line\n00001740 03 n 01 entity 0 00x | gloss\n";
    std::ofstream(dir / "index.noun") << "entity n 1 0 1 0 00001740\n";
  }
  try {
    (void)WordNet::load_nouns(dir);
    FAIL("a malformed pointer count was accepted");
  } catch (const WordNetError& e) {
    CHECK_THAT(e.what(), Catch::Contains("data.noun:2: expected a pointer count, found '00x'"));
  }
  CHECK_THROWS_WITH(WordNet::load_nouns(dir / "missing"), Catch::Contains("cannot open"));
}

TEST_CASE("augmentation finds new subtypes of the assisted-living categories in WordNet") {
  const AugmentationResult result =
      augment_types(wordnet(), assisted_living_types(), shipped_config(), AugmentationOptions{});
  const auto vessels = names_under(result, "drinking_vessel");
  CHECK(vessels.count("mug"));  // a hyponym of drinking_vessel
  CHECK(vessels.count("cup"));  // "a small open container usually used for drinking"
  CHECK(names_under(result, "making_music").count("drum"));
  CHECK(names_under(result, "reading").count("newspaper"));  // "a daily or weekly publication"
  CHECK(names_under(result, "solving").count("sudoku"));
  for (const CategoryReport& c : result.categories) {
    CHECK(c.added.size() <= 3);
    if (c.type == "reading") CHECK(c.anchors == std::vector<std::string>{"publication.n.01"});
    if (c.type == "drinking_vessel") CHECK(c.anchors == std::vector<std::string>{"drinking_vessel.n.01"});
    if (c.type == "communication_device") {
      CHECK(c.added.empty());
      CHECK_THAT(c.anchor_reason, Catch::Contains("give its senses in the configuration"));
    }
  }
  // Known types never come back as new ones.
  for (const AugmentedType& t : result.added()) {
    CHECK_FALSE(assisted_living_types().count(t.name));
    CHECK_FALSE(t.sense.empty());
    CHECK_FALSE(t.rule.empty());
  }
}

TEST_CASE("restricted to what the paper's dataset can show, augmentation finds Fig. 5's WordNet types") {
  AugmentationOptions options;
  options.perceivable = paper_table4_classes();
  const AugmentationResult result = augment_types(wordnet(), assisted_living_types(), shipped_config(), options);
  CHECK(names_under(result, "drinking_vessel") == std::set<std::string>{"cup", "mug"});
  CHECK(names_under(result, "making_music") == std::set<std::string>{"clarinet", "drum"});
  CHECK(names_under(result, "reading") == std::set<std::string>{"journal", "newspaper"});
  CHECK(names_under(result, "solving") == std::set<std::string>{"sudoku"});
}

TEST_CASE("the augmented ontology is OWL that the monitor's ontology reader takes") {
  AugmentationOptions options;
  options.perceivable = paper_table4_classes();
  const TypeParents types = assisted_living_types();
  const AugmentationResult result = augment_types(wordnet(), types, shipped_config(), options);
  const std::string turtle = augmented_ontology_turtle(types, result);
  const auto ontology = alplan::repair::TypeOntology::from_turtle(turtle, "generated.ttl");
  CHECK(ontology.parent("mug") == "drinking_vessel");
  CHECK(ontology.parent("clarinet") == "making_music");
  CHECK(ontology.parent("violin") == "making_music");
  CHECK(ontology.augmented().count("sudoku"));
  CHECK_FALSE(ontology.augmented().count("violin"));
  CHECK(ontology.lineage("sudoku") == std::vector<std::string>{"sudoku", "solving", "entertainment", "object"});
}

TEST_CASE("category configurations: senses are checked, errors name the line") {
  const auto config = read_category_config("# comment\nreading\nmaking_music musical_instrument.n.01 # why\n", "c");
  REQUIRE(config.size() == 2);
  CHECK(config[1].anchors == std::vector<std::string>{"musical_instrument.n.01"});
  CHECK_THROWS_WITH(read_category_config("reading\nsolving puzzle\n", "cfg.txt"),
                    Catch::Contains("cfg.txt:2: expected a WordNet noun sense"));
  CategoryConfig unknown{"spaceship", {}};
  CHECK_THROWS_AS(augment_types(wordnet(), assisted_living_types(), {unknown}, {}), std::invalid_argument);
  CategoryConfig bad_sense{"reading", {"publication.n.99"}};
  const auto result = augment_types(wordnet(), assisted_living_types(), {bad_sense}, {});
  CHECK(result.categories.front().added.empty());
  CHECK_THAT(result.categories.front().anchor_reason, Catch::Contains("publication.n.99 is not in WordNet"));
}
