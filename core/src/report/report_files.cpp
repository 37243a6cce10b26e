#include "report/report_files.h"

#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>

#include "io/text.h"
#include "meshtrace/io/input_error.h"
#include "meshtrace/util/quoted.h"
#include "report/csv.h"

namespace meshtrace::report_files {

namespace {

// Far above any report's files; a bound so that a wrong path cannot make
// the merge read a disk image.
constexpr std::uintmax_t kMaxFileBytes = 256u << 20;

constexpr const char* kRowColumns[] = {"scene",          "group",     "config",   "accel",
                                       "triangle",       "precision", "step",     "samples",
                                       "seconds",        "rmse",      "psnr",     "hit_differs",
                                       "max_normal_deg", "against",   "reference"};
constexpr const char* kSceneColumns[] = {
    "scene", "file", "reference", "converged", "jpeg_noise_rmse", "samples_slope", "left_out"};

// The rows of a CSV file whose header must be `columns`, header left out.
template <std::size_t N>
std::vector<csv::Row> readTable(const std::string& text, const std::filesystem::path& file,
                                const char* const (&columns)[N]) {
  std::vector<csv::Row> rows = csv::parse(text, file);
  std::string expected;
  for (const char* c : columns) expected += std::string(expected.empty() ? "" : ",") + c;
  if (rows.empty() || rows[0].fields != std::vector<std::string>(columns, columns + N))
    throw InputError::atLine(file, 1, "the header is not the report's (" + expected + ")");
  rows.erase(rows.begin());
  for (const csv::Row& row : rows)
    if (row.fields.size() != N)
      throw InputError::atLine(
          file, row.line,
          std::to_string(row.fields.size()) + " fields where the header has " + std::to_string(N));
  return rows;
}

double number(const std::filesystem::path& file, const csv::Row& row, std::size_t column,
              const char* name) {
  double x = 0.0;
  const std::string& text = row.fields[column];
  // psnr is "inf" for an image identical to its reference.
  if (text == "inf") return std::numeric_limits<double>::infinity();
  if (!text::parseDouble(text, x))
    throw InputError::atLine(
        file, row.line, std::string(name) + " is " + meshtrace::quoted(text) + ", not a number");
  return x;
}

int count(const std::filesystem::path& file, const csv::Row& row, std::size_t column,
          const char* name) {
  std::int64_t n = 0;
  if (!text::parseInt64(row.fields[column], n) || n < 1 || n > 1 << 20)
    throw InputError::atLine(file, row.line,
                             std::string(name) + " is " + meshtrace::quoted(row.fields[column]) +
                                 ", not a count from 1 to 1048576");
  return int(n);
}

}  // namespace

std::string sceneName(const SceneReport& report) { return report.scene.stem().string(); }

std::string rowsCsv(const std::vector<SceneReport>& scenes) {
  std::string out;
  for (const char* c : kRowColumns) out += std::string(out.empty() ? "" : ",") + c;
  out += "\n";
  char buf[512];
  for (const SceneReport& s : scenes)
    for (const ReportRow& r : s.rows) {
      const ReportConfig& c = r.config;
      const std::string& against = r.against == "converged" ? s.converged : s.reference;
      std::snprintf(buf, sizeof buf, ",%s,%s,%s,%d,%d,%.6f,%.4f,%.3f,%.6f,%.6g,",
                    toString(c.trace.accel), toString(c.trace.triangle.test),
                    toString(c.trace.triangle.precision), c.step, c.samples, r.seconds, r.rmse,
                    r.psnr, r.hitDiffers, r.maxNormalDegrees);
      out += csv::field(sceneName(s)) + "," + csv::field(c.group) + "," + csv::field(c.name) + buf +
             csv::field(r.against) + "," + csv::field(against) + "\n";
    }
  return out;
}

std::string scenesCsv(const std::vector<SceneReport>& scenes) {
  std::string out;
  for (const char* c : kSceneColumns) out += std::string(out.empty() ? "" : ",") + c;
  out += "\n";
  for (const SceneReport& s : scenes) {
    std::string leftOut;
    for (const std::string& l : s.leftOut) leftOut += (leftOut.empty() ? "" : "\n") + l;
    // Shortest round-trip text: the merged report compares and prints the
    // same numbers as the share's.
    out += csv::field(sceneName(s)) + "," + csv::field(s.scene.string()) + "," +
           csv::field(s.reference) + "," + csv::field(s.converged) + "," +
           shortestText(s.jpegNoiseRmse) + "," + shortestText(s.samplesSlope) + "," +
           csv::field(leftOut) + "\n";
  }
  return out;
}

std::string shareText(const ReportShare& share) {
  std::string out =
      "# raytrace --report: this folder holds share " + share.shard.text() +
      " of the run's scenes, those whose index in this sorted list is " +
      std::to_string(share.shard.index) + " modulo " + std::to_string(share.shard.count) +
      ". raytrace --report-merge joins the shares.\nshare " + share.shard.text() + "\n";
  for (const std::filesystem::path& s : share.scenes) out += "scene " + s.string() + "\n";
  return out;
}

std::vector<SceneReport> readScenes(const std::filesystem::path& dir) {
  return parseScenes(csv::readFile(dir / kScenes, kMaxFileBytes),
                     csv::readFile(dir / kRows, kMaxFileBytes), dir);
}

std::vector<SceneReport> parseScenes(const std::string& scenesText, const std::string& rowsText,
                                     const std::filesystem::path& dir) {
  const std::filesystem::path scenesFile = dir / kScenes, rowsFile = dir / kRows;
  std::vector<SceneReport> scenes;
  std::map<std::string, std::size_t> byName;
  for (const csv::Row& row : readTable(scenesText, scenesFile, kSceneColumns)) {
    SceneReport s;
    s.scene = row.fields[1];
    if (s.scene.empty() || sceneName(s) != row.fields[0])
      throw InputError::atLine(scenesFile, row.line,
                               "scene " + meshtrace::quoted(row.fields[0]) +
                                   " is not the stem of its file " +
                                   meshtrace::quoted(row.fields[1]));
    if (!byName.emplace(row.fields[0], scenes.size()).second)
      throw InputError::atLine(scenesFile, row.line,
                               "scene " + meshtrace::quoted(row.fields[0]) + " is listed twice");
    s.reference = row.fields[2];
    s.converged = row.fields[3];
    s.jpegNoiseRmse = number(scenesFile, row, 4, "jpeg_noise_rmse");
    s.samplesSlope = number(scenesFile, row, 5, "samples_slope");
    for (std::size_t at = 0; at < row.fields[6].size();) {
      const std::size_t end = std::min(row.fields[6].find('\n', at), row.fields[6].size());
      s.leftOut.push_back(row.fields[6].substr(at, end - at));
      at = end + 1;
    }
    scenes.push_back(std::move(s));
  }
  for (const csv::Row& row : readTable(rowsText, rowsFile, kRowColumns)) {
    const auto it = byName.find(row.fields[0]);
    if (it == byName.end())
      throw InputError::atLine(
          rowsFile, row.line,
          "scene " + meshtrace::quoted(row.fields[0]) + " is not in " + kScenes);
    ReportRow r;
    ReportConfig& c = r.config;
    c.group = row.fields[1];
    c.name = row.fields[2];
    try {
      c.trace.accel = parseAccelMethod(row.fields[3]);
      c.trace.triangle = {parseTriangleTest(row.fields[4]), parsePrecision(row.fields[5])};
    } catch (const std::invalid_argument& e) {
      throw InputError::atLine(rowsFile, row.line, e.what());
    }
    c.step = count(rowsFile, row, 6, "step");
    c.samples = count(rowsFile, row, 7, "samples");
    r.seconds = number(rowsFile, row, 8, "seconds");
    r.rmse = number(rowsFile, row, 9, "rmse");
    r.psnr = number(rowsFile, row, 10, "psnr");
    r.hitDiffers = number(rowsFile, row, 11, "hit_differs");
    r.maxNormalDegrees = number(rowsFile, row, 12, "max_normal_deg");
    r.against = row.fields[13];
    if (r.against != "reference" && r.against != "converged")
      throw InputError::atLine(
          rowsFile, row.line,
          "against is " + meshtrace::quoted(r.against) + ", not reference or converged");
    scenes[it->second].rows.push_back(std::move(r));
  }
  return scenes;
}

ReportShare readShare(const std::filesystem::path& dir) {
  const std::filesystem::path file = dir / kShare;
  const std::string bytes = csv::readFile(file, kMaxFileBytes);
  ReportShare share;
  bool sawShare = false;
  std::size_t lineNumber = 0;
  // Line by line, not through text::LineReader: a scene's path may hold a '#'.
  for (std::size_t at = 0; at < bytes.size();) {
    const std::size_t end = std::min(bytes.find('\n', at), bytes.size());
    const std::string_view line = std::string_view(bytes).substr(at, end - at);
    at = end + 1;
    ++lineNumber;
    if (line.empty() || line[0] == '#') continue;
    const std::size_t space = line.find(' ');
    const std::string_view key = line.substr(0, space);
    const std::string_view value = space == line.npos ? "" : line.substr(space + 1);
    if (key == "share" && !sawShare) {
      try {
        share.shard = parseShard(value);
      } catch (const std::invalid_argument& e) {
        throw InputError::atLine(file, lineNumber, e.what());
      }
      sawShare = true;
    } else if (key == "scene" && !value.empty()) {
      share.scenes.emplace_back(value);
    } else {
      throw InputError::atLine(
          file, lineNumber,
          meshtrace::quoted(line) + " is neither one 'share I/N' line nor 'scene FILE'");
    }
  }
  if (!sawShare) throw InputError::inFile(file, "no 'share I/N' line");
  return share;
}

std::string readStability(const std::filesystem::path& dir) {
  return csv::readFile(dir / kStability, kMaxFileBytes);
}

}  // namespace meshtrace::report_files
