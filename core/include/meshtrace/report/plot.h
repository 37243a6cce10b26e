#pragma once
// The plots of `raytrace --report`, drawn by gnuplot (Debian's gnuplot-nox)
// from report.csv: per scene, error against run time for every
// configuration group, with the JPEG-noise threshold labelled, and the
// samples-per-pixel convergence on log-log axes.
#include <filesystem>
#include <string>

#include "meshtrace/report/report.h"

namespace meshtrace {

// The gnuplot script that plots `report`'s scene from the CSV named by the
// variable `csv` (report.csv beside the script unless given with
// gnuplot -e "csv='...'") into the file named by `png`.
std::string plotScript(const SceneReport& report);

// Runs gnuplot on plotScript(report) over `csvBytes` (report.csv's
// contents) and returns the PNG's bytes. Throws std::runtime_error if
// gnuplot is missing or fails.
std::string plotPng(const SceneReport& report, const std::string& csvBytes);

}  // namespace meshtrace
