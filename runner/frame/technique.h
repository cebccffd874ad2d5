// The seam every shadow technique plugs into (SPEC §4.9): a technique turns
// one frame's inputs — the shadow map a ShadowMapSource made, the G-buffer
// and the light — into a visibility image, with its per-stage GPU times and
// its stats. render, bench and check drive techniques only through this
// interface and the registry (technique_registry.h); none of them knows which
// technique it runs.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <typeindex>
#include <utility>
#include <vector>

#include "device/query_device.h"
#include "pass_runners/cascade_blend_pass.h"
#include "pass_runners/second_layer_pass.h"
#include "pass_runners/shade_pass.h"
#include "scene/light_model.h"
#include "shader/source_tree.h"

namespace pn {

struct MinMaxMipChain;  // pass_runners/minmax_mip_pass.h
struct DepthPyramid;    // pass_runners/depth_pyramid_pass.h
struct CascadeInputs;   // below

// What a technique reads for one frame (non-owning: see SceneFrame).
struct TechniqueInputs {
  LightModel light;
  int screen_size = 0;
  const DeviceTexture* shadow_map = nullptr;  // N×N R32F linear light depth, +Inf where empty (N = light.map_size)
  const DeviceTexture* gbuffer = nullptr;     // screen² RGBA32F (u, v in texels, light depth, valid), rows from the bottom
  // The map's structures when the source keeps them up to date (a cache updates them where the map
  // changed); null: a technique that reads one builds its own from shadow_map.
  const MinMaxMipChain* mip = nullptr;
  const DepthPyramid* pyramid = nullptr;
  // Set when the frame is cascaded (cascades/cascaded_frame.h): what CascadedTechnique runs its
  // technique on, once a cascade; a technique itself reads only the fields above.
  const CascadeInputs* cascades = nullptr;
  // The stage the technique's one call runs in: a compute pass, or a fragment shader as a deferred
  // lighting pass runs it (the fragment-stage check; only for a technique with one, has_one_call()).
  ShadeStage stage = ShadeStage::compute;
  // The map's second layers that the frame drew (those its techniques ask for:
  // TechniqueConfig::second_layer).
  SecondLayers second_layers = {};
};

// A cascaded frame's layers: each cascade's map, G-buffer and light as one TechniqueInputs, and
// what blends their visibilities (cascades.glsl, pass_runners/cascade_blend_pass.h).
struct CascadeInputs : CascadeBlend {
  std::vector<TechniqueInputs> layers;  // nearest cascade first, at most PN_CASCADES_MAX
};

// Named values, in the order they are printed.
using NamedValues = std::vector<std::pair<std::string, double>>;

struct TechniqueFrame {
  std::unique_ptr<DeviceTexture> visibility;  // screen² R32F, rows from the bottom: 1 lit, 0 in shadow
  NamedValues stages;   // GPU ms per stage, in order (timestamps between them)
  NamedValues stats;    // what the frame did (e.g. "representatives", "work/px"); filled when asked
  double total_ms() const;
};

// A configured technique, bound to one device (a GL context, a Vulkan device).
class Technique {
 public:
  virtual ~Technique() = default;
  // One frame. `with_stats`: also count the frame's stats (a readback, after the last timestamp).
  // Throws Error for inputs it cannot take.
  virtual TechniqueFrame run(const TechniqueInputs& inputs, bool with_stats) const = 0;
  // Whether its visibility comes from one call per pixel (so it runs in either ShadeStage); false
  // for the ablations that need neighbours (reuse, blur) or a staged structure.
  virtual bool has_one_call() const { return true; }
};

// Device resources that techniques of one family share (compiled passes, tables),
// built once per device on first use and owned here, not in globals.
class TechniqueResources {
 public:
  TechniqueResources(const QueryDevice& device, const SourceTree& tree) : device_(&device), tree_(&tree) {}
  const QueryDevice& device() const { return *device_; }
  const SourceTree& tree() const { return *tree_; }

  // The one T of these resources, constructed as T(device, tree) the first time it is asked for.
  template <class T>
  const T& shared() {
    std::shared_ptr<void>& slot = shared_[std::type_index(typeid(T))];
    if (!slot) slot = std::make_shared<T>(*device_, *tree_);
    return *static_cast<const T*>(slot.get());
  }

 private:
  const QueryDevice* device_;
  const SourceTree* tree_;
  std::map<std::type_index, std::shared_ptr<void>> shared_;
};

// A technique's settings before any device: made by a registry entry, changed by
// its own override keys, validated on the command line before a context exists.
class TechniqueConfig {
 public:
  virtual ~TechniqueConfig() = default;
  virtual std::string name() const = 0;  // as the user wrote it, overrides included ("fast:leaf=4")
  virtual void rename(const std::string& name) = 0;
  virtual std::vector<std::string> keys() const = 0;  // the override keys it owns
  // Throws Error naming the technique, the key and what it expects.
  virtual void set(const std::string& key, const std::string& value) = 0;
  virtual void validate() const = 0;  // throws Error naming the setting and its range
  virtual std::unique_ptr<Technique> create(TechniqueResources& resources) const = 0;
  virtual std::unique_ptr<TechniqueConfig> clone() const = 0;
  // The second layer of the map it reads (issue 42), which the frame then draws; none for most.
  virtual std::optional<MapLayer> second_layer() const { return std::nullopt; }
};

// The second layers `configs` ask for, each once, in MapLayer order.
std::vector<MapLayer> second_layers_of(const std::vector<const TechniqueConfig*>& configs);

}  // namespace pn
