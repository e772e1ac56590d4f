// The type hierarchy of a domain as an OWL ontology in Turtle (the paper's
// Fig. 5): every class a PDDL type, rdfs:subClassOf its parent, and the
// classes knowledge augmentation added marked <...#augmented> true. Read with
// raptor2, the standard RDF parser library. The monitor adds the augmented
// types to the domain so that perception can name new objects with them and
// the planner can use those objects at once.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "pddl_parser/ast.h"

namespace alplan::repair {

class OntologyError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class TypeOntology {
 public:
  // Throws OntologyError with the place and the problem on bad input.
  static TypeOntology from_turtle(const std::string& text, const std::string& source_name);
  static TypeOntology from_file(const std::string& path);

  const std::map<std::string, std::string>& parents() const { return parents_; }
  const std::set<std::string>& augmented() const { return augmented_; }
  std::optional<std::string> parent(const std::string& type) const;
  // The type and its ancestors, nearest first.
  std::vector<std::string> lineage(const std::string& type) const;

 private:
  std::map<std::string, std::string> parents_;
  std::set<std::string> augmented_;
};

// The domain with every augmented type the domain lacks, under its parent
// (the parent must be a type the domain has, or one added before it).
pddl::Domain augment_domain(const pddl::Domain& domain, const TypeOntology& ontology);

}  // namespace alplan::repair
