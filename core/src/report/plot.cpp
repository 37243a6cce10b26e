// The plots of `raytrace --report`, as gnuplot scripts over report.csv.
#include "meshtrace/report/plot.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string_view>

namespace meshtrace {

namespace {
// The configuration groups measured against the scene's reference, as the
// CSV names them and as the legend does; the samples sweep, measured
// against a converged render, has a panel of its own.
struct Group {
  const char* csv;
  const char* legend;
  const char* color;
};
constexpr Group kGroups[] = {
    {"progressive", "progressive passes (coarse to exact)", "#d62728"},
    {"triangle", "triangle test, double precision", "#2ca02c"},
    {"precision", "triangle test, single precision", "#9467bd"},
    {"accel", "acceleration (box per mesh, brute force)", "#ff7f0e"},
};

// A single-quoted gnuplot string holding `text` (quotes doubled); for a
// `shown` string, one printed in enhanced text, its markup characters
// (_ ^ @ & { }) escaped too.
std::string quotedForGnuplot(const std::string& text, bool shown = false) {
  std::string out = "'";
  for (char c : text) {
    if (c == '\'')
      out += "''";
    else if (shown && std::string_view("_^@&{}").find(c) != std::string_view::npos)
      out += std::string("\\") + c;
    else
      out += c;
  }
  return out + "'";
}
}  // namespace

std::string plotScript(const SceneReport& report) {
  const std::string scene = report.scene.stem().string();
  std::ostringstream gp;
  // The y range of the first panel: its errors (0 drawn at 0.01) and the
  // JPEG-noise threshold.
  // The first panel's y axis: an RMSE of 0 (identical to the reference)
  // has no place on a log axis, so it is drawn a decade below the smallest
  // error that is not 0, at a tic labelled "0 (exact)"; the axis runs from
  // there past the largest error and the JPEG-noise threshold, with room
  // above them for the legend.
  double smallest = report.jpegNoiseRmse > 0.0 ? report.jpegNoiseRmse : 1.0, high = smallest;
  for (const ReportRow& r : report.rows) {
    if (r.against != "reference" || !(r.rmse > 0.0)) continue;
    smallest = std::min(smallest, r.rmse);
    high = std::max(high, r.rmse);
  }
  const double zero = std::min(0.01, std::pow(10.0, std::floor(std::log10(smallest)) - 1.0));
  const double bottom = zero / 2, belowKey = high * 2;
  const double top = belowKey * std::pow(belowKey / bottom, 0.4);
  std::ostringstream ytics;
  ytics << "set ytics ('0 (exact)' " << zero;
  for (double tic = zero * 10; tic <= top; tic *= 10) ytics << ", '" << tic << "' " << tic;
  ytics << ")\n";
  char jpeg[32];
  std::snprintf(jpeg, sizeof jpeg, "%.3f", report.jpegNoiseRmse);
  // Columns of report.csv: 1 scene, 2 group, 3 config, 8 samples, 9 seconds, 10 rmse.
  gp << "# Plots " << scene << " from report.csv (raytrace --report): gnuplot plot_" << scene
     << ".gp\n"
     << "if (!exists('csv')) csv = 'report.csv'\n"
     << "if (!exists('png')) png = 'plot_" << scene << ".png'\n"
     << "set datafile separator comma\n"
     << "set terminal pngcairo size 1100,480 font 'sans,11'\n"
     << "set output png\n"
     << "scene = " << quotedForGnuplot(scene) << "\n"
     << "# RMSE 0 (identical to the reference) is drawn at the tic '0 (exact)'.\n"
     << "zero = " << zero << "\n"
     << "shown(e) = e > 0 ? e : zero\n"
     << "pick(g, v) = (strcol(1) eq scene && strcol(2) eq g) ? v : NaN\n"
     << "set multiplot layout 1,2 title " << quotedForGnuplot(scene + ": error and run time", true)
     << " font 'sans,13'\n"
     << "set logscale xy\nset grid\nset key top right box opaque font 'sans,9'\n"
     << "set title 'Error against run time, per configuration group'\n"
     << "set xlabel 'run time, whole image on all cores (s)'\n"
     << "set ylabel 'RMSE against the reference (8-bit levels)'\n"
     << "jpeg = " << jpeg << "\n"
     << "# The errors and the threshold, with room around them and the legend above.\n"
     << "set yrange [" << bottom << ":" << top << "]\n"
     << ytics.str()
     << "set arrow 1 from graph 0, first jpeg to graph 1, first jpeg nohead dt 2 lw 1.5 lc "
        "'black'\n"
     << "set label 1 sprintf('JPEG noise: RMSE %.3f', jpeg) at graph 0.02, first jpeg offset 0,0.6 "
        "font 'sans,9'\n"
     << "plot ";
  bool first = true;
  for (const Group& g : kGroups) {
    gp << (first ? "" : ", \\\n     ") << "csv using (pick('" << g.csv << "', $9)):(shown($10)) "
       << "skip 1 with points pt 7 ps 1.2 lc rgb '" << g.color << "' title '" << g.legend << "'";
    first = false;
  }
  gp << "\nunset arrow 1\nunset label 1\n"
     << "set title 'Samples per pixel against a converged render'\n"
     << "set xlabel 'samples per pixel'\n"
     << "set ylabel 'RMSE against the converged render (8-bit levels)'\n"
     << "set xtics (1, 2, 4, 8, 16, 32, 64, 128, 256)\nset autoscale y\nset ytics autofreq\n"
     << "set key top right box opaque width 2 font 'sans,9'\n"
     << "f(x) = a * x**b\na = 1; b = -0.5\n"
     << "set fit quiet nolog\n"
     << "fit log(f(x)) csv using (pick('samples', $8)):(log(shown($10))) skip 1 via a, b\n"
     << "set label 2 sprintf('RMSE falls as samples^{%.2f} (log-log slope)', b) at graph 0.05, "
        "graph 0.08 font 'sans,10'\n"
     << "plot csv using (pick('samples', $8)):(shown($10)) skip 1 with linespoints pt 7 lc rgb "
        "'#1f77b4' title 'measured', \\\n"
     << "     f(x) with lines dt 2 lc 'black' title 'power-law fit'\n"
     << "unset multiplot\n";
  return gp.str();
}

std::string plotPng(const SceneReport& report, const std::string& csvBytes) {
  std::string pattern = (std::filesystem::temp_directory_path() / "meshtrace-plot-XXXXXX").string();
  if (!::mkdtemp(pattern.data())) throw std::runtime_error("cannot make a folder for gnuplot");
  const std::filesystem::path folder = pattern;
  std::string png;
  std::string error;
  {
    std::ofstream(folder / "report.csv", std::ios::binary) << csvBytes;
    std::ofstream(folder / "plot.gp", std::ios::binary) << plotScript(report);
    const std::string command =
        "cd '" + folder.string() + "' && gnuplot -e \"png='plot.png'\" plot.gp > gnuplot.log 2>&1";
    const int status = std::system(command.c_str());
    if (status != 0 || !std::filesystem::exists(folder / "plot.png")) {
      std::ifstream log(folder / "gnuplot.log");
      std::string said((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
      error = WIFEXITED(status) && WEXITSTATUS(status) == 127
                  ? "gnuplot not found (Debian's gnuplot-nox)"
                  : "gnuplot failed: " + said.substr(said.size() > 300 ? said.size() - 300 : 0);
    } else {
      std::ifstream in(folder / "plot.png", std::ios::binary);
      png.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
  }
  std::error_code ec;
  std::filesystem::remove_all(folder, ec);
  if (!error.empty()) throw std::runtime_error(error);
  return png;
}

}  // namespace meshtrace
