#include "viewer/model/inspector_report.h"

#include <cstdarg>
#include <cstdio>

#include "viewer/model/face_label.h"

namespace meshtrace::viewer {

namespace {
using Describe = std::function<std::string(const PrimitiveRef&)>;

__attribute__((format(printf, 1, 2))) std::string printed(const char* format, ...) {
  char text[256];
  va_list args;
  va_start(args, format);
  std::vsnprintf(text, sizeof text, format, args);
  va_end(args);
  return text;
}

class Lines {
 public:
  explicit Lines(std::vector<InspectorLine>& out) : out_(out) {}
  void add(std::string text, LineTone tone = LineTone::Plain) {
    out_.push_back({{}, std::move(text), tone, false});
  }
  void vec(const char* label, const Vec3& v) {
    add(printed("%-14s (%.5f, %.5f, %.5f)", label, v.x, v.y, v.z));
  }
  void color(const char* label, const Color& c) {
    add(printed("%-14s (%.4f, %.4f, %.4f)", label, c.r, c.g, c.b));
  }
  std::vector<InspectorLine>& out() { return out_; }

 private:
  std::vector<InspectorLine>& out_;
};

void addSurface(Lines& lines, const SurfaceRecord& s, const Describe& describe) {
  lines.add("hit           " + describe(s.ref));
  const bool mesh = s.ref.kind == ObjectKind::Mesh;
  if (mesh) {
    lines.add(printed("triangle      %u", s.ref.triangle) + faceSuffix(s.ref.triangle, s.face));
  }
  lines.add(printed("t             %.6f", s.t));
  lines.vec("point", s.point);
  if (!mesh) {
    lines.vec("normal", s.shadingNormal);
    return;
  }
  lines.add(printed("barycentrics  a %.5f  b %.5f  g %.5f", s.alpha, s.beta, s.gamma));
  lines.vec("flat normal", s.geometricNormal);
  if (s.hasVertexNormals)
    for (int k = 0; k < 3; ++k) lines.vec(printed("vertex n%d", k).c_str(), s.vertexNormals[k]);
  if (s.phong) {
    lines.vec("interpolated", s.shadingNormal);
    lines.add(printed("flat vs interpolated: %.4f deg", s.normalAngleDegrees));
  } else {
    lines.add("FLAT: shading uses the flat normal", LineTone::Dim);
  }
}

void addLights(Lines& lines, const BounceRecord& b, const Describe& describe) {
  lines.color("ambient", b.ambient);
  for (const LightRecord& l : b.lights) {
    InspectorLine line{printed("light %zu  n.l %.3f ", l.light, l.nDotL), "lit", LineTone::Plain};
    if (!l.facing) {
      line.text = "behind the surface: no shadow ray";
      line.tone = LineTone::Dim;
    } else if (l.shadowed) {
      line.text = "shadowed";
      if (l.blocker) line.text += " by " + describe(*l.blocker) + printed(" at t %.4g", l.blockerT);
      line.tone = LineTone::Alert;
    }
    lines.out().push_back(std::move(line));
    if (l.facing && !l.shadowed) {
      lines.add(printed("   diffuse (%.4f, %.4f, %.4f)", l.diffuse.r, l.diffuse.g, l.diffuse.b));
      lines.add(
          printed("   specular (%.4f, %.4f, %.4f)", l.specular.r, l.specular.g, l.specular.b));
    }
  }
}

InspectorBounce bounce(const BounceRecord& b, const Describe& describe) {
  InspectorBounce out;
  out.title = b.level == 0 ? std::string("primary ray")
                           : printed("reflection %d (weight %.3f)", b.level, b.weight);
  Lines lines(out.lines);
  lines.vec("ray origin", b.ray.origin);
  lines.vec("ray direction", b.ray.direction);
  if (!b.hit) {
    lines.add("miss: background");
  } else {
    addSurface(lines, b.surface, describe);
    addLights(lines, b, describe);
    lines.color("local", b.local);
    if (b.reflects)
      lines.add(printed("mirror %.3f: (1 - m) local + m reflected; carries %.3f of the pixel",
                        b.mirror, b.weight));
    else if (b.mirror > 0)
      lines.add(printed("mirror %.3f, but the depth limit is reached", b.mirror), LineTone::Dim);
  }
  lines.color("returns", b.color);
  if (b.boxes.empty()) {
    lines.add("entered no mesh box", LineTone::Dim);
    return out;
  }
  lines.add("mesh boxes entered:");
  for (const BoxRecord& box : b.boxes) {
    lines.add(describe(PrimitiveRef{ObjectKind::Mesh, box.mesh, 0}) +
              printed("  t %.4g .. %.4g", box.tEnter, box.tExit));
    lines.out().back().bullet = true;
  }
  return out;
}
}  // namespace

InspectorReport inspectorReport(const PixelInspection& in, int x, int y, bool pinned,
                                const Describe& describe) {
  InspectorReport r;
  r.pixel = printed("pixel (%d, %d)%s  y = 0 is the bottom row", x, y, pinned ? " pinned" : "");
  r.color = in.color;
  r.summary =
      printed("colour (%.4f, %.4f, %.4f)  rays: %llu shadow, %llu reflection", in.color.r,
              in.color.g, in.color.b, static_cast<unsigned long long>(in.counters.shadowRays),
              static_cast<unsigned long long>(in.counters.reflectionRays));
  for (const BounceRecord& b : in.bounces) r.bounces.push_back(bounce(b, describe));
  return r;
}

std::string reportText(const InspectorReport& report) {
  std::string text = report.pixel + "\n" + report.summary + "\n";
  for (const InspectorBounce& b : report.bounces) {
    text += "> " + b.title + "\n";
    for (const InspectorLine& line : b.lines)
      text += std::string(line.bullet ? "    - " : "    ") + line.lead + line.text + "\n";
  }
  return text;
}

}  // namespace meshtrace::viewer
