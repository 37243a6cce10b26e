#pragma once
// The body of a text mesh whose elements stand one to a line, in an order
// its header announces (OFF: the vertices, then the faces; ASCII PLY: its
// elements in the header's order). It streams through text::streamPieces:
// each piece's non-empty lines are found and counted in parallel, numbered
// in order (element k of a piece is element firstElement + k of the file),
// parsed in parallel, and their faces' triangles appended to the mesh in
// file order. The first bad line of the file ends the reading.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <memory>
#include <string_view>
#include <vector>

#include "io/line_pieces.h"
#include "io/mesh_arrays.h"
#include "io/piece_pipeline.h"
#include "io/text.h"
#include "meshtrace/io/input_error.h"
#include "meshtrace/io/memory_budget.h"

namespace meshtrace::text {

struct ElementChunk : mesh_arrays::MeshChunk {
  bool loneCr = false;        // text::hasLoneCr of its lines
  std::int64_t elements = 0;  // its non-empty lines
  std::int64_t firstElement = 0;
  // Its non-empty lines, comments cut, as the count found them: the parse
  // reads these instead of finding the lines a second time.
  struct Line {
    std::uint32_t begin, length;  // in text(); a piece never outgrows the file
    std::uint32_t number;         // counted from the chunk's first line, from 1
  };
  std::vector<Line> nonEmpty;
};

// Reads elements [0, `elements`) from `pieces`; `first` holds the piece
// where the body starts, from its `begin`, and `lineBefore` is the number
// of the header's last line. For each, parseLine(line, element, lineNumber,
// chunk) is called, in parallel across pieces; it throws InputError for a
// bad line and adds a face's triangles to chunk.triangles (and
// chunk.polygons). firstFace(element) is the number of the first face at
// or after `element`, which a piece's polygon records count from. Lines
// after the last element are not read. Returns the elements read (fewer
// than `elements` if the file ends first); throws the first bad line's
// InputError, MemoryLimitError, or InputError for a NUL byte.
template <typename ParseLine, typename FirstFace>
std::int64_t readElementLines(LinePieces& pieces, std::unique_ptr<ElementChunk> first,
                              std::size_t lineBefore, std::int64_t elements, MeshData& mesh,
                              MemoryBudget& budget, const std::filesystem::path& file,
                              ParseLine&& parseLine, FirstFace&& firstFace) {
  std::int64_t numbered = 0;  // elements of the pieces numbered so far
  std::int64_t read = 0;      // elements gathered before the first error
  std::exception_ptr error;
  const auto count = [](ElementChunk& c) {
    const std::string_view text = c.text();
    c.loneCr = hasLoneCr(text);
    LineReader lines(text, c.loneCr);
    std::string_view line;
    c.nonEmpty.clear();
    while (lines.nextNonEmpty(line)) {
      c.nonEmpty.push_back({static_cast<std::uint32_t>(line.data() - text.data()),
                            static_cast<std::uint32_t>(line.size()),
                            static_cast<std::uint32_t>(lines.lineNumber())});
    }
    c.elements = static_cast<std::int64_t>(c.nonEmpty.size());
    c.lines = lines.lineNumber();
  };
  const auto number = [&](ElementChunk& c) {
    c.firstElement = numbered;
    numbered += c.elements;
    c.lineBefore = lineBefore;
    lineBefore += c.lines;
  };
  const auto parse = [&](ElementChunk& c) {
    const std::string_view text = c.text();
    std::int64_t e = c.firstElement;
    for (auto it = c.nonEmpty.begin(); e < elements && it != c.nonEmpty.end(); ++it, ++e) {
      try {
        parseLine(text.substr(it->begin, it->length), e, c.lineBefore + it->number, c);
      } catch (const InputError&) {
        c.error = std::current_exception();
        return;
      }
    }
  };
  // In file order: the first error ends the reading.
  const auto gather = [&](ElementChunk& c, std::atomic<bool>& done) {
    const auto stop = [&](std::exception_ptr e) {
      error = e;
      done = true;
    };
    if (!done) {
      if (c.error) {
        stop(c.error);
      } else {
        read = std::min(c.firstElement + c.elements, elements);
        try {
          const std::int64_t face = firstFace(c.firstElement);
          mesh_arrays::appendTriangles(mesh, budget, c, static_cast<std::uint32_t>(face), file);
          if (c.piece.nulAfter())
            stop(std::make_exception_ptr(
                InputError::atLine(file, c.lineBefore + c.lines + 1, kNulByteMessage)));
        } catch (const MemoryLimitError&) {
          stop(std::current_exception());
        }
      }
    }
    c.triangles.clear();
    c.polygons.clear();
    c.error = nullptr;
  };
  streamPieces(pieces, std::move(first), count, number, parse, gather);
  if (error) std::rethrow_exception(error);
  return read;
}

}  // namespace meshtrace::text
