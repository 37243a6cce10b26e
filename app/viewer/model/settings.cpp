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
}  // namespace

ViewerSettings loadSettings(const fs::path& file) {
  ViewerSettings s;
  std::ifstream in(file);
  const std::string recent = "recent ";
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(recent, 0) == 0 && s.recent.size() < ViewerSettings::kMaxRecent)
      s.recent.emplace_back(line.substr(recent.size()));
    readPanel(line, "left-panel", s.left);
    readPanel(line, "right-panel", s.right);
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
  panel("left-panel", settings.left);
  panel("right-panel", settings.right);
  std::error_code ec;
  fs::create_directories(file.parent_path(), ec);
  writeFileAtomically(file, text);
}

void addRecent(ViewerSettings& settings, const fs::path& scene) {
  std::error_code ec;
  fs::path p = fs::absolute(scene, ec).lexically_normal();
  if (ec) p = scene;
  auto& r = settings.recent;
  r.erase(std::remove(r.begin(), r.end(), p), r.end());
  r.insert(r.begin(), p);
  if (r.size() > ViewerSettings::kMaxRecent) r.resize(ViewerSettings::kMaxRecent);
}

}  // namespace meshtrace::viewer
