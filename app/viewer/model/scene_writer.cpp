#include "viewer/model/scene_writer.h"

#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "meshtrace/io/output_file.h"
#include "meshtrace/io/scene_parser.h"
#include "viewer/model/save_target.h"

namespace meshtrace::viewer {

namespace {
struct Token {
  std::size_t begin, end;
};

// Whitespace-separated tokens, `#` comments skipped, as the scene parser reads them.
std::vector<Token> tokenize(std::string_view text) {
  std::vector<Token> tokens;
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == '#') {
      while (i < text.size() && text[i] != '\n') ++i;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else {
      const std::size_t begin = i;
      while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i])) &&
             text[i] != '#')
        ++i;
      tokens.push_back({begin, i});
    }
  }
  return tokens;
}

// Operands after each keyword (11 material numbers included).
const std::map<std::string_view, std::size_t>& operandCounts() {
  static const std::map<std::string_view, std::size_t> counts{
      {"camera", 12}, {"depth", 1},  {"background", 3}, {"ambience", 3}, {"light", 6},
      {"sphere", 15}, {"plane", 17}, {"cylinder", 19},  {"mesh", 13}};
  return counts;
}

// A mesh entity: its keyword, its file, its shading word and its last operand.
struct MeshTokens {
  Token keyword, file, mode, last;
};

std::vector<MeshTokens> meshTokens(std::string_view text) {
  const std::vector<Token> tokens = tokenize(text);
  std::vector<MeshTokens> meshes;
  for (std::size_t i = 0; i < tokens.size();) {
    const std::string_view word = text.substr(tokens[i].begin, tokens[i].end - tokens[i].begin);
    const auto it = operandCounts().find(word);
    if (it == operandCounts().end())
      throw std::runtime_error("unexpected word '" + std::string(word) + "'");
    if (word == "mesh" && i + 2 < tokens.size())
      meshes.push_back({tokens[i], tokens[i + 1], tokens[i + 2],
                        tokens[std::min(i + it->second, tokens.size() - 1)]});
    i += 1 + it->second;
  }
  return meshes;
}

// Whether the line holding text[pos] has something other than blanks
// before pos (before) or other than blanks and a comment after it.
bool entityBefore(std::string_view text, std::size_t pos) {
  const std::size_t start = text.rfind('\n', pos);
  const std::size_t from = start == std::string_view::npos ? 0 : start + 1;
  return text.substr(from, pos - from).find_first_not_of(" \t\r") != std::string_view::npos;
}
bool entityAfter(std::string_view text, std::size_t pos) {
  const std::size_t first = text.find_first_not_of(" \t\r", pos);
  return first != std::string_view::npos && text[first] != '\n' && text[first] != '#';
}

// The entity as comment lines, on lines of their own: the scene reader
// skips it, and a reader of the file sees what was hidden.
std::string commentedOut(std::string_view entity, bool before, bool after) {
  std::string out = before ? "\n" : "";
  out += "# hidden in the viewer: ";
  for (const char c : entity) {
    out += c;
    if (c == '\n') out += "#   ";
  }
  if (after) out += '\n';
  return out;
}
// A mesh's path as written in a scene moved from folder `from` to `to`: a
// relative path is relative to the scene's folder, so it is re-expressed
// from the new one (absolute when no relative path leads there).
std::string movedMeshPath(std::string_view written, const std::filesystem::path& from,
                          const std::filesystem::path& to) {
  const std::filesystem::path path(written);
  if (path.is_absolute() || from == to) return std::string(written);
  std::error_code ec;
  const std::filesystem::path target =
      std::filesystem::absolute(from / path, ec).lexically_normal();
  const std::filesystem::path folder = std::filesystem::absolute(to, ec).lexically_normal();
  const std::filesystem::path relative = target.lexically_relative(folder);
  const std::string moved = (relative.empty() ? target : relative).string();
  if (!isSceneWord(moved))
    throw std::runtime_error("the mesh " + std::string(written) + " would be written as '" + moved +
                             "', which a scene file cannot hold (white space or '#'); save the "
                             "scene beside its meshes or move them");
  return moved;
}
}  // namespace

std::vector<Shading> meshModes(std::string_view text) {
  std::vector<Shading> modes;
  for (const MeshTokens& m : meshTokens(text)) {
    try {
      modes.push_back(parseShading(text.substr(m.mode.begin, m.mode.end - m.mode.begin)));
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(e.what());
    }
  }
  return modes;
}

std::string rewriteMeshes(std::string_view text, const std::vector<Shading>& modes,
                          const std::vector<bool>& visible, const std::filesystem::path& from,
                          const std::filesystem::path& to) {
  const std::vector<MeshTokens> meshes = meshTokens(text);
  if (meshes.size() != modes.size() || visible.size() != modes.size()) {
    throw std::runtime_error("the file has " + std::to_string(meshes.size()) +
                             " meshes, the scene " + std::to_string(modes.size()));
  }
  std::string out;
  std::size_t pos = 0;
  for (std::size_t m = 0; m < modes.size(); ++m) {
    const MeshTokens& t = meshes[m];
    out.append(text.substr(pos, t.keyword.begin - pos));
    std::string entity(text.substr(t.keyword.begin, t.file.begin - t.keyword.begin));
    entity.append(movedMeshPath(text.substr(t.file.begin, t.file.end - t.file.begin), from, to));
    entity.append(text.substr(t.file.end, t.mode.begin - t.file.end));
    entity.append(toString(modes[m]));
    entity.append(text.substr(t.mode.end, t.last.end - t.mode.end));
    out.append(visible[m] ? entity
                          : commentedOut(entity, entityBefore(text, t.keyword.begin),
                                         entityAfter(text, t.last.end)));
    pos = t.last.end;
  }
  out.append(text.substr(pos));
  return out;
}

void saveSceneWithMeshes(const std::filesystem::path& scene, const std::filesystem::path& out,
                         const std::vector<Shading>& modes, const std::vector<bool>& visible,
                         Existing existing) {
  refuseExisting(out, existing);
  std::ifstream in(scene, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + scene.string());
  std::stringstream buffer;
  buffer << in.rdbuf();
  saveSceneTextWithMeshes(buffer.str(), scene.string(), scene.parent_path(), out, modes, visible,
                          existing);
}

void saveSceneTextWithMeshes(std::string_view text, const std::string& source,
                             const std::filesystem::path& from, const std::filesystem::path& out,
                             const std::vector<Shading>& modes, const std::vector<bool>& visible,
                             Existing existing) {
  refuseExisting(out, existing);
  std::string rewritten;
  try {
    rewritten = rewriteMeshes(text, modes, visible, from, out.parent_path());
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(source + ": " + e.what());
  }
  writeFileAtomically(out, rewritten);
}

}  // namespace meshtrace::viewer
