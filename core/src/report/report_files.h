#pragma once
// The data files of a report folder, written by writeReport and read back
// by mergeReports: report.csv (a row per scene and configuration),
// scenes.csv (a row per scene: its file, references, JPEG noise, slope and
// what was left out), stability.md (the stability table) and share.txt
// (which share of which run the folder holds).
#include <filesystem>
#include <string>
#include <vector>

#include "meshtrace/report/report.h"

namespace meshtrace::report_files {

inline constexpr const char* kRows = "report.csv";
inline constexpr const char* kScenes = "scenes.csv";
inline constexpr const char* kStability = "stability.md";
inline constexpr const char* kShare = "share.txt";

// The name a scene goes by in the files: its file's stem.
std::string sceneName(const SceneReport& report);

std::string rowsCsv(const std::vector<SceneReport>& scenes);
std::string scenesCsv(const std::vector<SceneReport>& scenes);
std::string shareText(const ReportShare& share);

// The scenes of scenes.csv's text, in its order, with their rows from
// report.csv's; both files are in `dir`. Throws InputError naming the file
// and line of anything malformed or inconsistent.
std::vector<SceneReport> parseScenes(const std::string& scenesText, const std::string& rowsText,
                                     const std::filesystem::path& dir);
// The same, read from the files in `dir`.
std::vector<SceneReport> readScenes(const std::filesystem::path& dir);
ReportShare readShare(const std::filesystem::path& dir);
std::string readStability(const std::filesystem::path& dir);

}  // namespace meshtrace::report_files
