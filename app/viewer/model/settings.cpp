#include "viewer/model/settings.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>

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

ViewerSettings loadSettings(const fs::path& file) {
  ViewerSettings s;
  std::ifstream in(file);
  const std::string recent = "recent ";
  for (std::string line; std::getline(in, line);)
    if (line.rfind(recent, 0) == 0 && s.recent.size() < ViewerSettings::kMaxRecent)
      s.recent.emplace_back(line.substr(recent.size()));
  return s;
}

void saveSettings(const ViewerSettings& settings, const fs::path& file) {
  std::string text;
  for (const fs::path& p : settings.recent) text += "recent " + p.string() + "\n";
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
