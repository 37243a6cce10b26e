// The report's plot scripts: an error of 0 is drawn at a tic that says so,
// below every error that is not 0, however small; nothing is drawn under
// the legend.
#include "meshtrace/report/plot.h"

#include <gtest/gtest.h>

#include <sstream>

namespace meshtrace {
namespace {

SceneReport withErrors(std::initializer_list<double> rmses) {
  SceneReport s;
  s.scene = "scene.sce";
  s.jpegNoiseRmse = 0.8;
  for (double e : rmses) {
    ReportRow r{{"triangle", "some test", TraceOptions{}, 1, 1}};
    r.rmse = e;
    s.rows.push_back(r);
  }
  return s;
}

// The value a line `name = value` of the script sets.
double assigned(const std::string& script, const std::string& name) {
  const std::size_t at = script.find("\n" + name + " = ");
  EXPECT_NE(at, std::string::npos) << name;
  return at == std::string::npos ? 0.0 : std::stod(script.substr(at + name.size() + 4));
}

// The first panel's y range, [low:high].
std::pair<double, double> yRange(const std::string& script) {
  const std::size_t at = script.find("set yrange [");
  EXPECT_NE(at, std::string::npos);
  std::istringstream in(script.substr(at + 12));
  double low = 0, high = 0;
  char colon = 0;
  in >> low >> colon >> high;
  return {low, high};
}

TEST(Plot, ZeroErrorIsDrawnBelowTheSmallestErrorAtATicSayingExact) {
  const std::string script = plotScript(withErrors({0.0, 0.0016, 3.0}));
  const double zero = assigned(script, "zero");
  // Below 0.0016: an error of one pixel in a million does not look exact.
  EXPECT_LT(zero, 0.0016);
  EXPECT_GT(zero, 0.0);
  EXPECT_NE(script.find("set ytics ('0 (exact)' " +
                        [&] {
                          std::ostringstream z;
                          z << zero;
                          return z.str();
                        }()),
            std::string::npos)
      << script;
  const auto [low, high] = yRange(script);
  EXPECT_LT(low, zero);
  // Room above the largest error for the legend: its four lines take the
  // top quarter of the panel.
  EXPECT_GT(std::log(high / 3.0), 0.3 * std::log(high / low)) << script;
}

TEST(Plot, WithoutSmallErrorsZeroStaysAtAHundredth) {
  const std::string script = plotScript(withErrors({0.0, 2.0}));
  EXPECT_DOUBLE_EQ(assigned(script, "zero"), 0.01);
}

}  // namespace
}  // namespace meshtrace
