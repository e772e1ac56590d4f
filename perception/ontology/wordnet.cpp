#include "perception/ontology/wordnet.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <deque>
#include <fstream>
#include <set>
#include <sstream>
#include <unordered_set>

namespace alplan::perception {
namespace {

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

[[noreturn]] void fail(const std::filesystem::path& file, std::size_t line, const std::string& what) {
  throw WordNetError(file.string() + ":" + std::to_string(line) + ": " + what);
}

// Reads whitespace-separated fields of one database line, reporting where a
// field is missing or malformed.
class FieldReader {
 public:
  FieldReader(const std::string& text, const std::filesystem::path& file, std::size_t line)
      : in_(text), file_(file), line_(line) {}

  std::string word(const char* what) {
    std::string field;
    if (!(in_ >> field)) fail(file_, line_, std::string("expected ") + what + ", found the end of the line");
    return field;
  }
  long number(const char* what, int base) {
    const std::string field = word(what);
    long value = 0;
    const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value, base);
    if (error != std::errc() || end != field.data() + field.size() || value < 0) {
      fail(file_, line_, std::string("expected ") + what + ", found '" + field + "'");
    }
    return value;
  }

 private:
  std::istringstream in_;
  const std::filesystem::path& file_;
  std::size_t line_;
};

std::ifstream open(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw WordNetError(file.string() + ": cannot open (is Debian's wordnet-base installed?)");
  return in;
}

NounSynset parse_synset_line(const std::string& line, const std::filesystem::path& file, std::size_t number) {
  const std::size_t bar = line.find(" | ");
  FieldReader fields(line.substr(0, bar), file, number);
  NounSynset s;
  s.offset = static_cast<SynsetOffset>(fields.number("a synset offset", 10));
  s.lexfile = static_cast<int>(fields.number("a lexicographer file number", 10));
  if (fields.word("the synset type") != "n") fail(file, number, "expected a noun synset (type n)");
  const long words = fields.number("a word count (hex)", 16);
  for (long w = 0; w < words; ++w) {
    s.words.push_back(fields.word("a word"));
    s.lex_ids.push_back(static_cast<int>(fields.number("a lex_id (hex)", 16)));
  }
  const long pointers = fields.number("a pointer count", 10);
  for (long p = 0; p < pointers; ++p) {
    const std::string symbol = fields.word("a pointer symbol");
    const auto target = static_cast<SynsetOffset>(fields.number("a pointer's synset offset", 10));
    const std::string pos = fields.word("a pointer's part of speech");
    fields.word("a pointer's source/target");
    if (pos != "n") continue;
    if (symbol == "@" || symbol == "@i") s.hypernyms.push_back(target);
    if (symbol == "~") s.hyponyms.push_back(target);
    if (symbol == "~i") s.instances.push_back(target);
  }
  if (bar != std::string::npos) {
    s.gloss = line.substr(bar + 3);
    while (!s.gloss.empty() && std::isspace(static_cast<unsigned char>(s.gloss.back()))) s.gloss.pop_back();
  }
  return s;
}

}  // namespace

std::string wordnet_lemma(std::string_view text) {
  std::string out = lower(text);
  std::replace(out.begin(), out.end(), ' ', '_');
  return out;
}

WordNet WordNet::load_nouns(const std::filesystem::path& dir) {
  WordNet wn;
  {
    const std::filesystem::path file = dir / "data.noun";
    std::ifstream in = open(file);
    std::string line;
    for (std::size_t number = 1; std::getline(in, line); ++number) {
      if (line.empty() || line[0] == ' ') continue;  // the licence header
      NounSynset s = parse_synset_line(line, file, number);
      const SynsetOffset offset = s.offset;
      if (!wn.synsets_.emplace(offset, std::move(s)).second) {
        fail(file, number, "synset offset " + std::to_string(offset) + " appears twice");
      }
      wn.offsets_.push_back(offset);
    }
    if (wn.synsets_.empty()) throw WordNetError(file.string() + ": no synsets");
    std::sort(wn.offsets_.begin(), wn.offsets_.end());
  }
  {
    const std::filesystem::path file = dir / "index.noun";
    std::ifstream in = open(file);
    std::string line;
    for (std::size_t number = 1; std::getline(in, line); ++number) {
      if (line.empty() || line[0] == ' ') continue;
      FieldReader fields(line, file, number);
      const std::string lemma = fields.word("a lemma");
      fields.word("a part of speech");
      const long synsets = fields.number("a synset count", 10);
      const long pointer_kinds = fields.number("a pointer count", 10);
      for (long p = 0; p < pointer_kinds; ++p) fields.word("a pointer symbol");
      fields.number("a sense count", 10);
      fields.number("a tagged sense count", 10);
      std::vector<SynsetOffset>& offsets = wn.index_[lemma];
      for (long k = 0; k < synsets; ++k) {
        offsets.push_back(static_cast<SynsetOffset>(fields.number("a synset offset", 10)));
      }
    }
  }
  const std::filesystem::path counts = dir / "cntlist.rev";
  if (std::filesystem::exists(counts)) {
    std::ifstream in = open(counts);
    std::string line;
    for (std::size_t number = 1; std::getline(in, line); ++number) {
      if (line.empty()) continue;
      FieldReader fields(line, counts, number);
      const std::string key = fields.word("a sense key");
      fields.number("a sense number", 10);
      wn.sense_tag_counts_[key] = static_cast<int>(fields.number("a tag count", 10));
    }
  }
  return wn;
}

const NounSynset& WordNet::synset(SynsetOffset offset) const {
  const auto it = synsets_.find(offset);
  if (it == synsets_.end()) throw WordNetError("WordNet has no noun synset at offset " + std::to_string(offset));
  return it->second;
}

std::vector<SynsetOffset> WordNet::senses(std::string_view lemma) const {
  const auto it = index_.find(wordnet_lemma(lemma));
  return it == index_.end() ? std::vector<SynsetOffset>{} : it->second;
}

std::optional<SynsetOffset> WordNet::find_sense(std::string_view sense_name) const {
  const std::string name(sense_name);
  const std::size_t n = name.rfind(".n.");
  if (n == std::string::npos) return std::nullopt;
  int number = 0;
  const auto [end, error] = std::from_chars(name.data() + n + 3, name.data() + name.size(), number);
  if (error != std::errc() || end != name.data() + name.size() || number < 1) return std::nullopt;
  const std::vector<SynsetOffset> all = senses(name.substr(0, n));
  if (static_cast<std::size_t>(number) > all.size()) return std::nullopt;
  return all[static_cast<std::size_t>(number) - 1];
}

std::string WordNet::sense_name(SynsetOffset offset) const {
  const NounSynset& s = synset(offset);
  const std::string lemma = lower(s.words.front());
  const std::vector<SynsetOffset> all = senses(lemma);
  const auto it = std::find(all.begin(), all.end(), offset);
  const int number = it == all.end() ? 0 : static_cast<int>(it - all.begin()) + 1;
  return lemma + ".n." + (number < 10 ? "0" : "") + std::to_string(number);
}

int WordNet::tag_count(SynsetOffset offset) const {
  const NounSynset& s = synset(offset);
  int total = 0;
  for (std::size_t w = 0; w < s.words.size(); ++w) {
    const auto two_digits = [](int n) { return (n < 10 ? "0" : "") + std::to_string(n); };
    const std::string key_tail = "%1:" + two_digits(s.lexfile) + ":" + two_digits(s.lex_ids[w]) + "::";
    std::string word = lower(s.words[w]);
    // Adjective markers such as "(p)" are not part of a sense key.
    if (const std::size_t paren = word.find('('); paren != std::string::npos) word.resize(paren);
    const auto it = sense_tag_counts_.find(word + key_tail);
    if (it != sense_tag_counts_.end()) total += it->second;
  }
  return total;
}

int WordNet::polysemy(std::string_view lemma) const { return static_cast<int>(senses(lemma).size()); }

bool WordNet::is_a(SynsetOffset start, SynsetOffset ancestor) const {
  std::unordered_set<SynsetOffset> seen;
  std::vector<SynsetOffset> todo{start};
  while (!todo.empty()) {
    const SynsetOffset s = todo.back();
    todo.pop_back();
    if (s == ancestor) return true;
    if (!seen.insert(s).second || !has(s)) continue;
    for (SynsetOffset h : synset(s).hypernyms) todo.push_back(h);
  }
  return false;
}

std::vector<std::pair<SynsetOffset, int>> WordNet::hyponym_closure(SynsetOffset root, int max_depth) const {
  std::vector<std::pair<SynsetOffset, int>> out;
  std::unordered_set<SynsetOffset> seen{root};
  std::deque<std::pair<SynsetOffset, int>> queue{{root, 0}};
  while (!queue.empty()) {
    const auto [s, depth] = queue.front();
    queue.pop_front();
    if (depth == max_depth || !has(s)) continue;
    for (SynsetOffset h : synset(s).hyponyms) {
      if (!seen.insert(h).second) continue;
      out.emplace_back(h, depth + 1);
      queue.emplace_back(h, depth + 1);
    }
  }
  return out;
}

}  // namespace alplan::perception
