#include "meshtrace/report/merge.h"

#include <map>
#include <set>
#include <stdexcept>

#include "meshtrace/io/input_error.h"
#include "meshtrace/report/report.h"
#include "report/report_files.h"

namespace meshtrace {

namespace {

std::string sceneList(const ReportShare& run, const Shard& shard) {
  std::string out;
  for (std::size_t i = 0; i < run.scenes.size(); ++i)
    if (shard.owns(i)) out += (out.empty() ? "" : ", ") + run.scenes[i].string();
  return out.empty() ? "no scenes" : out;
}

}  // namespace

void mergeReports(const std::filesystem::path& outDir,
                  const std::vector<std::filesystem::path>& shareDirs) {
  if (shareDirs.empty()) throw std::runtime_error("no share folders to merge");
  std::vector<ReportShare> shares;
  for (const auto& dir : shareDirs) shares.push_back(report_files::readShare(dir));
  const ReportShare& first = shares[0];
  // Which folder holds each share of the run.
  std::map<std::size_t, std::filesystem::path> holder;
  for (std::size_t k = 0; k < shares.size(); ++k) {
    const ReportShare& s = shares[k];
    const std::filesystem::path file = shareDirs[k] / report_files::kShare;
    if (s.shard.count != first.shard.count || s.scenes != first.scenes)
      throw InputError::inFile(
          file, "share " + s.shard.text() + " of " + std::to_string(s.scenes.size()) +
                    " scenes is not of the same run as " +
                    (shareDirs[0] / report_files::kShare).string() + " (share " +
                    first.shard.text() + " of " + std::to_string(first.scenes.size()) + " scenes)");
    const auto [it, added] = holder.emplace(s.shard.index, shareDirs[k]);
    if (!added)
      throw std::runtime_error("overlapping shares: " + it->second.string() + " and " +
                               shareDirs[k].string() + " both hold share " + s.shard.text() + " (" +
                               sceneList(first, s.shard) + ")");
  }
  for (std::size_t i = 0; i < first.shard.count; ++i)
    if (!holder.count(i)) {
      const Shard missing{i, first.shard.count};
      throw std::runtime_error("incomplete: no folder holds share " + missing.text() + " (" +
                               sceneList(first, missing) + "); " + std::to_string(holder.size()) +
                               " of " + std::to_string(first.shard.count) + " shares given");
    }

  // Each share must hold exactly its scenes, measured.
  std::map<std::string, SceneReport> measured;
  for (std::size_t k = 0; k < shares.size(); ++k) {
    const std::filesystem::path file = shareDirs[k] / report_files::kScenes;
    std::set<std::string> expected;
    for (std::size_t i = 0; i < first.scenes.size(); ++i)
      if (shares[k].shard.owns(i)) expected.insert(first.scenes[i].string());
    for (SceneReport& s : report_files::readScenes(shareDirs[k])) {
      if (!expected.erase(s.scene.string()))
        throw InputError::inFile(file, "holds " + s.scene.string() + ", which is not in share " +
                                           shares[k].shard.text());
      const std::string name = report_files::sceneName(s);
      if (s.rows.empty()) throw InputError::inFile(file, name + " has no rows in report.csv");
      measured.emplace(s.scene.string(), std::move(s));
    }
    if (!expected.empty())
      throw InputError::inFile(file, "share " + shares[k].shard.text() + " lacks " +
                                         *expected.begin() + ": its run did not finish");
  }
  std::vector<SceneReport> scenes;
  for (const std::filesystem::path& scene : first.scenes)
    scenes.push_back(std::move(measured.at(scene.string())));
  writeReport(outDir, scenes, report_files::readStability(holder.at(0)),
              ReportShare{Shard{}, first.scenes});
}

}  // namespace meshtrace
