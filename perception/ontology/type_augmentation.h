// Types augmentation (the paper's Section 6.2, layer 0): starting from a
// domain's object types, find new subtypes in a lexical knowledge base and
// write the augmented hierarchy as an OWL ontology (the paper's Fig. 5), so
// that perception can learn to recognise objects of the new types and the
// planner can use them when a plan's object fails.
//
// The paper adapts the first three stages of the context-aware knowledge
// acquisition method of its reference [13]; the knowledge base here is
// WordNet 3.0. The stages, as implemented:
//  1. Anchor: each category type (drinking_vessel, making_music, ...) gets
//     WordNet senses. Given senses (a configuration line) win; otherwise the
//     type's own lemma, disambiguated by the sense that subsumes most of its
//     known subtypes; otherwise the lowest common hypernym of its subtypes'
//     senses, if it is close to them (at most `max_lcs_height` levels up).
//  2. Candidates: a synset is a candidate subtype of the anchor when
//     (a) it is a hyponym within `max_depth` levels (mug, drum, clarinet), or
//     (b) its gloss names the anchor as its genus ("a daily or weekly
//         publication on folded sheets": newspaper), or
//     (c) the anchor is a compound whose modifier states a purpose
//         (drinking_vessel) and the gloss states the same purpose of a thing
//         that shares the anchor's grandparent ("a small open container
//         usually used for drinking": cup).
//     Only physical objects and documents count (WordNet's noun.artifact and
//     noun.communication files); known types and their synonyms do not.
//  3. Selection: candidates are ranked by how common the sense is (SemCor
//     tag counts), then by WordNet familiarity (polysemy), then by depth;
//     when a perceivable vocabulary is given (what the object recognisers
//     can see) only its members are kept, since a type nobody can perceive
//     never repairs a plan; at most `max_new_per_type` per category.
// Every decision is kept with its reason, so the result can be explained.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "pddl_parser/ast.h"
#include "perception/ontology/wordnet.h"

namespace alplan::perception {

// A domain's types: child -> parent ("object" at the top has no entry).
using TypeParents = std::map<std::string, std::string>;
// The hierarchy a domain declares; a type with `either` parents keeps the
// first, as an OWL class here has one superclass.
TypeParents type_parents(const pddl::Domain& domain);

struct CategoryConfig {
  std::string type;                  // a domain type to augment
  std::vector<std::string> anchors;  // WordNet senses ("musical_instrument.n.01"); empty: find them
};

struct AugmentationOptions {
  int max_depth = 5;        // hyponym levels below an anchor (clarinet is 5 below musical_instrument)
  int max_lcs_height = 2;   // how far above the subtypes a common hypernym may be
  int max_new_per_type = 3;
  bool single_words_only = true;  // "mug", not "coffee_mug" (unless perceivable)
  // Lower-case names a recogniser can see ("cup", "wine_glass"); empty: all.
  std::set<std::string> perceivable;
};

struct AugmentedType {
  std::string name;    // the new PDDL type, e.g. "mug"
  std::string parent;  // the category, e.g. "drinking_vessel"
  std::string sense;   // "mug.n.04"
  std::string gloss;
  std::string rule;    // "hyponym at depth 1", "gloss genus", "gloss purpose"
  int tag_count = 0;
  int polysemy = 0;
};

struct CategoryReport {
  std::string type;
  std::vector<std::string> anchors;  // sense names used
  std::string anchor_reason;         // how they were found, or why none
  std::vector<AugmentedType> added;
  std::vector<std::pair<std::string, std::string>> passed_over;  // name, why (best ranked first)
};

struct AugmentationResult {
  std::vector<CategoryReport> categories;
  std::vector<AugmentedType> added() const;
};

AugmentationResult augment_types(const WordNet& wordnet, const TypeParents& domain_types,
                                 const std::vector<CategoryConfig>& categories, const AugmentationOptions& options);

// The domain's hierarchy plus the added types as OWL in Turtle, in the
// vocabulary repair::TypeOntology reads: classes, rdfs:subClassOf, and
// al:augmented true on the added ones (with rdfs:comment = the gloss and
// al:wordnetSense = the sense).
std::string augmented_ontology_turtle(const TypeParents& domain_types, const AugmentationResult& result);

// Reads a category configuration: one category per line, the type then
// optional WordNet senses, '#' comments. Throws std::runtime_error with
// file:line on a malformed line.
std::vector<CategoryConfig> read_category_config(const std::string& text, const std::string& source_name);

}  // namespace alplan::perception
