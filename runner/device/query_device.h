// The executor seam of the query passes (architecture.md "Queries as textures"): a
// module's *_query.comp runs over a batch of queries on some device — an OpenGL 4.5 or ES 3.1
// context (gl/context.h), or a Vulkan device (vk/vulkan_device.h) — and nothing here names
// either. A query pass (pass_runners/query_pass.h) compiles through this interface, uploads its
// textures through it and dispatches through it, so one check runs on every executor. The passes
// that build structures (textures of levels and layers, storage buffers, a dispatch over a grid)
// and the raster passes (a triangle list drawn with depth testing) go through it the same way.
//
// Bindings are the numbers of glsl/passes/<pass>.h; a block is std140 bytes; the queries go up
// as RGBA32F images (query k at texel k, core/query_grid.h), the results come back as RGBA32F
// images or RGBA32UI words.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "core/image.h"
#include "core/query_grid.h"
#include "core/texel_rect.h"
#include "shader/loop_guard.h"
#include "shader/source_tree.h"
#include "shader/target.h"

namespace pn {

// The texel formats of what passes build: float maps, moments and structures (R32F, RG32F,
// RGBA32F) and exact sums (RGBA32UI).
enum class TexelFormat { r32f, rg32f, rgba32f, rgba32ui };
int texel_channels(TexelFormat format);  // 1, 2, 4, 4

// A texture a pass builds: `levels` mip levels (level i is max(1, size >> i) on each side) of
// `layers` layers; `array` makes it a 2-D array texture (sampler2DArray / image2DArray) even with
// one layer.
struct TextureShape {
  TexelFormat format = TexelFormat::rgba32f;
  int width = 0, height = 0;
  int levels = 1, layers = 1;
  bool array = false;
  int level_width(int level) const { return width >> level > 0 ? width >> level : 1; }
  int level_height(int level) const { return height >> level > 0 ? height >> level : 1; }
};

// A texture on one device, as a pass reads it (nearest filtering, clamped to the edge). Made by
// QueryDevice::upload or make_texture, or by a device's own passes (a GL pass's texture:
// gl/query_device_gl.h), which leave its shape unknown (width 0).
class DeviceTexture {
 public:
  virtual ~DeviceTexture() = default;
  explicit DeviceTexture(const TextureShape& shape = {}) : shape_(shape) {}
  DeviceTexture(const DeviceTexture&) = delete;
  DeviceTexture& operator=(const DeviceTexture&) = delete;
  const TextureShape& shape() const { return shape_; }

 private:
  TextureShape shape_;
};

// A storage buffer on one device (a list of texels, texel_list.h).
class DeviceBuffer {
 public:
  virtual ~DeviceBuffer() = default;
  DeviceBuffer() = default;
  DeviceBuffer(const DeviceBuffer&) = delete;
  DeviceBuffer& operator=(const DeviceBuffer&) = delete;
};

// Triangle corners (world positions, PN_SCENE_POSITION_LOCATION) in a vertex buffer on one device,
// kept for many draws (a cache's scene geometry).
class DeviceVertices {
 public:
  virtual ~DeviceVertices() = default;
  explicit DeviceVertices(int count) : count_(count) {}
  DeviceVertices(const DeviceVertices&) = delete;
  DeviceVertices& operator=(const DeviceVertices&) = delete;
  int count() const { return count_; }

 private:
  int count_;
};

// A run of vertices: what one draw call draws.
struct VertexRun {
  int first = 0, count = 0;
};

// A size × size texture of a float format with its own depth buffer, drawn into frame after
// frame (a cache's maps). Rows from the framebuffer's bottom, TexelRect rows likewise.
class DeviceRasterTarget {
 public:
  virtual ~DeviceRasterTarget() = default;
  DeviceRasterTarget() = default;
  DeviceRasterTarget(const DeviceRasterTarget&) = delete;
  DeviceRasterTarget& operator=(const DeviceRasterTarget&) = delete;
  virtual const DeviceTexture& texture() const = 0;  // the colour, as the passes read it
  int size() const { return texture().shape().width; }
};

// Where a pass reads its queries and writes its results (its header's binding numbers).
struct QueryBindings {
  std::vector<unsigned> inputs;        // a sampler per input image (a query's fields A, B, C, …)
  std::vector<unsigned> results;       // an RGBA32F image per result image
  std::vector<unsigned> word_results = {};  // an RGBA32UI image per result of exact words (sums modulo 2^64)
};

// A texture the pass reads besides its queries (a depth map, a pyramid, a table), at `binding`.
struct QueryTexture {
  unsigned binding;
  const DeviceTexture& texture;
};

// A pass's uniform block (a shared block of glsl/passes/<pass>.h: std140 layout, Block::binding);
// empty for a pass without one. It points at the block, which must outlive the dispatch.
struct QueryBlock {
  unsigned binding = 0;
  const void* data = nullptr;
  std::size_t size = 0;
};
template <class Block>
QueryBlock query_block(const Block& block) {
  return {Block::binding, &block, sizeof block};
}

// What a building pass writes: one level of a texture made by make_texture as a storage image
// (every layer of an array texture), write-only.
struct PassImage {
  unsigned binding;
  const DeviceTexture& texture;
  int level = 0;
};
struct PassBuffer {
  unsigned binding;
  const DeviceBuffer& buffer;
};
// Everything one dispatch of a building pass binds (its header's binding numbers).
struct PassResources {
  std::vector<QueryTexture> textures;
  std::vector<PassImage> images;
  std::vector<PassBuffer> buffers;
  QueryBlock block;
  std::vector<QueryBlock> more_blocks = {};  // further uniform blocks (a table beside the pass's parameters)

  // Appends, one by one: the entries hold references, so a list is added to, never assigned.
  void add_textures(std::initializer_list<QueryTexture> more) {
    for (const QueryTexture& t : more) textures.push_back(t);
  }
  void add_images(std::initializer_list<PassImage> more) {
    for (const PassImage& i : more) images.push_back(i);
  }
};
// `block` (when it has data) and `more_blocks`: every uniform block a dispatch binds.
std::vector<QueryBlock> uniform_blocks(const PassResources& resources);

// GPU time of consecutive stages of one run, read once at the end (a device's timestamp
// queries); NaN for every stage on a device without them.
class StageTimes {
 public:
  virtual ~StageTimes() = default;
  StageTimes() = default;
  StageTimes(const StageTimes&) = delete;
  StageTimes& operator=(const StageTimes&) = delete;
  virtual void start() = 0;                        // the beginning of the first stage
  virtual void stage(const std::string& name) = 0;  // the end of the stage `name`
  // (name, GPU milliseconds) of every stage in order; waits for the device.
  virtual std::vector<std::pair<std::string, double>> read() const = 0;
};

// What one dispatch wrote, read back: result k of query k at texel k of each image (query_result).
struct QueryResults {
  std::vector<Image> images;                      // per QueryBindings::results
  std::vector<std::vector<std::uint32_t>> words;  // per QueryBindings::word_results: 4 words a texel

  Query at(std::size_t image, std::size_t k) const { return query_result(images[image], k); }
  // Image `image`'s results of the first `count` queries.
  std::vector<Query> list(std::size_t image, std::size_t count) const;
};

// The queries of one run on the device and the images their results go to: made for one run, or
// dispatched many times (a benchmark times the dispatches alone).
class QueryBatch {
 public:
  virtual ~QueryBatch() = default;
  QueryBatch() = default;
  QueryBatch(const QueryBatch&) = delete;
  QueryBatch& operator=(const QueryBatch&) = delete;
  virtual int width() const = 0;
  virtual int height() const = 0;
  virtual std::size_t inputs() const = 0;
  virtual std::size_t results() const = 0;
  virtual std::size_t word_results() const = 0;
  virtual QueryResults read() const = 0;
};

// One pass compiled for one device with one set of defines.
class QueryProgram {
 public:
  virtual ~QueryProgram() = default;
  QueryProgram() = default;
  QueryProgram(const QueryProgram&) = delete;
  QueryProgram& operator=(const QueryProgram&) = delete;
};

// Bounds on GPU work, set by `penumbra check` (docs/reliability.md): every compute loop
// guarded (shader/loop_guard.h) and every dispatch waited for with a deadline, so that a
// module copy that never terminates fails its check instead of hanging the machine.
struct DispatchBounds {
  bool enabled = false;
  unsigned loop_iterations = LoopGuardSettings{}.iterations;  // per loop and invocation
  double timeout_s = 60.0;              // per dispatch
};

class QueryDevice {
 public:
  virtual ~QueryDevice() = default;
  QueryDevice() = default;
  QueryDevice(const QueryDevice&) = delete;
  QueryDevice& operator=(const QueryDevice&) = delete;

  // "gl450", "es310", "vulkan", "hlsl": what the passes are compiled as (check's --api).
  virtual std::string query_api() const = 0;
  // `pass` (a path under the glsl root, e.g. "passes/pcf_query.comp") with `defines`. Throws
  // Error(ExitCode::failed) naming the pass on a compile error.
  virtual std::unique_ptr<QueryProgram> compile_query(const SourceTree& tree, const std::string& pass,
                                                      const std::vector<Define>& defines) const = 0;
  // `image` (1, 2 or 4 channels) as a texture the passes sample with texelFetch, or write as a
  // storage image (its shape is float_shape of the image).
  virtual std::unique_ptr<DeviceTexture> upload(const Image& image) const = 0;
  // `inputs` all of one size (query_image of lists of one length); `results` RGBA32F and
  // `word_results` RGBA32UI images of that size. Throws Error on inputs of different sizes.
  virtual std::unique_ptr<QueryBatch> make_batch(const std::vector<Image>& inputs, std::size_t results,
                                                 std::size_t word_results) const = 0;
  // Binds the batch's inputs and results at `bindings`, `textures` and `block`, and runs
  // `program` over the batch's grid (whole work groups; the pass returns past the grid).
  // Throws Error unless the batch has an image per binding, or a texture was made elsewhere.
  virtual void dispatch(const QueryProgram& program, const QueryBindings& bindings, const QueryBatch& batch,
                        const std::vector<QueryTexture>& textures, const QueryBlock& block) const = 0;

  // The building passes (a mip chain, a pyramid, a summed-area table, a blur): textures they
  // write, lists they read, and a dispatch over a grid.
  // A texture of `shape`, its texels undefined until a pass writes them. Throws Error naming the
  // shape past the device's limits.
  virtual std::unique_ptr<DeviceTexture> make_texture(const TextureShape& shape) const = 0;
  // Level `level`, layer `layer` of a texture made by make_texture: a float format as an Image of
  // its channels, RGBA32UI as 4 words a texel.
  virtual Image read_texture(const DeviceTexture& texture, int level = 0, int layer = 0) const = 0;
  virtual std::vector<std::uint32_t> read_words(const DeviceTexture& texture, int level = 0, int layer = 0) const = 0;
  // Level 0 of layer `layer` of an array texture made by make_texture, as a 2-D texture: a view
  // where the device has them (the same texels), else a copy taken now (take it after the layer is
  // written).
  virtual std::unique_ptr<DeviceTexture> layer_texture(const DeviceTexture& array, int layer) const = 0;
  // The channels of the image a pass writes `channels` floats into (2 become 4 on ES, which has
  // no RG32F image format; the passes' shaders pick rgba32f there the same way).
  virtual int storage_channels(int channels) const { return channels; }
  // A storage buffer of `bytes` bytes (at least 4), and a write into it.
  virtual std::unique_ptr<DeviceBuffer> make_buffer(std::size_t bytes) const = 0;
  virtual void write_buffer(const DeviceBuffer& buffer, std::size_t offset, std::size_t bytes,
                            const void* data) const = 0;
  // Runs `program` over a width × height grid of invocations (rounded up to whole work groups)
  // with `resources` bound, and makes its writes visible to what follows. Throws Error naming
  // the pass for a resource its shader uses and `resources` lacks, or one made elsewhere.
  virtual void run(const QueryProgram& program, const PassResources& resources, int width, int height) const = 0;
  // As run, over the work groups counted in the first three 32-bit words of `groups` (x, y, z),
  // written by an earlier pass: a list whose length the device decided.
  virtual void run_indirect(const QueryProgram& program, const PassResources& resources,
                            const DeviceBuffer& groups) const = 0;
  // Every texel of every level and layer of a texture made by make_texture or upload set to `value`.
  virtual void clear_texture(const DeviceTexture& texture, const float value[4]) const = 0;
  // A clock for the stages of one run (GL's and Vulkan's timestamp queries where the device has
  // them). This default's times are all NaN ("unavailable"), never made up.
  virtual std::unique_ptr<StageTimes> stage_clock() const;

  // The raster passes (the shadow map, the G-buffer): `vertex` and `fragment` (paths under the glsl
  // root) as one program whose vertex stage reads a world position at PN_SCENE_POSITION_LOCATION
  // and whose fragment stage writes a `target` texel at PN_SCENE_TARGET_LOCATION
  // (glsl/passes/scene_raster.h). Throws Error as compile_query.
  virtual std::unique_ptr<QueryProgram> compile_raster(const SourceTree& tree, const std::string& vertex,
                                                       const std::string& fragment, TexelFormat target) const = 0;
  // A fragment pass over the whole target, as a deferred lighting pass runs: `fragment` with
  // `defines` behind passes/full_screen.vert (one triangle, no vertex input), its colour at
  // PN_SCENE_TARGET_LOCATION, the pixel from gl_FragCoord.
  virtual std::unique_ptr<QueryProgram> compile_full_screen(const SourceTree& tree, const std::string& fragment,
                                                            TexelFormat target,
                                                            const std::vector<Define>& defines) const = 0;
  // The kept raster path (a cache's maps): vertices written again where objects moved, a target
  // cleared, copied and drawn into inside rectangles. Each throws Error for an object made on
  // another device, and write_vertices for a list of another length or a range past it.
  virtual std::unique_ptr<DeviceVertices> make_vertices(const std::vector<glm::vec3>& vertices) const = 0;
  // Vertices [first, first + count) of `vertices` (the whole list, of to.count()) into `to`.
  virtual void write_vertices(const DeviceVertices& to, const std::vector<glm::vec3>& vertices, std::size_t first,
                              std::size_t count) const = 0;
  virtual std::unique_ptr<DeviceRasterTarget> make_raster_target(int size, TexelFormat format) const = 0;
  // Colour to `colour`, depth to the far plane, inside each rectangle (the whole target for none).
  virtual void clear_target(const DeviceRasterTarget& target, const float colour[4],
                            const std::vector<TexelRect>& rects = {}) const = 0;
  // Colour and depth of `source` (the same size and format) into `target` inside each rectangle
  // (everywhere for none), bit for bit.
  virtual void copy_target(const DeviceRasterTarget& source, const DeviceRasterTarget& target,
                           const std::vector<TexelRect>& rects = {}) const = 0;
  // Draws `runs` of `vertices` with a compile_raster `program` into `target` over what it holds
  // (the nearest surface kept), scissored to each rectangle in turn (unscissored for none), with
  // `resources`' textures and blocks bound.
  virtual void draw(const QueryProgram& program, const DeviceVertices& vertices, const std::vector<VertexRun>& runs,
                    const DeviceRasterTarget& target, const std::vector<TexelRect>& rects,
                    const PassResources& resources) const = 0;

  // Runs a compile_full_screen program over a new size × size texture of its target format with
  // `resources`' textures and blocks bound: every texel is the fragment's colour.
  virtual std::unique_ptr<DeviceTexture> draw_full_screen(const QueryProgram& program, int size,
                                                          const PassResources& resources) const = 0;
  // Draws `vertices` (a triangle list) with `program` into a new size × size texture of its target
  // format cleared to `clear`, the nearest surface kept (depth test "less"; clip-space depth -1..1
  // as GL's), rows from the bottom as GL's framebuffer; `resources`' textures and block bound.
  virtual std::unique_ptr<DeviceTexture> draw_triangles(const QueryProgram& program,
                                                        const std::vector<glm::vec3>& vertices, int size,
                                                        const float clear[4], const PassResources& resources) const = 0;
};

// The vertex stage of every full-screen pass (compile_full_screen).
inline constexpr const char* kFullScreenVertex = "passes/full_screen.vert";

TextureShape float_shape(int width, int height, int channels, int levels = 1);  // R32F, RG32F or RGBA32F

// Error unless the batch has one image per binding (the check every executor's dispatch makes).
void check_batch_bindings(const QueryBindings& bindings, const QueryBatch& batch);
// The batch inputs' common size; Error unless there is one and all share it (every executor's batch).
std::pair<int, int> query_batch_size(const std::vector<Image>& inputs);

}  // namespace pn
