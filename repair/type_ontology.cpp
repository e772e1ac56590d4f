#include "repair/type_ontology.h"

#include <raptor2.h>

#include <fstream>
#include <memory>
#include <sstream>

namespace alplan::repair {
namespace {

const std::string kSubClassOf = "http://www.w3.org/2000/01/rdf-schema#subClassOf";

// The local name of a URI: after its last '#' or '/'.
std::string local_name(const std::string& uri) {
  const std::size_t cut = uri.find_last_of("#/");
  return cut == std::string::npos ? uri : uri.substr(cut + 1);
}

std::string term_text(const raptor_term* term) {
  if (!term) return {};
  switch (term->type) {
    case RAPTOR_TERM_TYPE_URI: return reinterpret_cast<const char*>(raptor_uri_as_string(term->value.uri));
    case RAPTOR_TERM_TYPE_LITERAL: return reinterpret_cast<const char*>(term->value.literal.string);
    default: return {};
  }
}

struct Collector {
  std::vector<std::pair<std::string, std::string>> subclass;  // child, parent
  std::set<std::string> augmented;
  std::string errors;
  std::string source;
};

void on_statement(void* user_data, raptor_statement* triple) {
  auto* c = static_cast<Collector*>(user_data);
  const std::string predicate = term_text(triple->predicate);
  const std::string subject = local_name(term_text(triple->subject));
  if (predicate == kSubClassOf) c->subclass.emplace_back(subject, local_name(term_text(triple->object)));
  if (local_name(predicate) == "augmented" && term_text(triple->object) == "true") c->augmented.insert(subject);
}

void on_log(void* user_data, raptor_log_message* message) {
  if (message->level < RAPTOR_LOG_LEVEL_ERROR) return;
  auto* c = static_cast<Collector*>(user_data);
  const int line = message->locator ? raptor_locator_line(message->locator) : -1;
  const int column = message->locator ? raptor_locator_column(message->locator) : -1;
  c->errors += c->source + ":" + std::to_string(line) + ":" + std::to_string(std::max(column, 1)) + ": " +
               (message->text ? message->text : "error") + "\n";
}

}  // namespace

TypeOntology TypeOntology::from_turtle(const std::string& text, const std::string& source_name) {
  Collector collected;
  collected.source = source_name;
  std::unique_ptr<raptor_world, decltype(&raptor_free_world)> world(raptor_new_world(), raptor_free_world);
  if (!world || raptor_world_open(world.get()) != 0) throw OntologyError("raptor2 could not start");
  raptor_world_set_log_handler(world.get(), &collected, on_log);
  std::unique_ptr<raptor_parser, decltype(&raptor_free_parser)> parser(raptor_new_parser(world.get(), "turtle"),
                                                                       raptor_free_parser);
  if (!parser) throw OntologyError("raptor2 has no Turtle parser");
  raptor_parser_set_statement_handler(parser.get(), &collected, on_statement);
  std::unique_ptr<raptor_uri, decltype(&raptor_free_uri)> base(
      raptor_new_uri(world.get(), reinterpret_cast<const unsigned char*>("file:///ontology.ttl")), raptor_free_uri);
  const bool ok = raptor_parser_parse_start(parser.get(), base.get()) == 0 &&
                  raptor_parser_parse_chunk(parser.get(), reinterpret_cast<const unsigned char*>(text.data()),
                                            text.size(), 1) == 0;
  if (!ok || !collected.errors.empty()) {
    throw OntologyError(collected.errors.empty() ? source_name + ": cannot parse Turtle" : collected.errors);
  }
  TypeOntology ontology;
  for (const auto& [child, parent] : collected.subclass) {
    auto [it, inserted] = ontology.parents_.emplace(child, parent);
    if (!inserted && it->second != parent) {
      throw OntologyError(source_name + ": class " + child + " has two parents, " + it->second + " and " + parent +
                          " (a PDDL type has one parent)");
    }
  }
  for (const std::string& a : collected.augmented) {
    if (!ontology.parents_.count(a)) throw OntologyError(source_name + ": augmented class " + a + " has no parent");
    ontology.augmented_.insert(a);
  }
  for (const auto& [child, parent] : ontology.parents_) {
    if (ontology.lineage(child).size() > ontology.parents_.size() + 1) {
      throw OntologyError(source_name + ": the class hierarchy has a cycle through " + child);
    }
  }
  return ontology;
}

TypeOntology TypeOntology::from_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw OntologyError(path + ": cannot open the ontology file");
  std::ostringstream text;
  text << in.rdbuf();
  return from_turtle(text.str(), path);
}

std::optional<std::string> TypeOntology::parent(const std::string& type) const {
  auto it = parents_.find(type);
  if (it == parents_.end()) return std::nullopt;
  return it->second;
}

std::vector<std::string> TypeOntology::lineage(const std::string& type) const {
  std::vector<std::string> chain{type};
  // Bounded, so that a cycle cannot loop forever (from_turtle reports it).
  while (chain.size() <= parents_.size() + 1) {
    auto up = parent(chain.back());
    if (!up) break;
    chain.push_back(*up);
  }
  return chain;
}

pddl::Domain augment_domain(const pddl::Domain& domain, const TypeOntology& ontology) {
  pddl::Domain augmented = domain;
  std::set<std::string> declared{"object"};
  for (const pddl::TypeDeclaration& t : domain.types) declared.insert(t.name);
  bool added = true;
  while (added) {  // parents before children, whatever the file's order
    added = false;
    for (const std::string& type : ontology.augmented()) {
      const std::string parent = *ontology.parent(type);
      if (declared.count(type) || !declared.count(parent)) continue;
      pddl::TypeDeclaration declaration;
      declaration.name = type;
      declaration.parents = {parent};
      augmented.types.push_back(declaration);
      declared.insert(type);
      added = true;
    }
  }
  return augmented;
}

}  // namespace alplan::repair
