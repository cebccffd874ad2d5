// A scene as geometry: axis-aligned boxes (the ground is one), optionally a
// model's triangles (scene/model.h), and the area light (SPEC §4.7) with its
// view and projection; and a CPU ray caster that gives the box scenes' shadow
// map's definition — the linear light depth of the nearest surface through each
// texel centre — independently of rasterisation. The analytic casters below
// see the boxes only, never the mesh: they are the box scenes' independent
// check; a model scene's is the brute-force triangle caster over triangles()
// (scene/triangle_visibility_reference.h).
#pragma once

#include <glm/glm.hpp>
#include <limits>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "scene/light_model.h"
#include "scenes.h"

namespace pn {

struct Box {
  glm::vec3 lo, hi;
};

// A part of a scene that may move on its own (issue 13, scene/animated_scene.h):
// a run of triangles() vertices and the transform that placed them this frame.
// A shadow-map cache calls an object dynamic in a frame when its transform
// differs from the previous frame's, static otherwise.
struct SceneObject {
  int first_vertex = 0;
  int vertex_count = 0;
  glm::mat4 transform{1.0f};
};

// The G-buffer's camera: where it stands and looks, its vertical field of view and its
// near and far planes (square screen). The box scenes' is fixtures/scenes.h's.
struct SceneCamera {
  glm::vec3 eye{fixtures::kCameraPosition[0], fixtures::kCameraPosition[1], fixtures::kCameraPosition[2]};
  glm::vec3 target{0.0f};
  float fov_degrees = fixtures::kCameraFovDegrees;
  float near_plane = fixtures::kCameraNear;
  float far_plane = fixtures::kCameraFar;

  glm::mat4 view() const;  // looking from eye at target, +y up
};

// A directional light (issue 14, seed 003's sun): the direction its light travels and its
// angular diameter. Its soft-shadow width per unit of distance is spread() = 2 tan(theta / 2).
struct SunLight {
  glm::vec3 direction{0.0f, -1.0f, 0.0f};
  double angular_diameter_radians = 0.53 * 3.14159265358979 / 180.0;
  // The one orthographic map over the whole scene (fit_whole_scene_sun_map): the scene's
  // light view and projection when it is not cascaded.
  glm::mat4 view{1.0f}, projection{1.0f};

  double spread() const;
};

// What one shadow map is rendered and read with: the light's view and projection and the
// light model of its texels (the scene's own, or a cascade's).
struct MapLight {
  glm::mat4 view{1.0f}, projection{1.0f};
  LightModel light;
};

struct Scene {
  std::string name;
  std::vector<Box> boxes;  // boxes[0] is the ground slab
  std::vector<glm::vec3> mesh;  // a model's triangles, world space, 3 vertices each (empty for the box scenes)
  LightModel light;        // width, planes, field of view, shadow-map size
  glm::vec3 light_position{0.0f};
  std::vector<SceneObject> objects;  // in triangles() order; empty: the scene is one object that never moves
  SceneCamera camera;
  // Set: the light is the sun, `light` its whole-scene orthographic map (texel_world, spread),
  // and its techniques run on cascades (cascades/cascaded_frame.h); unset: the area light.
  std::optional<SunLight> sun;

  // Light space: the area light looks down −y from light_position, +x right, +z "up" in the
  // map; the sun's is its whole-scene map's (SunLight::view, projection).
  glm::mat4 light_view() const;
  glm::mat4 light_projection() const;  // OpenGL perspective (near/far from `light`) or the sun's orthographic
  MapLight map_light() const { return {light_view(), light_projection(), light}; }

  // The G-buffer's camera (`camera`), square screen.
  glm::mat4 camera_view() const;
  glm::mat4 camera_projection() const;

  // The bounding box of triangles().
  std::pair<glm::vec3, glm::vec3> bounds() const;

  // Triangles of every box, 36 vertices a box, counter-clockwise seen from
  // outside, followed by the mesh's (in the file's winding).
  std::vector<glm::vec3> triangles() const;
};

// The fixture called `name` (fixtures::kScenes); throws Error listing the names.
const fixtures::SceneFixture& find_scene_fixture(const std::string& name);

// Throws Error for N < 2 or a light that does not validate.
Scene make_scene(const fixtures::SceneFixture& fixture, int shadow_map_size);

// The scene with N×N shadow maps: the light's map size, and the sun's whole-scene map fitted
// again (light_by_sun) when it has one. Throws Error for N < 2.
Scene with_shadow_map_size(Scene scene, int shadow_map_size);

// Gives a scene the sun along `direction` with angular diameter `angular_diameter_radians`,
// and one orthographic N×N map over its whole bounds (light: spread, texel width, the depth
// range; sun->view, projection). Throws Error for a bad direction or diameter (0 < theta < 10 deg).
void light_by_sun(Scene& scene, const glm::vec3& direction, double angular_diameter_radians);

// Multiplies the scene's light width (the sun's angular diameter) by `factor` (wider penumbrae). Throws Error
// "<what> <factor>: expected a finite number > 0", or for a light that then does not validate.
void validate_light_width_factor(double factor, const char* what);
void scale_light_width(Scene& scene, double factor, const char* what);

// The widest area light the runner represents: the ray-traced truth shoots float rays (Embree)
// to points up to half the width from the light's centre, and Embree refuses a ray with a
// coordinate above 1.8e18 (FLT_LARGE; it aborts on one); 1e15 leaves room for where the light
// and the scene are (issue 26 B1). scale_light_width refuses a factor that passes it.
inline constexpr double kMaxLightWidth = 1e15;

// What a screen pixel sees, in the shadow map's terms (Step 2): the shadow-map
// position of the surface point through the pixel's centre, in texels
// (continuous: texel i spans [i, i + 1)), and its linear light depth.
struct Receiver {
  bool valid = false;  // the pixel sees a surface (project_to_light: the point is in front of the light)
  double u = 0, v = 0, depth = 0;
};

// The casters from here on see Scene::boxes only, not Scene::mesh.

// Where origin + t·direction, t in [0, t_max], enters box b (slab method); none if it misses.
std::optional<double> box_entry(const Box& b, const glm::dvec3& origin, const glm::dvec3& direction, double t_max);
// The part [t0, t1] of origin + t·direction with t in [t_min, t_max] inside the box (the slab
// method: t0 the entry, t1 the exit), or none. box_entry is its t0 from t_min = 0.
std::optional<std::pair<double, double>> box_span(const Box& b, const glm::dvec3& origin, const glm::dvec3& direction,
                                                  double t_min, double t_max);

struct SurfacePoint {
  glm::dvec3 position;
  int box = -1;  // index into Scene::boxes
};

// The ray from the camera through the centre of pixel (x, y) of a size×size
// screen (x, y from the lower left), from the camera's matrices alone
// (`inverse_view_projection` = inverse(P · V), in double): from the near plane
// (t = 0) to the far plane (t = 1).
struct CameraRay {
  glm::dvec3 origin, direction;
};
CameraRay camera_ray(const glm::dmat4& inverse_view_projection, int x, int y, int size);

// Where the ray from the camera through the centre of pixel (x, y) of a
// size×size screen (x, y from the lower left) first meets a box, within the
// camera's near and far planes; none when it meets nothing.
std::optional<SurfacePoint> ray_cast_surface_point(const Scene& scene, int x, int y, int size);

// A world point in the shadow map's terms (u, v in texels, linear light
// depth); valid when it lies in front of the light.
Receiver project_to_light(const Scene& scene, const glm::dvec3& point);

// The G-buffer's definition: the surface point of pixel (x, y) projected into
// the shadow map (ray_cast_surface_point, project_to_light).
Receiver ray_cast_receiver(const Scene& scene, int x, int y, int size);

// Whether a G-buffer value (u, v, light depth) names a point on some box's
// surface (within `tolerance` world units) that the camera sees within one
// pixel of pixel (x, y)'s centre: what a pixel on a silhouette may hold.
bool receiver_on_surface_near_pixel(const Scene& scene, double u, double v, double depth, int x, int y, int size,
                                    double tolerance);

// Linear light depth (distance along the light's axis) of the nearest box
// surface through the centre of shadow-map texel (x, y) — x, y counted from
// the framebuffer's lower left, as glReadPixels returns them — or +Inf.
float ray_cast_light_depth(const Scene& scene, int x, int y);
// The map's second layer through texel (x, y)'s centre, by ray casting (issue 42): with
// `back_faces` the nearest box exit (the nearest surface facing away from the light), else the
// nearest surface whose depth passes the first's by more than `margin` of it (depth peeling);
// +Inf when none.
float ray_cast_second_layer(const Scene& scene, int x, int y, bool back_faces, double margin);

}  // namespace pn
