// docs/images/cascades_splits.png: the city camera's view frustum seen from
// above, split by the practical scheme (k = 1) and by the hybrid split with
// the first split enlarged (k = 3), each cascade's bounding sphere and the
// fitted slice's cross-sections; the whole frustum and its first 40 units.
// Drawn from the runner's fit (cascades/cascade_fit.h: glsl/cascades.h's text in C++).
#include <algorithm>
#include <cmath>
#include <string>

#include "cascades/cascade_fit.h"
#include "cascades/cascade_math.h"
#include "cascades/cascaded_frame.h"
#include "core/format.h"
#include "figures/figures.h"
#include "draw/font.h"
#include "scene/city_scene.h"

namespace pn {
namespace {

constexpr Rgb kInk{20, 20, 20};
constexpr Rgb kCascadeColours[4] = {{214, 39, 40}, {44, 160, 44}, {31, 119, 180}, {255, 127, 14}};

struct View {
  double x0, z0, scale;  // world (x0, z0) at the panel's centre; pixels per world unit
  int left, top, size;
  double px(double x) const { return left + 0.5 * size + (x - x0) * scale; }
  double py(double z) const { return top + 0.5 * size + (z - z0) * scale; }

  // The part of the segment inside the panel (Liang and Barsky), drawn.
  void line(Canvas& canvas, double x0w, double z0w, double x1w, double z1w, Rgb colour, int width, int dash = 0) const {
    double ax = px(x0w), ay = py(z0w), bx = px(x1w), by = py(z1w), t0 = 0, t1 = 1;
    const double dx = bx - ax, dy = by - ay;
    const double p[4] = {-dx, dx, -dy, dy}, q[4] = {ax - left, left + size - ax, ay - top, top + size - ay};
    for (int i = 0; i < 4; ++i) {
      if (p[i] == 0) {
        if (q[i] < 0) return;
        continue;
      }
      const double t = q[i] / p[i];
      if (p[i] < 0) t0 = std::max(t0, t);
      else t1 = std::min(t1, t);
      if (t0 > t1) return;
    }
    canvas.line(ax + t0 * dx, ay + t0 * dy, ax + t1 * dx, ay + t1 * dy, colour, width, dash);
  }
};

void draw_panel(Canvas& canvas, const Font& font, const View& v, const std::vector<Cascade>& cascades,
                const CascadeCamera& camera, const std::string& title) {
  canvas.fill(v.left, v.top, v.size, v.size, {250, 250, 250});
  canvas.outline(v.left, v.top, v.size, v.size, {160, 160, 160});
  canvas.text(font, v.left, v.top - 18, title, 13, kInk);
  const glm::dmat4 to_world = glm::inverse(glm::dmat4(camera.view));
  const glm::dvec3 eye(to_world[3]);
  // The frustum's left and right edges from above: its corners at the far plane.
  const auto far_corners = camera.corners_at(camera.far_plane);
  for (const glm::dvec3& c : far_corners) v.line(canvas, eye.x, eye.z, c.x, c.z, {120, 120, 120}, 1);
  for (size_t i = 0; i < cascades.size(); ++i) {
    const Cascade& c = cascades[i];
    const Rgb colour = kCascadeColours[i % 4];
    // The split's cross-section at C_(i+1) (the far corners' outline from above).
    const auto corners = camera.corners_at(c.split_far);
    for (size_t k = 0; k < corners.size(); ++k) {
      const glm::dvec3 &a = corners[k], &b = corners[(k + 1) % corners.size()];
      v.line(canvas, a.x, a.z, b.x, b.z, colour, 2);
    }
    // The bounding sphere of the fitted slice, from above: a circle about its centre.
    const glm::vec2 sphere =
        cascade_math::pnCascadeSliceSphere(c.fit_near, c.split_far, static_cast<float>(camera.tan_diagonal()));
    const glm::dvec3 centre = eye + glm::dvec3(to_world * glm::dvec4(0, 0, -sphere.x, 0));
    const int segments = 96;
    for (int s = 0; s < segments; ++s) {
      const double a0 = 2 * 3.14159265358979 * s / segments, a1 = 2 * 3.14159265358979 * (s + 1) / segments;
      v.line(canvas, centre.x + sphere.y * std::cos(a0), centre.z + sphere.y * std::sin(a0),
             centre.x + sphere.y * std::cos(a1), centre.z + sphere.y * std::sin(a1), colour, 1, 4);
    }
  }
  canvas.fill(static_cast<int>(v.px(eye.x)) - 3, static_cast<int>(v.py(eye.z)) - 3, 6, 6, kInk);
}

}  // namespace

Canvas cascades_splits_figure() {
  const Font font;
  const Scene scene = make_city_scene(fixtures::kCityScenes[0], 1024);
  const SceneCamera& city = scene.camera;
  const CascadeCamera camera = cascade_camera(city);
  const auto [lo, hi] = scene.bounds();
  const int panel = 360, gap = 40, top = 56;
  Canvas canvas(4 * panel + 5 * gap, panel + top + 70, {255, 255, 255});
  canvas.text(font, gap, 8, "The city camera's view frustum from above (+x right, +z down), 3 cascades: split ends and bounding spheres (dashed)", 14, kInk);
  int column = 0;
  for (double k : {1.0, 3.0}) {
    CascadeSettings settings;
    settings.count = 3, settings.enlargement = k;
    const std::vector<Cascade> cascades = fit_cascades(settings, camera, scene.sun->direction, lo, hi);
    std::string splits;
    for (const Cascade& c : cascades) splits += (splits.empty() ? "" : ", ") + format_number("%.1f", c.split_far);
    const glm::dvec3 eye(city.eye);
    const glm::dvec3 ahead = glm::normalize(glm::dvec3(city.target - city.eye));
    const std::string name = k == 1.0 ? "practical split (k = 1)" : "hybrid split (k = 3)";
    const View whole{eye.x + 200 * ahead.x, eye.z + 200 * ahead.z, panel / 560.0, gap + column * (panel + gap), top, panel};
    draw_panel(canvas, font, whole, cascades, camera, name + ": splits " + splits);
    ++column;
    const View near{eye.x + 20 * ahead.x, eye.z + 20 * ahead.z, panel / 56.0, gap + column * (panel + gap), top, panel};
    draw_panel(canvas, font, near, cascades, camera, name + ": the first 40 units");
    ++column;
  }
  for (int i = 0; i < 3; ++i) {
    canvas.fill(gap + i * 140, top + panel + 24, 14, 14, kCascadeColours[i]);
    canvas.text(font, gap + i * 140 + 20, top + panel + 22, "cascade " + std::to_string(i), 13, kInk);
  }
  return canvas;
}

}  // namespace pn
