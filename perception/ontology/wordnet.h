// A read-only view of the noun part of WordNet 3.0 (Princeton), as Debian's
// `wordnet-base` installs it in /usr/share/wordnet: data.noun (synsets, their
// words, pointers and glosses), index.noun (lemma -> synsets in sense order)
// and cntlist.rev (how often each sense was tagged in the SemCor corpus). The
// file formats are WordNet's wndb(5WN) and cntlist(5WN).
//
// This is the lexical knowledge base the type augmentation walks (the paper's
// Section 6.2 and its Fig. 5): hyponyms of a domain type's concept are
// candidate new object types.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace alplan::perception {

class WordNetError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

using SynsetOffset = std::uint32_t;

struct NounSynset {
  SynsetOffset offset = 0;
  int lexfile = 0;                 // 6 = noun.artifact, 10 = noun.communication, ...
  std::vector<std::string> words;  // as written in the database, '_' for spaces
  std::vector<int> lex_ids;        // one per word; part of each sense key
  std::vector<SynsetOffset> hypernyms;  // '@' and '@i' pointers
  std::vector<SynsetOffset> hyponyms;   // '~' pointers: kinds of this
  std::vector<SynsetOffset> instances;  // '~i' pointers: individuals (Utopia is an instance of book)
  std::string gloss;
};

class WordNet {
 public:
  // Reads data.noun, index.noun and (if present) cntlist.rev from `dir`.
  // Throws WordNetError naming the file and line on malformed input.
  static WordNet load_nouns(const std::filesystem::path& dir = "/usr/share/wordnet");

  std::size_t synset_count() const { return synsets_.size(); }
  // Throws WordNetError for an offset the database does not have.
  const NounSynset& synset(SynsetOffset offset) const;
  bool has(SynsetOffset offset) const { return synsets_.count(offset) != 0; }
  // Every synset's offset, ascending (the database's order).
  const std::vector<SynsetOffset>& offsets() const { return offsets_; }

  // The synsets of a lemma in WordNet's sense order (most frequent first);
  // case-insensitive, spaces or '_' between words.
  std::vector<SynsetOffset> senses(std::string_view lemma) const;
  // "musical_instrument.n.01" -> its synset; nothing if there is no such sense.
  std::optional<SynsetOffset> find_sense(std::string_view sense_name) const;
  // The conventional name of a synset after its first word: "cup.n.01".
  std::string sense_name(SynsetOffset offset) const;

  // Times the synset's senses were tagged in SemCor (sum over its words):
  // WordNet's own measure of how common a meaning is.
  int tag_count(SynsetOffset offset) const;
  // Number of senses of a lemma: WordNet's familiarity measure (`wn -famln`).
  int polysemy(std::string_view lemma) const;

  // True when `ancestor` is the synset itself or one of its hypernyms.
  bool is_a(SynsetOffset synset, SynsetOffset ancestor) const;
  // Hyponyms down to `max_depth` levels, each with its depth (1 = direct),
  // in a deterministic order (breadth first, database order within a level).
  std::vector<std::pair<SynsetOffset, int>> hyponym_closure(SynsetOffset root, int max_depth) const;

 private:
  std::unordered_map<SynsetOffset, NounSynset> synsets_;
  std::vector<SynsetOffset> offsets_;
  std::unordered_map<std::string, std::vector<SynsetOffset>> index_;
  std::unordered_map<std::string, int> sense_tag_counts_;  // by sense key
};

// "Musical Instrument" / "musical-instrument" -> "musical_instrument".
std::string wordnet_lemma(std::string_view text);

}  // namespace alplan::perception
