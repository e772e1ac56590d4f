#include "repair/type_ontology.h"

#include <catch2/catch.hpp>

#include "tests/support/task_loader.h"
#include "tests/support/test_paths.h"

using namespace alplan;
using namespace alplan::repair;

TEST_CASE("the checked-in ontology gives the paper's Fig. 5 hierarchy") {
  const TypeOntology ontology = TypeOntology::from_file(test::source_dir() + "/domains/assisted_living/types.ttl");
  CHECK(ontology.parent("mug") == std::optional<std::string>("drinking_vessel"));
  CHECK(ontology.parent("clarinet") == std::optional<std::string>("making_music"));
  CHECK(ontology.parent("sudoku") == std::optional<std::string>("solving"));
  CHECK(ontology.lineage("story") == std::vector<std::string>{"story", "reading", "entertainment", "object"});
  CHECK(ontology.augmented() == std::set<std::string>{"clarinet", "cup", "drum", "jar", "journal", "magic_cube", "mug",
                                                       "newspaper", "story", "sudoku"});
  CHECK_FALSE(ontology.parent("unicorn"));
}

TEST_CASE("bad Turtle is an error that names the place") {
  try {
    TypeOntology::from_turtle("@prefix al: <http://x#> .\nal:a al:b al:c .\nal:mug rdfs:subClassOf\n", "bad.ttl");
    FAIL("no error");
  } catch (const OntologyError& e) {
    CHECK(std::string(e.what()).find("bad.ttl:") != std::string::npos);
  }
}

TEST_CASE("a class with two parents cannot be a PDDL type") {
  const char* text = R"(@prefix rdfs: <http://www.w3.org/2000/01/rdf-schema#> .
@prefix al: <http://x#> .
al:mug rdfs:subClassOf al:cup . al:mug rdfs:subClassOf al:jar .)";
  CHECK_THROWS_WITH(TypeOntology::from_turtle(text, "two.ttl"), Catch::Contains("two parents"));
}

TEST_CASE("augmenting the domain adds the new types under their parents, once") {
  const std::string dir = test::source_dir() + "/domains/assisted_living/";
  auto loaded = test::load_task(dir + "domain.pddl", dir + "paper-scenario-1.pddl");
  const TypeOntology ontology = TypeOntology::from_file(dir + "types.ttl");
  const pddl::Domain augmented = augment_domain(*loaded.domain, ontology);
  CHECK(augmented.types.size() == loaded.domain->types.size() + 10);
  bool mug = false;
  for (const pddl::TypeDeclaration& t : augmented.types) {
    if (t.name == "mug") mug = t.parents == std::vector<std::string>{"drinking_vessel"};
  }
  CHECK(mug);
  CHECK(augment_domain(augmented, ontology).types.size() == augmented.types.size());
}
