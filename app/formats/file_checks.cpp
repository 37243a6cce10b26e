#include "formats/file_checks.h"

#include <charconv>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "meshtrace/io/input_error.h"
#include "meshtrace/io/ply_header.h"
#include "meshtrace/util/quoted.h"

namespace meshtrace::formats {

namespace {
// No list in a mesh file needs more items than a file of 4 GiB has bytes.
constexpr std::int64_t kMaxListLength = std::int64_t{1} << 32;

// Whitespace-separated tokens, with the line each is on.
class Tokens {
 public:
  explicit Tokens(std::string_view text, std::size_t firstLine = 1)
      : text_(text), line_(firstLine) {}

  bool next(std::string_view& token) {
    while (pos_ < text_.size() && isSpace(text_[pos_])) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
    if (pos_ == text_.size()) return false;
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !isSpace(text_[pos_])) ++pos_;
    token = text_.substr(start, pos_ - start);
    return true;
  }
  std::size_t line() const { return line_; }

 private:
  static bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
  }
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_;
};

bool isInteger(std::string_view token, std::int64_t& value) {
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size();
}

bool isNumber(std::string_view token) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size();
}

// ---- PLY ----

class PlyCheck {
 public:
  PlyCheck(const std::filesystem::path& file, std::string_view bytes)
      : file_(file), bytes_(bytes), header_(readPlyHeader(file, bytes, bytes.size())) {}

  ElementCounts run() {
    // OpenMesh's PLY reader adds each face as it reads it, against the
    // vertices read so far: with the faces first it finds none ("face 0
    // refers to vertex 0 of 0"). Say what is wrong instead.
    for (const PlyElement& e : header_.elements) {
      if (e.name == "vertex") break;
      for (const PlyProperty& p : e.properties)
        if (isPlyCornerList(e, p))
          failAt(e.line, "element " + e.name +
                             " comes before element vertex: OpenMesh's PLY reader, which "
                             "reads this file, needs the vertices first");
    }
    const std::string_view body = bytes_.substr(header_.bodyStart);
    if (header_.format == "ascii")
      walkAscii(body);
    else
      walkBinary(body, header_.format == "binary_big_endian");
    ElementCounts counts{header_.vertices, 0};
    for (const PlyElement& e : header_.elements)
      for (const PlyProperty& p : e.properties)
        if (isPlyCornerList(e, p)) counts.faces += e.count;
    return counts;
  }

 private:
  [[noreturn]] void failAt(std::size_t line, const std::string& what) const {
    throw InputError::atLine(file_, line, what);
  }
  [[noreturn]] void fail(const std::string& what) const { throw InputError::inFile(file_, what); }

  void walkAscii(std::string_view body) {
    Tokens tokens(body, header_.lines + 1);
    std::string_view token;
    for (const PlyElement& e : header_.elements) {
      for (std::uint64_t i = 0; i < e.count; ++i) {
        const auto where = [&] { return e.name + " " + std::to_string(i); };
        for (const PlyProperty& p : e.properties) {
          std::int64_t count = 1;
          if (p.countSize) {
            if (!tokens.next(token)) fail("file ends at " + where());
            if (!isInteger(token, count) || count < 0 || count > kMaxListLength)
              failAt(tokens.line(), where() + ": bad list count " + quoted(token));
            checkCorners(e, p, count, where);
          }
          for (std::int64_t k = 0; k < count; ++k) {
            if (!tokens.next(token)) fail("file ends at " + where());
            std::int64_t integer = 0;
            if (p.isFloat ? !isNumber(token) : !isInteger(token, integer))
              failAt(tokens.line(), where() + ": " + p.name + " is " + quoted(token) + ", not " +
                                        (p.isFloat ? "a number" : "an integer"));
          }
        }
      }
    }
  }

  void walkBinary(std::string_view body, bool bigEndian) {
    std::uint64_t pos = 0;
    for (const PlyElement& e : header_.elements) {
      // Records without lists have one size: the element is skipped whole.
      std::uint64_t record = 0;
      bool fixed = true;
      for (const PlyProperty& p : e.properties) {
        record += p.size;
        fixed &= p.countSize == 0;
      }
      if (fixed) {
        if (record > 0 && (body.size() - pos) / record < e.count)
          fail("file ends at " + e.name + " " + std::to_string((body.size() - pos) / record));
        pos += e.count * record;
        continue;
      }
      for (std::uint64_t i = 0; i < e.count; ++i) {
        const auto where = [&] { return e.name + " " + std::to_string(i); };
        for (const PlyProperty& p : e.properties) {
          std::uint64_t count = 1;
          if (p.countSize) {
            if (body.size() - pos < static_cast<std::uint64_t>(p.countSize))
              fail("file ends at " + where());
            count = readCount(body.data() + pos, p.countSize, p.countSigned, bigEndian);
            pos += p.countSize;
            if (count > kMaxListLength)
              fail(where() + ": " + p.name + " lists " +
                   std::to_string(static_cast<std::int64_t>(count)) + " items");
            checkCorners(e, p, static_cast<std::int64_t>(count), where);
          }
          if ((body.size() - pos) / p.size < count) fail("file ends at " + where());
          pos += count * p.size;
        }
      }
    }
  }

  // A list count as read; a negative one of a signed type becomes huge.
  static std::uint64_t readCount(const char* at, int size, bool isSigned, bool bigEndian) {
    if (size == 1 && !isSigned) return static_cast<unsigned char>(*at);  // the usual count
    unsigned char b[8] = {};
    std::memcpy(b, at, size);
    std::uint64_t v = 0;
    for (int k = 0; k < size; ++k) v |= std::uint64_t{b[bigEndian ? size - 1 - k : k]} << (8 * k);
    if (isSigned && size < 8 && (v >> (8 * size - 1)) & 1)
      v |= ~std::uint64_t{0} << (8 * size);  // negative: refused as too long
    return v;
  }

  template <typename Where>
  void checkCorners(const PlyElement& e, const PlyProperty& p, std::int64_t count,
                    const Where& where) const {
    if (!isPlyCornerList(e, p)) return;
    if (count < 3 || static_cast<std::uint64_t>(count) > header_.vertices)
      fail(where() + ": " + p.name + " lists " + std::to_string(count) +
           " corners; a face has 3 to " + std::to_string(header_.vertices) + " (the vertex count)");
  }

  const std::filesystem::path& file_;
  std::string_view bytes_;
  PlyHeader header_;
};

std::uint32_t littleEndian32(const char* at) {
  unsigned char b[4];
  std::memcpy(b, at, 4);
  return std::uint32_t{b[0]} | std::uint32_t{b[1]} << 8 | std::uint32_t{b[2]} << 16 |
         std::uint32_t{b[3]} << 24;
}
}  // namespace

ElementCounts checkPly(const std::filesystem::path& file, std::string_view bytes) {
  return PlyCheck(file, bytes).run();
}

[[noreturn]] void checkOm(const std::filesystem::path& file, std::string_view bytes) {
  // magic "OM", mesh kind, version, then the vertex, face and edge counts.
  if (bytes.size() < 16 || bytes.substr(0, 2) != "OM")
    throw InputError::inFile(file, "not an OM file: no OM header");
  const std::uint64_t vertices = littleEndian32(bytes.data() + 4);
  const std::uint64_t faces = littleEndian32(bytes.data() + 8);
  const std::uint64_t edges = littleEndian32(bytes.data() + 12);
  // At least a float point per vertex, an index per face and per edge.
  if (vertices * 12 + faces * 4 + edges * 4 > bytes.size())
    throw InputError::inFile(file, "header announces " + std::to_string(vertices) + " vertices, " +
                                       std::to_string(faces) + " faces and " +
                                       std::to_string(edges) + " edges, more than a " +
                                       std::to_string(bytes.size()) + "-byte file can hold");
  // OpenMesh's OM reader takes the halfedge and face indices it reads on
  // trust and writes through them: a damaged or crafted file writes out of
  // bounds, and no check short of parsing the whole format ourselves rules
  // that out. Until we read OM ourselves, it is refused.
  throw InputError::inFile(file,
                           "OM files are not read: OpenMesh's OM reader is not safe on a damaged "
                           "file; save the mesh as PLY or OFF");
}

}  // namespace meshtrace::formats
