#include "viewer/model/settings.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "meshtrace/io/output_file.h"

namespace meshtrace::viewer {

namespace fs = std::filesystem;

fs::path settingsFile() {
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg)
    return fs::path(xdg) / "meshtrace" / "viewer.txt";
  if (const char* home = std::getenv("HOME"); home && *home)
    return fs::path(home) / ".config" / "meshtrace" / "viewer.txt";
  return {};
}

namespace {
// "NAME WIDTH SHOWN" into `panel`, if the line is one.
void readPanel(const std::string& line, const std::string& name, SidePanel& panel) {
  std::istringstream in(line);
  std::string word;
  float width = 0;
  int shown = 1;
  if (in >> word && word == name && in >> width >> shown && width >= 0) {
    panel.width = width;
    panel.shown = shown != 0;
  }
}

// "NAME HEIGHT" into `height`, if the line is one.
void readHeight(const std::string& line, const std::string& name, float& height) {
  std::istringstream in(line);
  std::string word;
  float h = 0;
  if (in >> word && word == name && in >> h && h >= 0) height = h;
}

void readBookmark(const std::string& line, std::vector<CameraBookmark>& out) {
  const std::string key = "bookmark ";
  if (line.rfind(key, 0) != 0) return;
  const std::size_t a = line.find('\t', key.size());
  const std::size_t b = a == std::string::npos ? a : line.find('\t', a + 1);
  if (b == std::string::npos) return;
  out.push_back(
      {line.substr(key.size(), a - key.size()), line.substr(a + 1, b - a - 1), line.substr(b + 1)});
}

fs::path absoluteOf(const fs::path& p) {
  std::error_code ec;
  const fs::path a = fs::absolute(p, ec).lexically_normal();
  return ec ? p : a;
}

// Tabs and line breaks would break the line a bookmark is kept in.
std::string oneField(std::string text) {
  for (char& c : text)
    if (c == '\t' || c == '\n' || c == '\r') c = ' ';
  return text;
}
}  // namespace

void setBookmark(ViewerSettings& settings, const fs::path& scene, const std::string& name,
                 const std::string& cameraLine) {
  const CameraBookmark b{absoluteOf(scene), oneField(name), oneField(cameraLine)};
  for (CameraBookmark& existing : settings.bookmarks)
    if (existing.scene == b.scene && existing.name == b.name) {
      existing = b;
      return;
    }
  settings.bookmarks.push_back(b);
}

std::vector<CameraBookmark> bookmarksOf(const ViewerSettings& settings, const fs::path& scene) {
  std::vector<CameraBookmark> out;
  const fs::path p = absoluteOf(scene);
  for (const CameraBookmark& b : settings.bookmarks)
    if (b.scene == p) out.push_back(b);
  return out;
}

void removeBookmark(ViewerSettings& settings, const fs::path& scene, const std::string& name) {
  const fs::path p = absoluteOf(scene);
  std::erase_if(settings.bookmarks,
                [&](const CameraBookmark& b) { return b.scene == p && b.name == name; });
}

ViewerSettings loadSettings(const fs::path& file) {
  ViewerSettings s;
  std::ifstream in(file);
  const std::string recent = "recent ";
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(recent, 0) == 0 && s.recent.size() < ViewerSettings::kMaxRecent)
      s.recent.emplace_back(line.substr(recent.size()));
    readBookmark(line, s.bookmarks);
    readPanel(line, "left-panel", s.left);
    readPanel(line, "right-panel", s.right);
    readHeight(line, "scene-list-height", s.panes.sceneList);
    readHeight(line, "inspector-height", s.panes.inspector);
  }
  return s;
}

PanelWidths panelWidths(float width, const ViewerSettings& s) {
  const auto chosen = [&](const SidePanel& p, float share, float lo, float hi) {
    if (!p.shown) return 0.0f;
    const float w = p.width > 0 ? p.width : std::clamp(share * width, lo, hi);
    return std::max(kMinPanel, w);
  };
  float left = chosen(s.left, 0.22f, 230.0f, 320.0f);
  float right = chosen(s.right, 0.32f, 330.0f, 440.0f);
  // The panels give up room in proportion until the image has 40%.
  const float room = 0.6f * width;
  if (left + right > room) {
    const float scale = room / (left + right);
    left *= scale;
    right *= scale;
  }
  return {left, right};
}

void saveSettings(const ViewerSettings& settings, const fs::path& file) {
  std::string text;
  for (const fs::path& p : settings.recent) text += "recent " + p.string() + "\n";
  const auto panel = [&](const char* name, const SidePanel& p) {
    text += std::string(name) + " " + std::to_string(static_cast<int>(p.width)) + " " +
            (p.shown ? "1" : "0") + "\n";
  };
  for (const CameraBookmark& b : settings.bookmarks)
    text += "bookmark " + b.scene.string() + "\t" + b.name + "\t" + b.cameraLine + "\n";
  panel("left-panel", settings.left);
  panel("right-panel", settings.right);
  text += "scene-list-height " + std::to_string(static_cast<int>(settings.panes.sceneList)) + "\n";
  text += "inspector-height " + std::to_string(static_cast<int>(settings.panes.inspector)) + "\n";
  std::error_code ec;
  fs::create_directories(file.parent_path(), ec);
  writeFileAtomically(file, text);
}

void addRecent(ViewerSettings& settings, const fs::path& scene) {
  const fs::path p = absoluteOf(scene);
  auto& r = settings.recent;
  r.erase(std::remove(r.begin(), r.end(), p), r.end());
  r.insert(r.begin(), p);
  if (r.size() > ViewerSettings::kMaxRecent) r.resize(ViewerSettings::kMaxRecent);
}

}  // namespace meshtrace::viewer
