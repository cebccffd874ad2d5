// The scene the example draws: a model on a ground slab under a square area
// light, seen by one camera. Every number here mirrors the defaults of
// `penumbra render --model FILE` (runner/scene/model.cpp, scene.cpp,
// fixtures/scenes.h, frame/scene_frame.cpp, pipeline/pcss_settings.cpp,
// metrics/lit_image.h), so that this program's picture can be compared
// with the runner's (the `example_fast_pcss` test). They are the example's
// own constants: it links nothing of the runner. Your engine has its own.
#pragma once

#include <glm/glm.hpp>

namespace example {

// The ground: a slab [-10, 10] x [-1, 0] x [-10, 10] (world units, +y up);
// its top face at y = 0 is what the model stands on.
inline constexpr float kGroundHalfWidth = 10.0f;

// The model is scaled uniformly so that its bounding box's longest side is
// 8, centred over the origin in x and z, its lowest point at y = 0.
inline constexpr float kModelFitSide = 8.0f;

// The light: a square area light of width 3 centred 20 above the origin,
// facing straight down (-y). Its shadow map is a perspective view from the
// light's centre: 60 degrees, near 9, far 40, 512 x 512 texels, storing the
// LINEAR light depth (distance along the light's axis), which is what the
// Fast PCSS module expects (light_model.glsl).
inline constexpr glm::vec3 kLightPosition{0.0f, 20.0f, 0.0f};
inline constexpr glm::vec3 kLightDirection{0.0f, -1.0f, 0.0f};
inline constexpr glm::vec3 kLightMapUp{0.0f, 0.0f, -1.0f};  // the map's +v axis in world space
inline constexpr float kLightWidth = 3.0f;
inline constexpr float kLightNear = 9.0f;
inline constexpr float kLightFar = 40.0f;
inline constexpr double kLightFovRadians = 60.0 * 3.14159265358979 / 180.0;
inline constexpr int kShadowMapSize = 512;

// The camera: at (0, 13, 17) looking at the origin, 55 degrees vertical
// field of view, near 1, far 60, square screen (512 x 512 by default).
inline constexpr glm::vec3 kCameraEye{0.0f, 13.0f, 17.0f};
inline constexpr glm::vec3 kCameraTarget{0.0f, 0.0f, 0.0f};
inline constexpr float kCameraFovDegrees = 55.0f;
inline constexpr float kCameraNear = 1.0f;
inline constexpr float kCameraFar = 60.0f;
inline constexpr int kDefaultScreenSize = 512;

// Shadow settings: the depth bias (light-depth units) that
// pnFastPcssDefaults takes, and the normal offset: each receiver is moved
// 1.5 shadow-map texels off its face before it is projected, so that faces
// the light sees edge-on do not shadow themselves in stripes.
inline constexpr float kDepthBias = 0.02f;
inline constexpr float kNormalOffsetTexels = 1.5f;

// Shading: albedo x (ambient + (1 - ambient) x max(N.L, 0) x visibility);
// the sky where nothing is drawn.
inline constexpr glm::vec3 kGroundAlbedo{0.80f, 0.80f, 0.78f};
inline constexpr glm::vec3 kModelAlbedo{0.85f, 0.55f, 0.30f};
inline constexpr float kAmbient = 0.25f;
inline constexpr glm::vec3 kSkyColour{0.62f, 0.75f, 0.90f};

}  // namespace example
