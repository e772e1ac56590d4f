#include "cli/perceive_common.h"

#include <iostream>
#include <map>
#include <new>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/commands.h"

namespace alplan::cli {

namespace {

// Messages that already say "file:line:col: error: ..." are printed as they
// are; the others get the "error: " prefix.
std::string as_error(const std::string& what) {
  return what.find(": error: ") != std::string::npos ? what : "error: " + what;
}

}  // namespace

int guarded(const std::function<int()>& command, const std::string& context) {
  try {
    return command();
  } catch (const std::bad_alloc&) {
    std::cerr << "error: out of memory" << (context.empty() ? "" : " working on " + context) << "\n";
    return kExitLimit;
  } catch (const std::invalid_argument& e) {
    std::cerr << as_error(e.what()) << "\n";
    return kExitInputError;
  } catch (const std::runtime_error& e) {
    std::cerr << as_error(e.what()) << "\n";
    return kExitInputError;
  } catch (const std::exception& e) {
    std::cerr << "internal error" << (context.empty() ? "" : " on " + context) << ": " << e.what() << "\n";
    return kExitInternalError;
  }
}

void print_ontology(const perception::TypeParents& types, const perception::AugmentationResult& result, bool explain,
                    bool json) {
  std::map<std::string, std::vector<std::string>> children;
  for (const auto& [child, parent] : types) children[parent].push_back(child);
  for (const perception::AugmentedType& t : result.added()) children[t.parent].push_back("+" + t.name);
  if (json) {
    nlohmann::json out = {{"subtypes", nlohmann::json::object()}, {"augmented", nlohmann::json::array()},
                          {"categories", nlohmann::json::array()}};
    for (const auto& [parent, kids] : children) {
      for (const std::string& k : kids) out["subtypes"][parent].push_back(k[0] == '+' ? k.substr(1) : k);
    }
    for (const perception::AugmentedType& t : result.added()) {
      out["augmented"].push_back({{"type", t.name}, {"parent", t.parent}, {"sense", t.sense}, {"gloss", t.gloss},
                                  {"rule", t.rule}, {"semcor_count", t.tag_count}});
    }
    for (const perception::CategoryReport& c : result.categories) {
      out["categories"].push_back({{"type", c.type}, {"anchors", c.anchors}, {"anchor_reason", c.anchor_reason}});
    }
    std::cout << out.dump(2) << "\n";
    return;
  }
  for (const auto& [parent, kids] : children) {
    std::cout << parent << " ->";
    for (std::size_t i = 0; i < kids.size(); ++i) std::cout << (i ? ", " : " ") << kids[i];
    std::cout << "\n";
  }
  std::cout << "(+ added from WordNet 3.0)\n";
  if (!explain) return;
  for (const perception::CategoryReport& c : result.categories) {
    std::cout << "\n" << c.type << ": anchored at";
    for (const std::string& a : c.anchors) std::cout << " " << a;
    std::cout << (c.anchors.empty() ? " nothing" : "") << " (" << c.anchor_reason << ")\n";
    for (const perception::AugmentedType& t : c.added) {
      std::cout << "  + " << t.name << " (" << t.sense << ", SemCor " << t.tag_count << "): " << t.rule << "; \""
                << t.gloss << "\"\n";
    }
    for (std::size_t i = 0; i < c.passed_over.size() && i < 5; ++i) {
      std::cout << "  - " << c.passed_over[i].first << ": " << c.passed_over[i].second << "\n";
    }
  }
}

}  // namespace alplan::cli
