// A scene that moves (issue 13): fixtures/animated_scenes.h's boxes and
// model on the ground, moved frame by frame by the seed's motion function P.
// Every `period` frames P draws which movable objects move until its next
// call — objects in a seeded order, taken while the moving triangles stay
// nearest to K of all movable triangles — so objects start and stop; a moving
// object keeps its own seeded velocity (boxes cross each other and leave the
// map past kAnimatedWrap, coming back on the other side), the model turns as
// it goes. Frame 0 is every object at its home; frame f >= 1 has moved the
// objects that P chose for frames ((f - 1) / period) · period + 1 … .
#pragma once

#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

#include "animated_scenes.h"
#include "scene/scene.h"

namespace pn {

// The fixture called `name`; throws Error listing the names.
const fixtures::AnimatedSceneFixture& find_animated_scene_fixture(const std::string& name);

// The model an animated scene carries: `chosen`, or fixtures::kAnimatedModel when `chosen` is empty
// and that file exists, else none (empty: boxes only).
std::filesystem::path animated_scene_model(const std::filesystem::path& chosen);

// Throws Error unless the model `chosen` names (if any) loads: what a command calls before it makes
// a GL context or an output directory, so a bad file is refused first (issue 26 B13).
void validate_animated_scene_model(const std::filesystem::path& chosen);

// Throws Error unless 0 <= k <= 1 (named `what`).
void validate_moving_share(double k, const char* what);

class AnimatedScene {
 public:
  // `model` empty: boxes only. Throws Error for a bad K, N < 2, or a model that does not load.
  AnimatedScene(const fixtures::AnimatedSceneFixture& fixture, double k, int map_size,
                const std::filesystem::path& model);

  // Frame f >= 0 as a Scene: world-space boxes and mesh, and Scene::objects (the ground, each box, the
  // model) with this frame's transforms. Frames may be asked for in any order.
  Scene frame(int f);

  int movable_triangles() const { return movable_triangles_; }
  // The triangles of the objects P sets moving for frame f (0 for frame 0).
  int moving_triangles(int f);
  // moving_triangles(f) / movable_triangles() (0 without movable triangles).
  double moving_share(int f);

 private:
  struct Mover {
    glm::vec3 velocity;
    int triangles;
  };
  void step_to(int f);
  std::vector<bool> draw_movers(int epoch) const;

  fixtures::AnimatedSceneFixture fixture_;
  double k_;
  Scene base_;                       // frame 0 without the model, and the light
  std::vector<glm::vec3> model_;     // the model in its own space: footprint centred on the origin, lowest y 0
  glm::vec3 model_home_{0.0f};
  std::vector<Mover> movers_;        // the boxes (scene boxes 1…), then the model
  int movable_triangles_ = 0;
  // The simulation's state at frame_: each mover's offset from home (and the model's turn).
  int frame_ = 0;
  std::vector<glm::vec3> offsets_;
  float model_turn_degrees_ = 0.0f;
  std::vector<bool> moving_;  // P's draw for frame_
};

}  // namespace pn
