#include "viewer/model/scene_writer.h"

#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

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

// The token of each mesh's shading word.
std::vector<Token> modeTokens(std::string_view text) {
  const std::vector<Token> tokens = tokenize(text);
  std::vector<Token> modes;
  for (std::size_t i = 0; i < tokens.size();) {
    const std::string_view word = text.substr(tokens[i].begin, tokens[i].end - tokens[i].begin);
    const auto it = operandCounts().find(word);
    if (it == operandCounts().end())
      throw std::runtime_error("unexpected word '" + std::string(word) + "'");
    if (word == "mesh" && i + 2 < tokens.size()) modes.push_back(tokens[i + 2]);
    i += 1 + it->second;
  }
  return modes;
}
}  // namespace

std::vector<Shading> meshModes(std::string_view text) {
  std::vector<Shading> modes;
  for (const Token& t : modeTokens(text)) {
    try {
      modes.push_back(parseShading(text.substr(t.begin, t.end - t.begin)));
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(e.what());
    }
  }
  return modes;
}

std::string rewriteMeshModes(std::string_view text, const std::vector<Shading>& modes) {
  const std::vector<Token> tokens = modeTokens(text);
  if (tokens.size() != modes.size()) {
    throw std::runtime_error("the file has " + std::to_string(tokens.size()) +
                             " meshes, the scene " + std::to_string(modes.size()));
  }
  std::string out;
  std::size_t pos = 0;
  for (std::size_t m = 0; m < modes.size(); ++m) {
    out.append(text.substr(pos, tokens[m].begin - pos));
    out.append(toString(modes[m]));
    pos = tokens[m].end;
  }
  out.append(text.substr(pos));
  return out;
}

void saveSceneWithModes(const std::filesystem::path& scene, const std::filesystem::path& out,
                        const std::vector<Shading>& modes) {
  std::ifstream in(scene, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + scene.string());
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string text;
  try {
    text = rewriteMeshModes(buffer.str(), modes);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(scene.string() + ": " + e.what());
  }
  const std::filesystem::path tmp = out.string() + ".tmp";
  {
    std::ofstream o(tmp, std::ios::binary);
    o << text;
    if (!o.flush()) throw std::runtime_error("cannot write " + tmp.string());
  }
  std::error_code ec;
  std::filesystem::rename(tmp, out, ec);
  if (ec) throw std::runtime_error("cannot write " + out.string() + ": " + ec.message());
}

}  // namespace meshtrace::viewer
