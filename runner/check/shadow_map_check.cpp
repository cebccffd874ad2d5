// Cases of the shadow_map check (Steps 1 and 2 on the scenes): each scene's
// rasterised shadow map of linear light depth against a CPU ray cast through
// every texel centre, and its G-buffer (shadow-map u, v, light depth, valid)
// against a ray cast from the camera through every pixel centre, both with
// the silhouette rule of check/raster_compare.h; and the map's two second layers
// (depth peeling, back faces) against the rays' next surfaces.
#include <string>

#include "check/module_check.h"
#include "check/raster_compare.h"
#include "gl/texture.h"
#include "pass_runners/gbuffer_pass.h"
#include "pass_runners/shadow_map_pass.h"
#include "scene/scene.h"

namespace pn {
namespace {

constexpr double kRelative = 1e-5;  // a few float roundings of interpolated, projected values
constexpr double kSliver = 1e-4;    // extrapolation on edge-on faces from 1/256-pixel vertex snapping
constexpr double kSurface = 1e-3;   // world units: a float G-buffer value back-projected onto a face

}  // namespace

std::vector<CaseResult> run_shadow_map_check(const CheckEnvironment& env) {
  const ShadowMapRenderer shadow_map(env.device, env.tree);
  const ShadowMapRenderer peeled(env.device, env.tree, MapLayer::peeled);
  const ShadowMapRenderer back_faces(env.device, env.tree, MapLayer::back_faces);
  const GBufferRenderer gbuffer(env.device, env.tree);
  std::vector<CaseResult> results;
  for (const auto& fixture : check_scenes(env)) {
    for (int n : {100, 256}) {
      const Scene scene = make_scene(fixture, n);
      const std::string name = std::string(fixture.name) + " " + std::to_string(n) + "x" + std::to_string(n);
      Image expected(n, n);
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) expected.at(x, y) = ray_cast_light_depth(scene, x, y);
      const std::unique_ptr<DeviceTexture> map = shadow_map.render_texture(scene, scene.map_light());
      const Image observed = env.device.read_texture(*map);
      for (CaseResult& c : compare_raster(name + " shadow map: light depth vs ray cast", expected, observed, kRelative,
                                          within_neighbour_range(expected, observed, kSliver),
                                          "lies within its 3x3 rays' depths"))
        results.push_back(std::move(c));
      // Its second layers (issue 42): the nearest surface behind it, the nearest back face.
      for (const ShadowMapRenderer* layer : {&peeled, &back_faces}) {
        const bool back = layer == &back_faces;
        Image second(n, n);
        for (int y = 0; y < n; ++y)
          for (int x = 0; x < n; ++x)
            second.at(x, y) = ray_cast_second_layer(scene, x, y, back, ShadowMapRenderer::peel_margin());
        const Image drawn = env.device.read_texture(*layer->render_texture(scene, scene.map_light(), map.get()));
        // On a silhouette the texel may hold a face the ray through its centre misses: a wall seen
        // edge-on spans from the first layer's depths to the second's.
        const SilhouetteRule of_second = within_neighbour_range(second, drawn, kSliver);
        const SilhouetteRule of_first = within_neighbour_range(expected, drawn, kSliver);
        for (CaseResult& c : compare_raster(name + " " + map_layer_name(layer->layer()) + " second layer: light depth vs "
                                                "ray cast",
                                            second, drawn, kRelative,
                                            [&](int x, int y) { return of_second(x, y) || of_first(x, y); },
                                            "lies within its 3x3 rays' depths of either layer"))
          results.push_back(std::move(c));
      }

      const int screen = n;  // screen as large as the map
      Image receivers(screen, screen, 4);
      for (int y = 0; y < screen; ++y)
        for (int x = 0; x < screen; ++x) {
          const Receiver r = ray_cast_receiver(scene, x, y, screen);
          const float v[4] = {float(r.u), float(r.v), float(r.depth), r.valid ? 1.0f : 0.0f};
          for (int c = 0; c < 4; ++c) receivers.at(x, y, c) = r.valid ? v[c] : 0.0f;
        }
      const Image seen = env.device.read_texture(*gbuffer.render_texture(scene, screen, 0.0f, scene.map_light()));
      // On a silhouette the pixel may see another surface than the ray through its
      // centre: background only if a neighbouring ray does, else a point on a box
      // that the camera sees within one pixel of the centre.
      const SilhouetteRule seen_near = [&](int x, int y) {
        if (seen.at(x, y, 3) == 0.0f) return within_neighbour_range(receivers, seen, kSliver)(x, y);
        return receiver_on_surface_near_pixel(scene, seen.at(x, y, 0), seen.at(x, y, 1), seen.at(x, y, 2), x, y, screen,
                                              kSurface);
      };
      for (CaseResult& c : compare_raster(name + " G-buffer: (u, v, light depth, valid) vs camera ray cast", receivers,
                                          seen, kRelative, seen_near, "shows a surface point within a pixel of it"))
        results.push_back(std::move(c));
    }
  }
  return results;
}

}  // namespace pn
