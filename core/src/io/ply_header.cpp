#include "meshtrace/io/ply_header.h"

#include "io/text.h"
#include "meshtrace/io/input_error.h"
#include "meshtrace/util/quoted.h"

namespace meshtrace {

namespace {
// Bytes of a PLY scalar type, 0 if unknown; whether it is a floating-point
// or a signed integer type.
int plyTypeSize(std::string_view type, bool& isFloat, bool& isSigned) {
  isFloat = type == "float" || type == "float32" || type == "double" || type == "float64";
  isSigned = type == "char" || type == "short" || type == "int" || type == "int8" ||
             type == "int16" || type == "int32";
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" ||
      type == "float32")
    return 4;
  if (type == "double" || type == "float64") return 8;
  return 0;
}

class HeaderReader {
 public:
  HeaderReader(const std::filesystem::path& file, std::string_view bytes)
      : file_(file), bytes_(bytes.substr(0, kMaxPlyHeaderBytes)) {}

  PlyHeader read() {
    findEnd();
    std::size_t line = 0, pos = 0;
    while (pos < header_.bodyStart) {
      std::size_t eol = bytes_.find('\n', pos);
      std::string_view text = bytes_.substr(pos, eol - pos);
      pos = eol + 1;
      ++line;
      if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
      if (text.find('\0') != std::string_view::npos) failAt(line, "a NUL byte in the header");
      readLine(text, line);
    }
    if (header_.format.empty()) fail("the header has no format line");
    bool vertices = false;
    for (const PlyElement& e : header_.elements) vertices |= e.name == "vertex";
    if (!vertices) fail("the header has no vertex element");
    header_.lines = line;
    return std::move(header_);
  }

 private:
  [[noreturn]] void failAt(std::size_t line, const std::string& what) const {
    throw InputError::atLine(file_, line, what);
  }
  [[noreturn]] void fail(const std::string& what) const { throw InputError::inFile(file_, what); }

  // The header ends at a line that is end_header and nothing else (as
  // OpenMesh's reader reads it); the text may occur inside other lines.
  void findEnd() {
    for (std::size_t at = 0; at < bytes_.size();) {
      const std::size_t eol = bytes_.find('\n', at);
      if (eol == std::string_view::npos) break;
      std::string_view text = bytes_.substr(at, eol - at);
      if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
      at = eol + 1;
      if (text == "end_header") {
        header_.bodyStart = at;
        return;
      }
    }
    fail("no end_header line in the first " + std::to_string(kMaxPlyHeaderBytes) +
         " bytes: not a PLY header");
  }

  void readLine(std::string_view text, std::size_t line) {
    text::TokenReader words(text);
    std::string_view keyword;
    if (!words.next(keyword)) return;
    if (line == 1) {
      if (keyword != "ply") failAt(line, "not a PLY file: it must start with 'ply'");
      return;
    }
    std::vector<std::string_view> args;
    for (std::string_view w; words.next(w);) args.push_back(w);
    if (keyword == "comment" || keyword == "obj_info" || keyword == "end_header") return;
    if (keyword == "format") {
      if (args.size() != 2 || args[1] != "1.0" ||
          (args[0] != "ascii" && args[0] != "binary_little_endian" &&
           args[0] != "binary_big_endian"))
        failAt(line,
               "format must be ascii, binary_little_endian or binary_big_endian, "
               "version 1.0");
      header_.format = args[0];
    } else if (keyword == "element") {
      std::int64_t count = 0;
      if (args.size() != 2 || !text::parseInt64(args[1], count) || count < 0)
        failAt(line, "element needs a name and a count of 0 or more");
      header_.elements.push_back(
          {std::string(args[0]), static_cast<std::uint64_t>(count), {}, line});
    } else if (keyword == "property") {
      if (header_.elements.empty()) failAt(line, "a property before any element");
      header_.elements.back().properties.push_back(readProperty(args, line));
    } else {
      failAt(line, "unknown header keyword " + quoted(keyword));
    }
  }

  PlyProperty readProperty(const std::vector<std::string_view>& args, std::size_t line) const {
    PlyProperty p;
    if (args.size() == 4 && args[0] == "list") {
      bool countIsFloat = false;
      p.countSize = plyTypeSize(args[1], countIsFloat, p.countSigned);
      p.size = plyTypeSize(args[2], p.isFloat, p.isSigned);
      p.name = args[3];
      if (p.countSize == 0 || countIsFloat || p.size == 0)
        failAt(line, "a list needs an integer count type and a known item type");
    } else if (args.size() == 2) {
      p.size = plyTypeSize(args[0], p.isFloat, p.isSigned);
      p.name = args[1];
      if (p.size == 0) failAt(line, "unknown property type " + quoted(args[0]));
    } else {
      failAt(line, "property needs a type and a name (or list, two types and a name)");
    }
    return p;
  }

  const std::filesystem::path& file_;
  std::string_view bytes_;
  PlyHeader header_;
};

// A vertex element with x, y and z, a face element with one list; the
// counts against what the file's bytes can hold.
void checkElements(const std::filesystem::path& file, PlyHeader& header, std::uint64_t fileSize) {
  const bool ascii = header.format == "ascii";
  std::uint64_t minimum = 0;
  for (const PlyElement& e : header.elements) {
    std::uint64_t each = 0;
    for (const PlyProperty& p : e.properties) {
      // ASCII: a digit and a space per value; binary: the value's bytes.
      each += ascii ? 2 : (p.countSize ? p.countSize : p.size);
      if (isPlyCornerList(e, p)) each += 3 * (ascii ? 2 : p.size);
    }
    if (each > 0 && e.count > (fileSize - minimum) / each)
      throw InputError::atLine(file, e.line,
                               "element " + e.name + " announces " + std::to_string(e.count) +
                                   ", more than a " + std::to_string(fileSize) +
                                   "-byte file can hold");
    minimum += e.count * each;
    if (e.name == "vertex") {
      header.vertices = e.count;
      for (const char* axis : {"x", "y", "z"}) {
        bool found = false;
        for (const PlyProperty& p : e.properties) found |= p.name == axis && !p.countSize;
        if (!found)
          throw InputError::atLine(file, e.line,
                                   std::string("the vertex element has no property ") + axis);
      }
    }
    if (e.name == "face") {
      bool found = false;
      for (const PlyProperty& p : e.properties) found |= isPlyCornerList(e, p);
      if (!found)
        throw InputError::atLine(file, e.line,
                                 "the face element has no list vertex_indices (or vertex_index)");
    }
  }
}
}  // namespace

PlyHeader readPlyHeader(const std::filesystem::path& file, std::string_view bytes,
                        std::uint64_t fileSize) {
  PlyHeader header = HeaderReader(file, bytes).read();
  checkElements(file, header, fileSize);
  return header;
}

bool isPlyCornerList(const PlyElement& e, const PlyProperty& p) {
  return e.name == "face" && p.countSize != 0 &&
         (p.name == "vertex_indices" || p.name == "vertex_index");
}

}  // namespace meshtrace
