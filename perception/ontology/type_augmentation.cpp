#include "perception/ontology/type_augmentation.h"

#include <algorithm>
#include <cctype>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

namespace alplan::perception {
namespace {

constexpr int kArtifactFile = 6;
constexpr int kCommunicationFile = 10;
constexpr int kNotAHyponym = std::numeric_limits<int>::max();

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

// Letters and digits only: "yo-yo", "yoyo" and "Yo_Yo" are the same name.
std::string bare(std::string_view text) {
  std::string out;
  for (unsigned char c : text) {
    if (std::isalnum(c)) out.push_back(static_cast<char>(std::tolower(c)));
  }
  return out;
}

// A WordNet word as a PDDL type name: lower case, '_' between words.
std::string type_name(std::string_view word) {
  std::string out = lower(word);
  for (char& c : out) {
    if (c == '-' || c == ' ' || c == '\'') c = '_';
  }
  return out;
}

// The gloss up to its first ';' (the definition, without examples), as
// space-separated lower-case words.
std::string definition_words(const std::string& gloss) {
  std::string out = " ";
  for (unsigned char c : gloss.substr(0, gloss.find(';'))) {
    out.push_back(std::isalnum(c) ? static_cast<char>(std::tolower(c)) : ' ');
  }
  return out + " ";
}

bool mentions(const std::string& definition, const std::string& phrase) {
  return definition.find(" " + phrase + " ") != std::string::npos;
}

// The genus of a definition: the words before the first preposition or
// relative word ("a daily or weekly publication | on folded sheets").
std::string genus_words(const std::string& definition) {
  static const char* const kCuts[] = {" of ",   " on ",   " in ",    " for ",  " with ",       " that ",
                                      " which ", " who ", " where ", " when ", " used ",       " to ",
                                      " by ",    " from ", " made ",  " having ", " consisting ", " containing "};
  std::size_t end = definition.size();
  for (const char* cut : kCuts) end = std::min(end, definition.find(cut));
  return definition.substr(0, end) + " ";
}

// Hypernyms of a synset with their distance (the shortest path upwards).
std::unordered_map<SynsetOffset, int> ancestors(const WordNet& wn, SynsetOffset start, int max_height) {
  std::unordered_map<SynsetOffset, int> found{{start, 0}};
  std::vector<SynsetOffset> level{start};
  for (int height = 1; height <= max_height && !level.empty(); ++height) {
    std::vector<SynsetOffset> next;
    for (SynsetOffset s : level) {
      for (SynsetOffset h : wn.synset(s).hypernyms) {
        if (found.emplace(h, height).second) next.push_back(h);
      }
    }
    level = std::move(next);
  }
  return found;
}

std::vector<std::string> direct_subtypes(const TypeParents& types, const std::string& parent) {
  std::vector<std::string> out;
  for (const auto& [child, p] : types) {
    if (p == parent) out.push_back(child);
  }
  return out;
}

// The senses of a domain type's name, trying "yo-yo" for "yoyo" and the like.
std::vector<SynsetOffset> senses_of_type(const WordNet& wn, const std::string& type) {
  std::vector<SynsetOffset> senses = wn.senses(type);
  if (!senses.empty() || type.size() < 4) return senses;
  const std::string half = type.substr(0, type.size() / 2);
  if (type.size() % 2 == 0 && half + half == type) return wn.senses(half + "-" + half);
  return senses;
}

struct Anchoring {
  std::vector<SynsetOffset> anchors;
  std::string reason;
};

Anchoring anchor_by_own_lemma(const WordNet& wn, const std::string& type, const std::vector<std::string>& children) {
  const std::vector<SynsetOffset> own = wn.senses(type);
  SynsetOffset best = 0;
  int best_covered = 0;
  for (SynsetOffset sense : own) {
    int covered = 0;
    for (const std::string& child : children) {
      const std::vector<SynsetOffset> child_senses = senses_of_type(wn, child);
      covered += std::any_of(child_senses.begin(), child_senses.end(),
                             [&](SynsetOffset c) { return wn.is_a(c, sense); });
    }
    if (covered > best_covered) best = sense, best_covered = covered;
  }
  if (best_covered > 0) {
    return {{best}, "the sense of '" + type + "' that subsumes " + std::to_string(best_covered) + " of its " +
                        std::to_string(children.size()) + " subtypes"};
  }
  // WordNet files the subtypes elsewhere (a drinking glass is a container),
  // but a name with one meaning needs no disambiguation.
  if (own.size() == 1) return {own, "the only sense of '" + type + "'"};
  return {};
}

Anchoring anchor_by_common_hypernym(const WordNet& wn, const std::vector<std::string>& children, int max_height) {
  std::map<SynsetOffset, std::pair<int, int>> shared;  // ancestor -> (children reaching it, worst height)
  int known = 0;
  for (const std::string& child : children) {
    std::unordered_map<SynsetOffset, int> reach;
    for (SynsetOffset sense : senses_of_type(wn, child)) {
      for (const auto& [a, height] : ancestors(wn, sense, max_height)) {
        auto [it, inserted] = reach.emplace(a, height);
        if (!inserted) it->second = std::min(it->second, height);
      }
    }
    if (reach.empty()) continue;
    ++known;
    for (const auto& [a, height] : reach) {
      auto& entry = shared[a];
      entry.first += 1;
      entry.second = std::max(entry.second, height);
    }
  }
  if (known < 2) return {};
  // The closest common hypernym; between equally close ones, the narrower
  // (fewer kinds below it): publication rather than product for book and
  // magazine.
  SynsetOffset best = 0;
  std::pair<int, std::size_t> best_key{max_height + 1, 0};
  for (const auto& [a, entry] : shared) {
    if (entry.first != known || entry.second == 0) continue;
    const std::pair<int, std::size_t> key{entry.second, wn.hyponym_closure(a, 3).size()};
    if (key < best_key) best = a, best_key = key;
  }
  if (best_key.first > max_height) return {};
  return {{best}, "the lowest common hypernym of its subtypes (" + std::to_string(best_key.first) + " levels up)"};
}

Anchoring find_anchors(const WordNet& wn, const TypeParents& types, const CategoryConfig& category,
                       const AugmentationOptions& options) {
  if (!category.anchors.empty()) {
    Anchoring given{{}, "given in the configuration"};
    for (const std::string& name : category.anchors) {
      const std::optional<SynsetOffset> sense = wn.find_sense(name);
      if (!sense) return {{}, "the configured sense " + name + " is not in WordNet"};
      given.anchors.push_back(*sense);
    }
    return given;
  }
  const std::vector<std::string> children = direct_subtypes(types, category.type);
  if (Anchoring own = anchor_by_own_lemma(wn, category.type, children); !own.anchors.empty()) return own;
  if (Anchoring common = anchor_by_common_hypernym(wn, children, options.max_lcs_height); !common.anchors.empty()) {
    return common;
  }
  return {{}, "no WordNet sense of '" + category.type + "' subsumes its subtypes, and they have no common hypernym"
              " within " + std::to_string(options.max_lcs_height) + " levels; give its senses in the configuration"};
}

struct Candidate {
  SynsetOffset synset = 0;
  int depth = kNotAHyponym;
  std::string rule;
};

// Rules (b) and (c) of the header: a gloss naming the anchor as the genus,
// or stating the anchor's purpose for a thing under the same grandparent.
void add_gloss_candidates(const WordNet& wn, SynsetOffset anchor, std::map<SynsetOffset, Candidate>& found) {
  const std::string lemma = lower(wn.synset(anchor).words.front());
  std::string phrase = lemma;
  std::replace(phrase.begin(), phrase.end(), '_', ' ');
  const std::size_t cut = lemma.find('_');
  const std::string modifier = cut == std::string::npos ? "" : lemma.substr(0, cut);
  const bool states_purpose = modifier.size() > 3 && modifier.compare(modifier.size() - 3, 3, "ing") == 0;
  std::unordered_map<SynsetOffset, int> family = ancestors(wn, anchor, 2);
  family.erase(anchor);
  for (SynsetOffset offset : wn.offsets()) {
    if (offset == anchor || found.count(offset)) continue;
    const NounSynset& s = wn.synset(offset);
    if (s.lexfile != kArtifactFile && s.lexfile != kCommunicationFile) continue;
    const std::string definition = definition_words(s.gloss);
    if (mentions(genus_words(definition), phrase)) {
      found.emplace(offset, Candidate{offset, kNotAHyponym, "its gloss names " + phrase + " as what it is"});
      continue;
    }
    if (!states_purpose || !mentions(definition, modifier)) continue;
    for (const auto& [a, height] : ancestors(wn, offset, 2)) {
      if (height > 0 && family.count(a)) {
        found.emplace(offset, Candidate{offset, kNotAHyponym,
                                        "its gloss says it is for " + modifier + ", and it is a " +
                                            lower(wn.synset(a).words.front()) + " like " + lemma});
        break;
      }
    }
  }
}

std::map<SynsetOffset, Candidate> candidates_of(const WordNet& wn, const std::vector<SynsetOffset>& anchors,
                                                const AugmentationOptions& options) {
  std::map<SynsetOffset, Candidate> found;
  for (SynsetOffset anchor : anchors) {
    for (const auto& [offset, depth] : wn.hyponym_closure(anchor, options.max_depth)) {
      auto [it, inserted] = found.emplace(offset, Candidate{offset, depth, ""});
      if (!inserted && depth < it->second.depth) it->second.depth = depth;
    }
  }
  for (auto& [offset, c] : found) {
    c.rule = "hyponym of " + wn.sense_name(anchors.front()) + " at depth " + std::to_string(c.depth);
  }
  for (SynsetOffset anchor : anchors) add_gloss_candidates(wn, anchor, found);
  return found;
}

// The name a candidate takes as a type, or why it cannot take one.
struct Naming {
  std::string name;
  std::string refusal;
};

Naming name_candidate(const NounSynset& s, const std::set<std::string>& known_bare,
                      const AugmentationOptions& options) {
  for (const std::string& word : s.words) {
    if (known_bare.count(bare(word))) return {"", "already a type (" + type_name(word) + ")"};
  }
  if (s.lexfile != kArtifactFile && s.lexfile != kCommunicationFile) return {"", "not a physical object or document"};
  if (!options.perceivable.empty()) {
    for (const std::string& word : s.words) {
      if (options.perceivable.count(type_name(word))) return {type_name(word), ""};
    }
    return {"", "no recogniser can see it"};
  }
  const std::string first = type_name(s.words.front());
  if (options.single_words_only && first.find('_') != std::string::npos) return {"", "a compound name"};
  return {first, ""};
}

CategoryReport augment_category(const WordNet& wn, const TypeParents& types, const CategoryConfig& category,
                                const AugmentationOptions& options, std::set<std::string>& taken) {
  CategoryReport report;
  report.type = category.type;
  const Anchoring anchoring = find_anchors(wn, types, category, options);
  report.anchor_reason = anchoring.reason;
  for (SynsetOffset a : anchoring.anchors) report.anchors.push_back(wn.sense_name(a));
  if (anchoring.anchors.empty()) return report;

  std::vector<AugmentedType> ranked;
  std::vector<std::pair<std::string, std::string>> refused;
  for (const auto& [offset, candidate] : candidates_of(wn, anchoring.anchors, options)) {
    const NounSynset& s = wn.synset(offset);
    const Naming naming = name_candidate(s, taken, options);
    if (!naming.refusal.empty()) {
      if (wn.tag_count(offset) > 0) refused.emplace_back(type_name(s.words.front()), naming.refusal);
      continue;
    }
    AugmentedType t;
    t.name = naming.name;
    t.parent = category.type;
    t.sense = wn.sense_name(offset);
    t.gloss = s.gloss.substr(0, s.gloss.find(';'));
    t.rule = candidate.rule;
    t.tag_count = wn.tag_count(offset);
    t.polysemy = wn.polysemy(s.words.front());
    ranked.push_back(std::move(t));
  }
  std::stable_sort(ranked.begin(), ranked.end(), [](const AugmentedType& x, const AugmentedType& y) {
    if (x.tag_count != y.tag_count) return x.tag_count > y.tag_count;
    if (x.polysemy != y.polysemy) return x.polysemy > y.polysemy;
    return x.name < y.name;
  });
  for (AugmentedType& t : ranked) {
    if (taken.count(bare(t.name))) continue;
    if (static_cast<int>(report.added.size()) >= options.max_new_per_type) {
      report.passed_over.emplace_back(t.name, "ranked below the " + std::to_string(options.max_new_per_type) +
                                                  " kept (SemCor count " + std::to_string(t.tag_count) + ")");
      continue;
    }
    taken.insert(bare(t.name));
    report.added.push_back(std::move(t));
  }
  std::stable_sort(refused.begin(), refused.end());
  for (auto& r : refused) report.passed_over.push_back(std::move(r));
  return report;
}

}  // namespace

TypeParents type_parents(const pddl::Domain& domain) {
  TypeParents parents;
  for (const pddl::TypeDeclaration& t : domain.types) {
    if (t.name != "object") parents.emplace(t.name, t.parents.empty() ? "object" : t.parents.front());
  }
  return parents;
}

std::vector<AugmentedType> AugmentationResult::added() const {
  std::vector<AugmentedType> all;
  for (const CategoryReport& c : categories) all.insert(all.end(), c.added.begin(), c.added.end());
  return all;
}

AugmentationResult augment_types(const WordNet& wordnet, const TypeParents& domain_types,
                                 const std::vector<CategoryConfig>& categories, const AugmentationOptions& options) {
  std::set<std::string> taken;  // bare names of every type there is
  for (const auto& [child, parent] : domain_types) taken.insert(bare(child)), taken.insert(bare(parent));
  AugmentationResult result;
  for (const CategoryConfig& category : categories) {
    bool known = false;
    for (const auto& [child, parent] : domain_types) known = known || child == category.type;
    if (!known) throw std::invalid_argument("type augmentation: the domain has no type " + category.type);
    result.categories.push_back(augment_category(wordnet, domain_types, category, options, taken));
  }
  return result;
}

std::string augmented_ontology_turtle(const TypeParents& domain_types, const AugmentationResult& result) {
  std::ostringstream out;
  out << "# The type hierarchy of the domain and the types augmented from WordNet 3.0\n"
         "# (written by alplan's type augmentation; see perception/ontology/type_augmentation.h).\n"
         "@prefix rdf:  <http://www.w3.org/1999/02/22-rdf-syntax-ns#> .\n"
         "@prefix rdfs: <http://www.w3.org/2000/01/rdf-schema#> .\n"
         "@prefix owl:  <http://www.w3.org/2002/07/owl#> .\n"
         "@prefix al:   <http://alplan.org/assisted-living#> .\n\n"
         "al:augmented a owl:AnnotationProperty .\nal:wordnetSense a owl:AnnotationProperty .\n\n"
         "al:object a owl:Class .\n";
  for (const auto& [child, parent] : domain_types) {
    out << "al:" << child << " a owl:Class ; rdfs:subClassOf al:" << parent << " .\n";
  }
  out << "\n";
  for (const AugmentedType& t : result.added()) {
    std::string gloss = t.gloss;
    std::replace(gloss.begin(), gloss.end(), '"', '\'');
    out << "al:" << t.name << " a owl:Class ; rdfs:subClassOf al:" << t.parent << " ; al:augmented true ;\n"
        << "  al:wordnetSense \"" << t.sense << "\" ; rdfs:comment \"" << gloss << "\" .\n";
  }
  return out.str();
}

std::vector<CategoryConfig> read_category_config(const std::string& text, const std::string& source_name) {
  std::vector<CategoryConfig> out;
  std::istringstream in(text);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    line = line.substr(0, line.find('#'));
    std::istringstream fields(line);
    CategoryConfig c;
    if (!(fields >> c.type)) continue;
    for (std::string sense; fields >> sense;) {
      if (sense.find(".n.") == std::string::npos) {
        throw std::runtime_error(source_name + ":" + std::to_string(number) + ": expected a WordNet noun sense such"
                                 " as musical_instrument.n.01 after " + c.type + ", found '" + sense + "'");
      }
      c.anchors.push_back(sense);
    }
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace alplan::perception
