#include "truth/embree_scene.h"

#include <embree3/rtcore.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "core/error.h"

namespace pn {
namespace {

const char* error_name(RTCError code) {
  switch (code) {
    case RTC_ERROR_NONE: return "no error";
    case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
    case RTC_ERROR_CANCELLED: return "cancelled";
    default: return "unknown error";
  }
}

// The first error Embree reports while the scene is built (its callback's user data).
struct FirstError {
  std::string message;
  static void record(void* self, RTCError code, const char* text) {
    auto& first = static_cast<FirstError*>(self)->message;
    if (first.empty()) first = std::string(error_name(code)) + (text != nullptr ? std::string(": ") + text : "");
  }
};

RTCRay make_ray(const glm::dvec3& origin, const glm::dvec3& direction, double t_max) {
  RTCRay ray{};
  ray.org_x = static_cast<float>(origin.x), ray.org_y = static_cast<float>(origin.y);
  ray.org_z = static_cast<float>(origin.z);
  ray.dir_x = static_cast<float>(direction.x), ray.dir_y = static_cast<float>(direction.y);
  ray.dir_z = static_cast<float>(direction.z);
  ray.tnear = 0.0f;
  ray.tfar = static_cast<float>(t_max);
  ray.mask = 0xffffffffu;
  ray.flags = 0;
  return ray;
}

}  // namespace

EmbreeScene::EmbreeScene(const std::vector<glm::vec3>& triangles) {
  if (triangles.size() % 3 != 0)
    throw Error("ray-traced truth: " + std::to_string(triangles.size()) + " triangle vertices: expected a multiple of 3");
  for (const glm::vec3& v : triangles)
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
      throw Error("ray-traced truth: a triangle vertex is not finite: expected finite coordinates");
  device_ = rtcNewDevice(nullptr);
  if (device_ == nullptr)
    throw Error(std::string("embree: cannot create a device: ") + error_name(rtcGetDeviceError(nullptr)));
  FirstError first;
  rtcSetDeviceErrorFunction(device_, &FirstError::record, &first);
  scene_ = rtcNewScene(device_);
  if (scene_ != nullptr) {
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    const size_t count = triangles.size() / 3;
    if (count > 0) {
      RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
      if (geometry != nullptr) {
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), triangles.size()));
        auto* indices = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), count));
        if (vertices != nullptr && indices != nullptr) {
          for (size_t i = 0; i < triangles.size(); ++i) {
            vertices[3 * i] = triangles[i].x, vertices[3 * i + 1] = triangles[i].y, vertices[3 * i + 2] = triangles[i].z;
            indices[i] = static_cast<unsigned>(i);  // triangle k is vertices 3k, 3k + 1, 3k + 2
          }
          rtcCommitGeometry(geometry);
          rtcAttachGeometry(scene_, geometry);
        }
        rtcReleaseGeometry(geometry);  // the scene holds its own reference
      }
    }
    rtcCommitScene(scene_);
  }
  rtcSetDeviceErrorFunction(device_, nullptr, nullptr);
  if (scene_ == nullptr || !first.message.empty()) {
    const std::string message = first.message.empty() ? "cannot create a scene" : first.message;
    release();
    throw Error("embree: " + message);
  }
}

EmbreeScene::~EmbreeScene() { release(); }

EmbreeScene::EmbreeScene(EmbreeScene&& other) noexcept
    : device_(std::exchange(other.device_, nullptr)), scene_(std::exchange(other.scene_, nullptr)) {}

EmbreeScene& EmbreeScene::operator=(EmbreeScene&& other) noexcept {
  if (this != &other) {
    release();
    device_ = std::exchange(other.device_, nullptr);
    scene_ = std::exchange(other.scene_, nullptr);
  }
  return *this;
}

void EmbreeScene::release() noexcept {
  if (scene_ != nullptr) rtcReleaseScene(scene_);
  if (device_ != nullptr) rtcReleaseDevice(device_);
  scene_ = nullptr, device_ = nullptr;
}

std::optional<EmbreeScene::Hit> EmbreeScene::nearest(const glm::dvec3& origin, const glm::dvec3& direction,
                                                     double t_max) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit query{};
  query.ray = make_ray(origin, direction, t_max);
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  query.hit.primID = RTC_INVALID_GEOMETRY_ID;
  query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &query);
  if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  return Hit{query.ray.tfar, query.hit.primID};
}

bool EmbreeScene::blocked(const glm::dvec3& origin, const glm::dvec3& direction, double t_max) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray = make_ray(origin, direction, t_max);
  rtcOccluded1(scene_, &context, &ray);
  return ray.tfar == -std::numeric_limits<float>::infinity();  // Embree's mark of an occluded ray
}

}  // namespace pn
