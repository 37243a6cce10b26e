#include "io/stl_ascii_reader.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <exception>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "io/corner_welder.h"
#include "io/element_problems.h"
#include "io/line_pieces.h"
#include "io/mesh_arrays.h"
#include "io/piece_pipeline.h"
#include "io/text.h"
#include "meshtrace/io/input_error.h"
#include "meshtrace/util/quoted.h"

namespace meshtrace {

namespace {
// The fewest bytes an ASCII facet takes ("facet normal 0 0 0 outer loop",
// three "vertex 0 0 0", "endloop endfacet"), to size the arrays at first.
constexpr std::uint64_t kMinFacetBytes = 80;

// The words of the grammar. A word that reads as a number is a Number
// whatever its place; any other word is Other.
enum class Word : std::uint8_t {
  Number,
  Solid,
  EndSolid,
  Facet,
  Normal,
  Outer,
  Loop,
  Vertex,
  EndLoop,
  EndFacet,
  Other
};
// The keywords' spelling, in Word's order from Solid.
constexpr std::array<std::string_view, 9> kKeywords = {
    "solid", "endsolid", "facet", "normal", "outer", "loop", "vertex", "endloop", "endfacet"};

Word wordOf(std::string_view text) {
  for (std::size_t k = 0; k < kKeywords.size(); ++k)
    if (text == kKeywords[k]) return static_cast<Word>(k + 1);
  return Word::Other;
}
std::string spelling(Word word) {
  return std::string(kKeywords[static_cast<std::size_t>(word) - 1]);
}

struct StlChunk : text::PieceChunk {  // no header shares the first piece: begin is 0
  std::vector<Word> words;
  std::vector<double> numbers;  // the Number words' values, in order
};

// Calls visit(word, value, text, line) for the words of `text` in order,
// `value` a Number's, `line` counted from 1, until it returns false. A
// solid's name (the rest of the line after solid or endsolid) is not a
// word of the grammar and is not read. Returns the lines of `text`.
template <typename Visit>
std::size_t forEachWord(std::string_view text, Visit&& visit) {
  text::LineReader lines(text);
  std::string_view line;
  while (lines.nextNonEmpty(line)) {
    text::TokenReader words(line);
    std::string_view spelt;
    double value = 0.0;
    for (;;) {
      // Most words are keywords or numbers; a letter tells which is tried
      // first ("inf" and "nan" are numbers too).
      const char first = words.peek();
      if (first == '\0') break;
      Word word = Word::Other;
      if (const char lower = static_cast<char>(first | 0x20); lower >= 'a' && lower <= 'z') {
        words.next(spelt);
        word = wordOf(spelt);
        if (word == Word::Other && text::parseDouble(spelt, value)) word = Word::Number;
      } else if (words.nextDouble(value, spelt) == text::NumberToken::Read) {
        word = Word::Number;
      }
      if (!visit(word, value, spelt, lines.lineNumber())) return lines.lineNumber();
      if (word == Word::Solid || word == Word::EndSolid) break;
    }
  }
  return lines.lineNumber();
}

// The parallel stage: the chunk's words, numbers parsed.
void findWords(StlChunk& chunk) {
  chunk.words.clear();
  chunk.numbers.clear();
  chunk.lines =
      forEachWord(chunk.text(), [&](Word word, double value, std::string_view, std::size_t) {
        chunk.words.push_back(word);
        if (word == Word::Number) chunk.numbers.push_back(value);
        return true;
      });
}

// Word `index` of the chunk as the file spells it, and its line: found
// again for a message rather than kept for every word.
struct Spelt {
  std::string_view text;
  std::size_t line = 0;
};
Spelt findWord(const StlChunk& chunk, std::size_t index) {
  Spelt found;
  std::size_t at = 0;
  forEachWord(chunk.text(), [&](Word, double, std::string_view text, std::size_t line) {
    if (at++ < index) return true;
    found = {text, chunk.lineBefore + line};
    return false;
  });
  return found;
}

// A facet's words in order. Steps 8-10, 12-14 and 16-18 are its corners'
// coordinates; the normal's numbers are checked and not kept.
constexpr std::array<Word, 21> kFacetWords = {
    Word::Facet,  Word::Normal,  Word::Number,  Word::Number, Word::Number, Word::Outer,
    Word::Loop,   Word::Vertex,  Word::Number,  Word::Number, Word::Number, Word::Vertex,
    Word::Number, Word::Number,  Word::Number,  Word::Vertex, Word::Number, Word::Number,
    Word::Number, Word::EndLoop, Word::EndFacet};
constexpr std::size_t kFirstCoordinateStep = 8;
constexpr std::size_t kFacetNumbers = 12;

// The grammar, fed the file's words in order. The corners of the facets it
// reads are welded into the mesh a batch at a time (weldFacets).
class Grammar {
 public:
  Grammar(const std::filesystem::path& file, CornerWelder& welder) : file_(file), welder_(welder) {}

  // The next word, `value` a Number's; throws InputError if it is out of
  // place, naming it as spelt() finds it: the spelling and the line.
  template <typename Spell>
  void take(Word word, double value, Spell&& spelt) {
    switch (place_) {
      case Place::BeforeFirstSolid:
        if (word != Word::Solid) throw notStl();
        place_ = Place::BetweenFacets;
        return;
      case Place::AfterSolid:
        if (word != Word::Solid) throw misplaced("expected solid after endsolid", spelt());
        place_ = Place::BetweenFacets;
        return;
      case Place::BetweenFacets:
        if (word == Word::EndSolid) {
          place_ = Place::AfterSolid;
          return;
        }
        if (word != Word::Facet) throw misplaced("expected facet or endsolid", spelt());
        place_ = Place::InFacet;
        step_ = 1;
        return;
      case Place::InFacet: takeInFacet(word, value, spelt); return;
    }
  }

  // Takes the whole, well-formed facets at the start of words[0, count)
  // (their Numbers' values from `numbers` on), as take() would one word at
  // a time, and returns the words taken: the common case, without a
  // grammar step per word. Anything else is left to take().
  std::size_t takeWholeFacets(const Word* words, std::size_t count, const double*& numbers) {
    std::size_t taken = 0;
    while (place_ == Place::BetweenFacets && count - taken >= kFacetWords.size() &&
           std::equal(kFacetWords.begin(), kFacetWords.end(), words + taken)) {
      const double* coordinates = numbers + 3;  // after the normal's
      for (int k = 0; k < 9; ++k)
        if (!std::isfinite(coordinates[k])) return taken;  // take() names it
      for (int c = 0; c < 3; ++c)
        corners_.emplace_back(coordinates[3 * c], coordinates[3 * c + 1], coordinates[3 * c + 2]);
      numbers += kFacetNumbers;
      taken += kFacetWords.size();
      ++facet_;
    }
    return taken;
  }

  // Welds the corners of the facets read since the last call.
  void weldFacets() {
    welder_.addFacets(corners_, facet_ - corners_.size() / 3);
    corners_.clear();
  }

  // The file ended after the words taken.
  void end() const {
    switch (place_) {
      case Place::BeforeFirstSolid: throw notStl();
      case Place::BetweenFacets:
        throw InputError::inFile(
            file_, "file ends after facet " + std::to_string(facet_) + ": no endsolid");
      case Place::InFacet: throw InputError::inFile(file_, "file ends in " + where());
      case Place::AfterSolid: return;
    }
  }

  // A NUL byte on line `line`, after the words taken.
  [[noreturn]] void nulByte(std::size_t line) const {
    if (place_ == Place::BeforeFirstSolid) throw notStl();
    throw InputError::atLine(file_, line, text::kNulByteMessage);
  }

 private:
  enum class Place { BeforeFirstSolid, BetweenFacets, InFacet, AfterSolid };

  template <typename Spell>
  void takeInFacet(Word word, double value, Spell&& spelt) {
    const Word wanted = kFacetWords[step_];
    if (wanted == Word::Number) {
      if (word != Word::Number) {
        const Spelt s = spelt();
        throw InputError::atLine(file_, s.line,
                                 where() + ": " + quoted(s.text) + " is not a number");
      }
      if (step_ >= kFirstCoordinateStep) {
        const std::size_t corner = (step_ - kFirstCoordinateStep) / 4;
        if (!std::isfinite(value)) {
          const Spelt s = spelt();
          throw InputError::atLine(file_, s.line,
                                   where() + ": vertex " + std::to_string(corner) +
                                       element_problems::nonFiniteCoordinate(s.text));
        }
        facetCorners_[corner][(step_ - kFirstCoordinateStep) % 4] = value;
      }
    } else if (word != wanted) {
      const std::string context =
          wanted == Word::EndLoop ? where() + " (a facet has three vertices)" : where();
      throw misplaced(context + ": expected " + spelling(wanted), spelt());
    }
    if (++step_ < kFacetWords.size()) return;
    corners_.insert(corners_.end(), std::begin(facetCorners_), std::end(facetCorners_));
    ++facet_;
    place_ = Place::BetweenFacets;
  }

  std::string where() const { return "facet " + std::to_string(facet_); }
  InputError misplaced(const std::string& expected, const Spelt& found) const {
    return InputError::atLine(file_, found.line, expected + ", found " + quoted(found.text));
  }
  InputError notStl() const {
    return InputError::inFile(file_,
                              "neither a binary STL (its size does not match the triangle "
                              "count at byte 80) nor an ASCII one (it must start with solid)");
  }

  const std::filesystem::path& file_;
  CornerWelder& welder_;
  Place place_ = Place::BeforeFirstSolid;
  std::size_t step_ = 0;  // of kFacetWords, in a facet
  std::uint64_t facet_ = 0;
  Vec3 facetCorners_[3];
  std::vector<Vec3> corners_;  // of the facets read since the last weldFacets
};
}  // namespace

MeshData readAsciiStl(text::FileSource& source, MemoryBudget& budget) {
  const std::filesystem::path file = source.file();
  MeshData mesh;
  const std::uint64_t facets = source.size() / kMinFacetBytes;
  mesh_arrays::growTriangles(mesh, budget, static_cast<std::size_t>(facets / 4 + 1), file);
  CornerWelder welder(mesh, budget, file, static_cast<std::size_t>(facets / 8 + 3));
  Grammar grammar(file, welder);

  std::size_t lineBefore = 0;
  const auto number = [&](StlChunk& c) {
    c.lineBefore = lineBefore;
    lineBefore += c.lines;
  };
  std::exception_ptr error;
  // In file order: the first bad word ends the reading.
  const auto gather = [&](StlChunk& c, std::atomic<bool>& done) {
    if (!done) {
      try {
        const double* value = c.numbers.data();
        const std::size_t words = c.words.size();
        for (std::size_t w = 0; w < words; ++w) {
          w += grammar.takeWholeFacets(c.words.data() + w, words - w, value);
          if (w == words) break;
          const Word word = c.words[w];
          grammar.take(word, word == Word::Number ? *value++ : 0.0, [&] { return findWord(c, w); });
        }
        grammar.weldFacets();
        if (c.piece.nulAfter()) grammar.nulByte(c.lineBefore + c.lines + 1);
      } catch (const InputError&) {
        error = std::current_exception();
        done = true;
      } catch (const MemoryLimitError&) {
        error = std::current_exception();
        done = true;
      }
    }
  };
  text::LinePieces pieces(source, text::kPieceBytes);
  // Finding a piece's words counts its lines, all that numbering needs, and
  // leaves nothing for a parse stage.
  text::streamPieces(
      pieces, std::unique_ptr<StlChunk>(), findWords, number, [](StlChunk&) {}, gather);
  if (error) std::rethrow_exception(error);
  grammar.end();
  return mesh;
}

}  // namespace meshtrace
