// Interiors built from boxes (mesh_generators.h): the hall and the Menger
// sponge. Their long faces are single pairs of triangles on purpose: a
// floor stripe or a beam is two triangles as long as the hall, as exported
// architecture and CAD models have them.
#include <array>

#include "meshtrace/geometry/mesh_generators.h"

namespace meshtrace {

namespace {
// Walls reach below the floor's lowest stripe, so no light passes under them.
constexpr double kFoot = -0.05;

void addBox(MeshData& mesh, const Vec3& min, const Vec3& max) {
  appendMesh(mesh, makeGriddedBox(min, max, 1));
}

// A wall in the plane x = x0 (thickness along x), running along z from z0
// to z1 up to `height`, with `windows` openings spread along it; each
// opening is crossed by vertical and horizontal bars.
void addWindowedWall(MeshData& mesh, double x0, double thickness, double z0, double z1,
                     double height, int windows) {
  const double sill = 0.35 * height, lintel = 0.75 * height;
  const double bay = (z1 - z0) / windows, opening = 0.6 * bay;
  const double bar = 0.04;
  const double xa = x0, xb = x0 + thickness;
  for (int w = 0; w < windows; ++w) {
    const double b0 = z0 + w * bay, o0 = b0 + 0.5 * (bay - opening), o1 = o0 + opening;
    addBox(mesh, Vec3(xa, kFoot, b0), Vec3(xb, height, o0));        // pier before the opening
    addBox(mesh, Vec3(xa, kFoot, o1), Vec3(xb, height, b0 + bay));  // pier after it
    addBox(mesh, Vec3(xa, kFoot, o0), Vec3(xb, sill, o1));          // below the window
    addBox(mesh, Vec3(xa, lintel, o0), Vec3(xb, height, o1));       // above it
    const double xm = 0.5 * (xa + xb);
    for (int k = 1; k < 4; ++k) {  // vertical bars
      const double z = o0 + opening * k / 4.0;
      addBox(mesh, Vec3(xm - bar, sill, z - bar), Vec3(xm + bar, lintel, z + bar));
    }
    for (int k = 1; k < 3; ++k) {  // horizontal bars
      const double y = sill + (lintel - sill) * k / 3.0;
      addBox(mesh, Vec3(xm - bar, y - bar, o0), Vec3(xm + bar, y + bar, o1));
    }
  }
}
}  // namespace

void appendMesh(MeshData& mesh, const MeshData& part) {
  const auto offset = static_cast<std::uint32_t>(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), part.vertices.begin(), part.vertices.end());
  for (const auto& [a, b, c] : part.triangles)
    mesh.triangles.push_back({a + offset, b + offset, c + offset});
}

MeshData makeHall(double length, double width, double height) {
  MeshData m;
  const double hx = 0.5 * width, hz = 0.5 * length, wall = 0.3;
  // Floor: stripes of two colours' worth of boards, each as long as the hall.
  const int stripes = 48;
  for (int s = 0; s < stripes; ++s) {
    const double x0 = -hx + width * s / stripes, x1 = -hx + width * (s + 1) / stripes;
    addBox(m, Vec3(x0, -0.05, -hz), Vec3(x1, s % 2 == 0 ? 0.0 : -0.01, hz));
  }
  // Side walls with windows; the end walls are plain.
  addWindowedWall(m, -hx - wall, wall, -hz, hz, height, 10);
  addWindowedWall(m, hx, wall, -hz, hz, height, 10);
  addBox(m, Vec3(-hx - wall, kFoot, -hz - wall), Vec3(hx + wall, height, -hz));
  addBox(m, Vec3(-hx - wall, kFoot, hz), Vec3(hx + wall, height, hz + wall));
  // Ceiling and the beams under it, across the width.
  addBox(m, Vec3(-hx - wall, height, -hz - wall), Vec3(hx + wall, height + wall, hz + wall));
  const int beams = 20;
  for (int b = 0; b < beams; ++b) {
    const double z = -hz + length * (b + 0.5) / beams;
    addBox(m, Vec3(-hx, height - 0.5, z - 0.15), Vec3(hx, height, z + 0.15));
  }
  // A beam along the length over each row of columns.
  for (const double x : {-0.3 * width, 0.3 * width})
    addBox(m, Vec3(x - 0.2, height - 0.9, -hz), Vec3(x + 0.2, height - 0.5, hz));
  // Two rows of columns, each on a plinth.
  const int columns = 12;
  for (const double x : {-0.3 * width, 0.3 * width}) {
    for (int c = 0; c < columns; ++c) {
      const double z = -hz + length * (c + 0.5) / columns;
      addBox(m, Vec3(x - 0.35, 0, z - 0.35), Vec3(x + 0.35, 0.3, z + 0.35));
      addBox(m, Vec3(x - 0.2, 0.3, z - 0.2), Vec3(x + 0.2, height - 0.9, z + 0.2));
    }
  }
  // Stairs at the far end (negative z), rising to a landing against the wall.
  const int steps = 16;
  const double rise = 0.6 * height / steps, run = 0.3, stairWidth = 0.3 * width;
  for (int s = 0; s < steps; ++s) {
    const double z1 = -hz + run * (steps - s);
    addBox(m, Vec3(-0.5 * stairWidth, 0, -hz), Vec3(0.5 * stairWidth, rise * (s + 1), z1));
  }
  return m;
}

MeshData makeMengerSponge(const Vec3& center, double size, int level) {
  MeshData m;
  // Each cube of the sponge: keep the 20 of its 27 sub-cubes that are not
  // at the centre of a face or of the whole.
  const auto build = [&](auto&& self, const Vec3& min, double side, int depth) -> void {
    if (depth == 0) {
      addBox(m, min, min + Vec3(side));
      return;
    }
    const double third = side / 3.0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
          if ((i == 1) + (j == 1) + (k == 1) < 2)
            self(self, min + third * Vec3(i, j, k), third, depth - 1);
  };
  build(build, center - Vec3(0.5 * size), size, level);
  return m;
}

}  // namespace meshtrace
