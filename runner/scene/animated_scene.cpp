#include "scene/animated_scene.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "core/format.h"
#include "core/integer_hash.h"
#include "core/named.h"
#include "core/seeded_random.h"
#include "scene/model.h"

namespace pn {

const fixtures::AnimatedSceneFixture& find_animated_scene_fixture(const std::string& name) {
  return find_named(fixtures::kAnimatedScenes, name, "animated scene '" + name + "'");
}

std::filesystem::path animated_scene_model(const std::filesystem::path& chosen) {
  if (!chosen.empty()) return chosen;
  return std::filesystem::exists(fixtures::kAnimatedModel) ? fixtures::kAnimatedModel : "";
}

void validate_animated_scene_model(const std::filesystem::path& chosen) {
  if (!chosen.empty()) load_model_triangles(chosen);
}

void validate_moving_share(double k, const char* what) {
  if (!(k >= 0.0 && k <= 1.0)) throw Error(std::string(what) + " " + format_shortest(k) + ": expected 0 <= K <= 1");
}

AnimatedScene::AnimatedScene(const fixtures::AnimatedSceneFixture& fixture, double k, int map_size,
                             const std::filesystem::path& model)
    : fixture_(fixture), k_(k) {
  validate_moving_share(k, "moving share K");
  const fixtures::SceneFixture ground_only{fixture.name, fixtures::SceneKind::random_boxes, 0, 0, fixture.light_width};
  base_ = make_scene(ground_only, map_size);
  SeededRandom random(fixture.seed);
  const auto velocity = [&] {
    const float angle = random.uniform_float(0.0f, 6.2831853f);
    const float speed = random.uniform_float(fixtures::kAnimatedMinSpeed, fixtures::kAnimatedMaxSpeed);
    return glm::vec3(speed * std::cos(angle), 0.0f, speed * std::sin(angle));
  };
  const float home = fixtures::kAnimatedHome;
  for (int b = 0; b < fixture.boxes; ++b) {
    const float w = random.uniform_float(0.3f, 1.2f), d = random.uniform_float(0.3f, 1.2f);
    const float h = random.uniform_float(0.3f, 3.0f);
    const float x = random.uniform_float(-home, home), z = random.uniform_float(-home, home);
    base_.boxes.push_back({{x - w / 2, 0.0f, z - d / 2}, {x + w / 2, h, z + d / 2}});
    movers_.push_back({velocity(), 12});
  }
  if (!model.empty() && fixture.model_fit_side > 0.0f) {
    // The loader's placement (longest side kModelFitSide, footprint centred, on the ground), scaled to the fixture's size.
    model_ = place_model_on_ground(load_model_triangles(model), model);
    const float scale = fixture.model_fit_side / kModelFitSide;
    for (glm::vec3& v : model_) v *= scale;
    model_home_ = {random.uniform_float(-home / 2, home / 2), 0.0f, random.uniform_float(-home / 2, home / 2)};
    movers_.push_back({velocity(), static_cast<int>(model_.size() / 3)});
  }
  for (const Mover& m : movers_) movable_triangles_ += m.triangles;
  offsets_.assign(movers_.size(), glm::vec3(0.0f));
  moving_.assign(movers_.size(), false);
}

// P: the movers in an order drawn from (seed, epoch), each taken while it brings the moving
// triangles nearer to K of the movable ones.
std::vector<bool> AnimatedScene::draw_movers(int epoch) const {
  std::vector<int> order(movers_.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  SeededRandom random(integer_hash(fixture_.seed ^ integer_hash(static_cast<std::uint32_t>(epoch) + 1u)));
  for (size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[static_cast<size_t>(random.uniform_int(0, static_cast<int>(i) - 1))]);
  const double target = k_ * movable_triangles_;
  std::vector<bool> moving(movers_.size(), false);
  double taken = 0.0;
  for (int i : order) {
    const double with = taken + movers_[static_cast<size_t>(i)].triangles;
    if (std::abs(with - target) < std::abs(taken - target)) {
      moving[static_cast<size_t>(i)] = true;
      taken = with;
    }
  }
  return moving;
}

void AnimatedScene::step_to(int f) {
  if (f < 0) throw Error("frame " + std::to_string(f) + ": expected >= 0");
  if (f < frame_) {  // back to the start
    frame_ = 0;
    offsets_.assign(movers_.size(), glm::vec3(0.0f));
    model_turn_degrees_ = 0.0f;
    moving_.assign(movers_.size(), false);
  }
  const float wrap = fixtures::kAnimatedWrap;
  const auto wrapped = [&](float home, float offset) {
    const float p = home + offset;
    return p > wrap ? offset - 2 * wrap : p < -wrap ? offset + 2 * wrap : offset;
  };
  while (frame_ < f) {
    ++frame_;
    const int period = std::max(fixture_.period, 1);
    if ((frame_ - 1) % period == 0) moving_ = draw_movers((frame_ - 1) / period);
    for (size_t i = 0; i < movers_.size(); ++i) {
      if (!moving_[i]) continue;
      glm::vec3& o = offsets_[i];
      o += movers_[i].velocity;
      const bool model = i >= base_.boxes.size() - 1;
      const glm::vec3 centre = model ? model_home_ : 0.5f * (base_.boxes[i + 1].lo + base_.boxes[i + 1].hi);
      o.x = wrapped(centre.x, o.x);
      o.z = wrapped(centre.z, o.z);
      if (model) model_turn_degrees_ += fixtures::kAnimatedModelTurnDegrees;
    }
  }
}

int AnimatedScene::moving_triangles(int f) {
  step_to(f);
  if (f == 0) return 0;
  int n = 0;
  for (size_t i = 0; i < movers_.size(); ++i)
    if (moving_[i]) n += movers_[i].triangles;
  return n;
}

double AnimatedScene::moving_share(int f) {
  const int moving = moving_triangles(f);
  return movable_triangles_ > 0 ? static_cast<double>(moving) / movable_triangles_ : 0.0;
}

Scene AnimatedScene::frame(int f) {
  step_to(f);
  Scene scene = base_;
  scene.objects.push_back({0, 36, glm::mat4(1.0f)});  // the ground
  for (size_t b = 1; b < scene.boxes.size(); ++b) {
    const glm::vec3 o = offsets_[b - 1];
    scene.boxes[b].lo += o;
    scene.boxes[b].hi += o;
    scene.objects.push_back({static_cast<int>(36 * b), 36, glm::translate(glm::mat4(1.0f), o)});
  }
  if (!model_.empty()) {
    const glm::mat4 transform =
        glm::rotate(glm::translate(glm::mat4(1.0f), model_home_ + offsets_.back()), glm::radians(model_turn_degrees_),
                    glm::vec3(0.0f, 1.0f, 0.0f));
    scene.mesh.reserve(model_.size());
    for (const glm::vec3& v : model_) scene.mesh.push_back(glm::vec3(transform * glm::vec4(v, 1.0f)));
    scene.objects.push_back({static_cast<int>(36 * scene.boxes.size()), static_cast<int>(model_.size()), transform});
  }
  return scene;
}

}  // namespace pn
