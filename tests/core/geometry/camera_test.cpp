// The pinhole camera: the pixel-ray formula of the scene format, y = 0 the
// bottom row, no half-pixel offset, and an up vector parallel to the view.
#include "meshtrace/geometry/camera.h"

#include <gtest/gtest.h>

#include <numbers>

namespace meshtrace {
namespace {

CameraSpec spec(const Vec3& eye, const Vec3& center, const Vec3& up, double fovy, int w, int h) {
  CameraSpec s;
  s.eye = eye;
  s.center = center;
  s.up = up;
  s.fovyDegrees = fovy;
  s.width = w;
  s.height = h;
  return s;
}

// The formula of SCENE_FORMAT.md, written out independently of Camera.
Vec3 specDirection(const CameraSpec& s, double x, double y) {
  const Vec3 view = glm::normalize(s.center - s.eye);
  const double dist = glm::length(s.center - s.eye);
  const double imageHeight = 2.0 * dist * std::tan(s.fovyDegrees * std::numbers::pi / 180.0 / 2.0);
  const double imageWidth = double(s.width) / s.height * imageHeight;
  const Vec3 xDir = glm::normalize(glm::cross(view, s.up)) * imageWidth / double(s.width);
  const Vec3 yDir = glm::normalize(glm::cross(xDir, view)) * imageHeight / double(s.height);
  const Vec3 lowerLeft = s.center - 0.5 * s.width * xDir - 0.5 * s.height * yDir;
  return glm::normalize(lowerLeft + x * xDir + y * yDir - s.eye);
}

void expectNear(const Vec3& a, const Vec3& b, double tol = 1e-12) {
  EXPECT_NEAR(glm::length(a - b), 0.0, tol) << "(" << a.x << ", " << a.y << ", " << a.z << ") vs ("
                                            << b.x << ", " << b.y << ", " << b.z << ")";
}

TEST(Camera, PrimaryRaysFollowTheSpecFormula) {
  const CameraSpec s = spec(Vec3(1, 2, 3), Vec3(-0.5, 0.25, 0), Vec3(0.1, 1, 0.2), 50, 40, 30);
  const Camera camera(s);
  EXPECT_FALSE(camera.upWasReplaced());
  for (int y : {0, 7, 29})
    for (int x : {0, 13, 39}) {
      const Ray ray = camera.primaryRay(x, y);
      EXPECT_EQ(ray.origin, s.eye);
      expectNear(ray.direction, specDirection(s, x, y));
      EXPECT_NEAR(glm::length(ray.direction), 1.0, 1e-15);
    }
}

TEST(Camera, RowZeroIsTheBottomAndColumnZeroTheLeft) {
  const Camera camera(spec(Vec3(0, 0, 5), Vec3(0.0), Vec3(0, 1, 0), 60, 20, 10));
  EXPECT_LT(camera.primaryRay(10, 0).direction.y, 0.0) << "row 0 looks down";
  EXPECT_GT(camera.primaryRay(10, 9).direction.y, 0.0) << "the last row looks up";
  EXPECT_LT(camera.primaryRay(0, 5).direction.x, 0.0) << "column 0 looks left";
  EXPECT_GT(camera.primaryRay(19, 5).direction.x, 0.0);
}

// Without a half-pixel offset, pixel (w/2, h/2) looks exactly at the center
// and pixel (0, 0) at the lower-left corner of the image plane.
TEST(Camera, HasNoHalfPixelOffset) {
  const Camera camera(spec(Vec3(0, 0, 5), Vec3(0.0), Vec3(0, 1, 0), 90, 20, 10));
  expectNear(camera.primaryRay(10, 5).direction, Vec3(0, 0, -1));
  // fovy 90 at distance 5: the image plane is 10 high and 20 wide.
  expectNear(camera.primaryRay(0, 0).direction, glm::normalize(Vec3(-10, -5, -5)));
}

TEST(Camera, UpNeedNotBePerpendicularToTheView) {
  const Camera camera(spec(Vec3(0, 0, 5), Vec3(0.0), Vec3(0, 1, 3), 45, 8, 8));
  EXPECT_FALSE(camera.upWasReplaced());
  expectNear(camera.primaryRay(4, 4).direction, Vec3(0, 0, -1));
  EXPECT_GT(camera.primaryRay(4, 7).direction.y, 0.0);
}

TEST(Camera, ReplacesAnUpVectorParallelToTheView) {
  for (const Vec3 up : {Vec3(0, -1, 0), Vec3(0, 2, 0)}) {
    const Camera camera(spec(Vec3(0, 5, 0), Vec3(0.0), up, 45, 8, 6));
    EXPECT_TRUE(camera.upWasReplaced());
    expectNear(camera.primaryRay(4, 3).direction, Vec3(0, -1, 0));
    for (int y = 0; y < 6; ++y)
      for (int x = 0; x < 8; ++x) EXPECT_TRUE(isFinite(camera.primaryRay(x, y).direction));
    // The replacement still gives a non-degenerate image: corners differ.
    EXPECT_GT(glm::length(camera.primaryRay(0, 0).direction - camera.primaryRay(7, 5).direction),
              0.1);
  }
}

// An up vector of any length gives its direction: 1e-200, 1e200 or 5e-324
// along y is the up of the same vector scaled near 1 by a power of two, bit
// for bit, and y itself to rounding.
TEST(Camera, TakesAnUpVectorOfAnyLength) {
  const Vec3 eye(1, 2, 5);
  const Camera unit(spec(eye, Vec3(0.0), Vec3(0, 1, 0), 45, 8, 6));
  for (const double y : {1e-200, 1e200, 5e-324}) {
    int e = 0;
    std::frexp(y, &e);
    const Camera camera(spec(eye, Vec3(0.0), Vec3(0, y, 0), 45, 8, 6));
    const Camera nearOne(spec(eye, Vec3(0.0), Vec3(0, std::ldexp(y, -e), 0), 45, 8, 6));
    EXPECT_FALSE(camera.upWasReplaced()) << y;
    for (const auto& [px, py] : {std::pair{0, 0}, {7, 5}, {3, 2}}) {
      EXPECT_EQ(camera.primaryRay(px, py).direction, nearOne.primaryRay(px, py).direction) << y;
      expectNear(camera.primaryRay(px, py).direction, unit.primaryRay(px, py).direction, 1e-15);
    }
  }
  EXPECT_EQ(cameraProblem(spec(Vec3(0, 0, 5), Vec3(0.0), Vec3(1e-200, 0, 0), 45, 8, 6)), "")
      << "(1e-200, 0, 0) is the x axis, not the zero vector";
  EXPECT_NE(cameraProblem(spec(Vec3(0, 0, 5), Vec3(0.0), Vec3(0.0), 45, 8, 6)).find("zero vector"),
            std::string::npos);
}

TEST(CameraProblem, NoneForTheCamerasOfTheSpec) {
  EXPECT_EQ(cameraProblem(spec(Vec3(1, 2, 3), Vec3(-0.5, 0.25, 0), Vec3(0.1, 1, 0.2), 50, 40, 30)),
            "");
  EXPECT_EQ(cameraProblem(spec(Vec3(0, 0, 1e-100), Vec3(0.0), Vec3(0, 1, 0), 45, 8, 6)), "")
      << "a tiny scene, far above underflow";
  EXPECT_EQ(cameraProblem(spec(Vec3(0, 0, 1e100), Vec3(0.0), Vec3(0, 1, 0), 45, 8, 6)), "");
  EXPECT_EQ(cameraProblem(spec(Vec3(0, 0, 5), Vec3(0.0), Vec3(0, 1, 0), 179.9999, 1, 1)), "");
}

void expectProblem(const CameraSpec& s, std::initializer_list<std::string_view> parts) {
  const std::string problem = cameraProblem(s);
  for (std::string_view part : parts)
    EXPECT_NE(problem.find(part), std::string::npos)
        << "'" << problem << "' lacks '" << part << "'";
}

TEST(CameraProblem, SaysEyeAndCenterAreTooCloseToDefineAView) {
  expectProblem(spec(Vec3(0.0), Vec3(5e-324, 0, 0), Vec3(0, 1, 0), 45, 8, 6),
                {"eye and center are 5e-324 apart: too close to define a view direction"});
  expectProblem(spec(Vec3(0, 0, 1e-300), Vec3(0.0), Vec3(0, 1, 0), 45, 8, 6),
                {"1e-300 apart", "too close to define a view direction"});
  expectProblem(spec(Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(0, 1, 0), 45, 8, 6), {"same point"});
}

TEST(CameraProblem, SaysTheImagePlaneIsTooLarge) {
  expectProblem(spec(Vec3(1e308, 0, 0), Vec3(0.0), Vec3(0, 1, 0), 90, 8, 6),
                {"eye and center are 1e+308 apart with fovy 90", "too large"});
  expectProblem(spec(Vec3(0, 0, 1e160), Vec3(0.0), Vec3(0, 1, 0), 45, 8, 6), {"too large"});
  expectProblem(spec(Vec3(-1e308, 0, 0), Vec3(1e308, 0, 0), Vec3(0, 1, 0), 45, 8, 6),
                {"too far apart", "overflows"});
}

// Eye and center 1e-5 apart at x = 1e10, where doubles are 2e-6 apart: the
// pixels' rays would be rounded to a few directions.
TEST(CameraProblem, SaysNeighbouringPixelsCannotBeToldApart) {
  expectProblem(spec(Vec3(1e10, 0, 0), Vec3(1e10, 1e-5, 0), Vec3(0, 0, 1), 45, 8, 6),
                {"1e-05 apart at coordinates up to 1e+10", "neighbouring pixels"});
  EXPECT_EQ(cameraProblem(spec(Vec3(1e10, 0, 0), Vec3(1e10, 100, 0), Vec3(0, 0, 1), 45, 80, 60)),
            "");
}

}  // namespace
}  // namespace meshtrace
