#include "gl/query_device_gl.h"

#include <algorithm>
#include <string>

#include "core/error.h"
#include "gl/gpu_timer.h"
#include "gl/pass_bindings.h"
#include "gl/raster_target.h"

namespace pn {

GlQueryBatch::GlQueryBatch(const Context& context, const std::vector<Image>& inputs, std::size_t results,
                           std::size_t word_results)
    : context_(&context) {
  std::tie(width_, height_) = query_batch_size(inputs);
  for (const Image& input : inputs) inputs_.push_back(upload_float_texture(context, input));
  for (std::size_t i = 0; i < results; ++i) results_.push_back(make_float_texture(context, width_, height_, 4));
  for (std::size_t i = 0; i < word_results; ++i)
    word_results_.push_back(make_texture(context, GL_TEXTURE_2D, GL_RGBA32UI, width_, height_));
}

QueryResults GlQueryBatch::read() const {
  QueryResults out;
  for (const FloatTexture& result : results_) out.images.push_back(read_float_texture(*context_, result));
  for (const GlObject& words : word_results_)
    out.words.push_back(read_uint4_texture(*context_, words, width_, height_));
  return out;
}

std::string Context::query_api() const { return api_name(api_); }

std::unique_ptr<QueryProgram> Context::compile_query(const SourceTree& tree, const std::string& pass,
                                                     const std::vector<Define>& defines) const {
  return std::make_unique<GlQueryProgram>(compile_pass(*this, tree, pass, defines));
}

std::unique_ptr<DeviceTexture> Context::upload(const Image& image) const {
  return std::make_unique<GlDeviceTexture>(upload_float_texture(*this, image));
}

std::unique_ptr<QueryBatch> Context::make_batch(const std::vector<Image>& inputs, std::size_t results,
                                                std::size_t word_results) const {
  return std::make_unique<GlQueryBatch>(*this, inputs, results, word_results);
}

namespace {

GLenum gl_format(TexelFormat format) {
  switch (format) {
    case TexelFormat::r32f: return GL_R32F;
    case TexelFormat::rg32f: return GL_RG32F;
    case TexelFormat::rgba32f: return GL_RGBA32F;
    case TexelFormat::rgba32ui: return GL_RGBA32UI;
  }
  return GL_RGBA32F;
}

std::string shape_text(const TextureShape& shape) {
  return std::to_string(shape.width) + "x" + std::to_string(shape.height) + " (" + std::to_string(shape.levels) +
         " levels, " + std::to_string(shape.layers) + " layers)";
}

template <class Made>
const Made& made_here(const auto& object, const char* what) {
  const auto* made = dynamic_cast<const Made*>(&object);
  if (made == nullptr) throw Error(std::string("query pass: a ") + what + " made on another device than this GL context");
  return *made;
}

}  // namespace

void Context::dispatch(const QueryProgram& program, const QueryBindings& bindings, const QueryBatch& batch,
                       const std::vector<QueryTexture>& textures, const QueryBlock& block) const {
  check_batch_bindings(bindings, batch);
  const auto& gl_batch = made_here<GlQueryBatch>(batch, "batch");
  const auto& gl_program = made_here<GlQueryProgram>(program, "program");
  PassBindings bind(*this);
  if (block.data != nullptr) bind.uniform_data(block.binding, block.data, block.size);
  for (const QueryTexture& t : textures) bind.texture(t.binding, made_here<GlDeviceTexture>(t.texture, "texture").object());
  for (std::size_t i = 0; i < gl_batch.inputs_.size(); ++i) bind.texture(bindings.inputs[i], gl_batch.inputs_[i]);
  for (std::size_t i = 0; i < gl_batch.results_.size(); ++i)
    bind.image(bindings.results[i], gl_batch.results_[i], GL_WRITE_ONLY, GL_RGBA32F);
  for (std::size_t i = 0; i < gl_batch.word_results_.size(); ++i)
    bind.image(bindings.word_results[i], gl_batch.word_results_[i], GL_WRITE_ONLY, GL_RGBA32UI);
  gl_program.program().dispatch(gl_batch.width_, gl_batch.height_);
}

const GlObject& gl_texture(const DeviceTexture& texture) {
  return made_here<GlDeviceTexture>(texture, "texture").object();
}

FloatTexture GlDeviceTexture::take() {
  if (texture_ != &owned_) throw Error("a GL texture borrowed by a device texture: it has no texture of its own to give");
  return std::move(owned_);
}

FloatTexture take_float_texture(std::unique_ptr<DeviceTexture> texture) {
  auto* gl = dynamic_cast<GlDeviceTexture*>(texture.get());
  if (gl == nullptr) throw Error("a texture made on another device than this GL context");
  return gl->take();
}

int Context::storage_channels(int channels) const { return image_channels(*this, channels); }

std::unique_ptr<DeviceTexture> Context::make_texture(const TextureShape& shape) const {
  GLint max_size = 0, max_layers = 0;
  gl().GetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  gl().GetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &max_layers);
  int full_levels = 1;
  while ((std::max(shape.width, shape.height) >> full_levels) > 0) ++full_levels;
  if (shape.width < 1 || shape.height < 1 || shape.width > max_size || shape.height > max_size || shape.layers < 1 ||
      shape.layers > max_layers || (shape.layers > 1 && !shape.array) || shape.levels < 1 || shape.levels > full_levels)
    throw Error("a texture of " + shape_text(shape) + ": expected sides 1.." + std::to_string(max_size) +
                " (GL_MAX_TEXTURE_SIZE), 1.." + std::to_string(max_layers) + " layers (an array for more than one), 1.." +
                std::to_string(full_levels) + " levels");
  GlObject texture = pn::make_texture(*this, shape.array ? GL_TEXTURE_2D_ARRAY : GL_TEXTURE_2D, gl_format(shape.format),
                                      shape.width, shape.height, shape.layers, shape.levels);
  throw_if_gl_error("allocating a texture of " + shape_text(shape));
  return std::make_unique<GlDeviceTexture>(
      FloatTexture(std::move(texture), shape.width, shape.height, texel_channels(shape.format)), shape);
}

Image Context::read_texture(const DeviceTexture& texture, int level, int layer) const {
  const TextureShape& shape = texture.shape();
  if (shape.width == 0 || shape.format == TexelFormat::rgba32ui || level < 0 || level >= shape.levels || layer < 0 ||
      layer >= shape.layers)
    throw Error("reading level " + std::to_string(level) + ", layer " + std::to_string(layer) +
                " of a texture of " + shape_text(shape) + ": expected a float texture made by make_texture and a level and layer it has");
  return read_float_texture_layer(*this, gl_texture(texture), layer, shape.level_width(level), shape.level_height(level),
                                  texel_channels(shape.format), level);
}

std::vector<std::uint32_t> Context::read_words(const DeviceTexture& texture, int level, int layer) const {
  const TextureShape& shape = texture.shape();
  if (shape.format != TexelFormat::rgba32ui || level != 0 || layer != 0)
    throw Error("reading the words of level " + std::to_string(level) + ", layer " + std::to_string(layer) +
                " of a texture of " + shape_text(shape) + ": expected an RGBA32UI texture's level 0, layer 0");
  return read_uint4_texture(*this, gl_texture(texture), shape.width, shape.height);
}

std::unique_ptr<DeviceTexture> Context::layer_texture(const DeviceTexture& array, int layer) const {
  const TextureShape& shape = array.shape();
  if (!shape.array || layer < 0 || layer >= shape.layers || shape.format == TexelFormat::rgba32ui)
    throw Error("layer " + std::to_string(layer) + " of a texture of " + shape_text(shape) +
                ": expected a float array texture made by make_texture and a layer it has");
  const int channels = texel_channels(shape.format);
  return std::make_unique<GlDeviceTexture>(FloatTexture(
      texture_of_layer(*this, gl_texture(array), layer, shape.width, shape.height, channels), shape.width,
      shape.height, channels));
}

std::unique_ptr<DeviceBuffer> Context::make_buffer(std::size_t bytes) const {
  return std::make_unique<GlDeviceBuffer>(pn::make_buffer(*this, std::max<std::size_t>(bytes, 4), nullptr, GL_DYNAMIC_DRAW));
}

void Context::write_buffer(const DeviceBuffer& buffer, std::size_t offset, std::size_t bytes, const void* data) const {
  pn::write_buffer(*this, made_here<GlDeviceBuffer>(buffer, "buffer").object(), offset, bytes, data);
}

namespace {

// `resources` bound for one dispatch or draw (`bind` is the dispatch's scope).
void bind_resources(PassBindings& bind, const PassResources& resources) {
  for (const QueryBlock& block : uniform_blocks(resources)) bind.uniform_data(block.binding, block.data, block.size);
  for (const QueryTexture& t : resources.textures) bind.texture(t.binding, gl_texture(t.texture));
  for (const PassImage& image : resources.images) {
    const TextureShape& shape = image.texture.shape();
    if (shape.width == 0)
      throw Error("storage image at binding " + std::to_string(image.binding) + ": a texture of unknown format");
    bind.image(image.binding, gl_texture(image.texture), GL_WRITE_ONLY, gl_format(shape.format), image.level, shape.array);
  }
  for (const PassBuffer& b : resources.buffers)
    bind.storage_buffer(b.binding, made_here<GlDeviceBuffer>(b.buffer, "buffer").object());
}

// Error unless `resources` are what a raster pass binds: textures and blocks, no storage.
void require_raster_resources(const PassResources& resources, const char* pass) {
  if (!resources.images.empty() || !resources.buffers.empty())
    throw Error(std::string("a ") + pass + " pass binds textures and blocks only: expected no storage images or buffers");
}

// StageClock (gl/gpu_timer.h) behind the device's interface.
class GlStageTimes final : public StageTimes {
 public:
  explicit GlStageTimes(const Context& context) : clock_(context) {}
  void start() override { clock_.start(); }
  void stage(const std::string& name) override { clock_.stage(name); }
  std::vector<std::pair<std::string, double>> read() const override { return clock_.read(); }

 private:
  StageClock clock_;
};

}  // namespace

void Context::run(const QueryProgram& program, const PassResources& resources, int width, int height) const {
  const auto& gl_program = made_here<GlQueryProgram>(program, "program");
  if (width <= 0 || height <= 0) return;
  PassBindings bind(*this);
  bind_resources(bind, resources);
  gl_program.program().dispatch(width, height);
}

void Context::run_indirect(const QueryProgram& program, const PassResources& resources,
                           const DeviceBuffer& groups) const {
  const auto& gl_program = made_here<GlQueryProgram>(program, "program");
  PassBindings bind(*this);
  bind_resources(bind, resources);
  gl_program.program().dispatch_indirect(made_here<GlDeviceBuffer>(groups, "buffer").object());
}

void Context::clear_texture(const DeviceTexture& texture, const float value[4]) const {
  const TextureShape& shape = texture.shape();
  if (shape.width == 0) throw Error("clearing a texture of unknown shape: expected one made by make_texture or upload");
  for (int level = 0; level < shape.levels; ++level)
    for (int layer = 0; layer < shape.layers; ++layer)
      clear_texture_layer(*this, gl_texture(texture), level, shape.array ? layer : 0,
                          shape.format == TexelFormat::rgba32ui, value);
}

std::unique_ptr<StageTimes> Context::stage_clock() const { return std::make_unique<GlStageTimes>(*this); }

const GlRasterProgram& gl_raster_program(const QueryProgram& program) {
  return made_here<GlRasterProgram>(program, "raster program");
}

std::unique_ptr<QueryProgram> Context::compile_raster(const SourceTree& tree, const std::string& vertex,
                                                      const std::string& fragment, TexelFormat target) const {
  if (target == TexelFormat::rgba32ui) throw Error("raster pass " + fragment + ": expected a float target");
  return std::make_unique<GlRasterProgram>(link_raster_pass(*this, tree, vertex, fragment, {}), target);
}

std::unique_ptr<DeviceTexture> Context::draw_triangles(const QueryProgram& program,
                                                       const std::vector<glm::vec3>& vertices, int size,
                                                       const float clear[4], const PassResources& resources) const {
  const GlRasterProgram& raster = gl_raster_program(program);
  require_raster_resources(resources, "raster");
  const TriangleBuffer triangles(*this, vertices);
  RasterTarget target(*this, size, texel_channels(raster.target()));
  target.clear(clear);
  {
    PassBindings bind(*this);
    bind_resources(bind, resources);
    target.draw(raster.program(), triangles, {{0, triangles.vertex_count()}});
  }
  return std::make_unique<GlDeviceTexture>(target.release_texture());
}

std::unique_ptr<QueryProgram> Context::compile_full_screen(const SourceTree& tree, const std::string& fragment,
                                                           TexelFormat target, const std::vector<Define>& defines) const {
  if (target == TexelFormat::rgba32ui) throw Error("full-screen pass " + fragment + ": expected a float target");
  return std::make_unique<GlRasterProgram>(link_raster_pass(*this, tree, kFullScreenVertex, fragment, defines), target);
}

std::unique_ptr<DeviceTexture> Context::draw_full_screen(const QueryProgram& program, int size,
                                                         const PassResources& resources) const {
  const GlRasterProgram& raster = gl_raster_program(program);
  require_raster_resources(resources, "full-screen");
  RasterTarget target(*this, size, texel_channels(raster.target()));
  {
    PassBindings bind(*this);
    bind_resources(bind, resources);
    target.draw_full_screen(raster.program());
  }
  return std::make_unique<GlDeviceTexture>(target.release_texture());
}

std::unique_ptr<DeviceVertices> Context::make_vertices(const std::vector<glm::vec3>& vertices) const {
  return std::make_unique<GlDeviceVertices>(*this, vertices);
}

void Context::write_vertices(const DeviceVertices& to, const std::vector<glm::vec3>& vertices, std::size_t first,
                             std::size_t count) const {
  made_here<GlDeviceVertices>(to, "vertex buffer").buffer().write(vertices, first, count);
}

std::unique_ptr<DeviceRasterTarget> Context::make_raster_target(int size, TexelFormat format) const {
  if (format == TexelFormat::rgba32ui) throw Error("a raster target of RGBA32UI texels: expected a float format");
  return std::make_unique<GlDeviceRasterTarget>(*this, size, format);
}

void Context::clear_target(const DeviceRasterTarget& target, const float colour[4],
                           const std::vector<TexelRect>& rects) const {
  made_here<GlDeviceRasterTarget>(target, "raster target").target().clear(colour, rects);
}

void Context::copy_target(const DeviceRasterTarget& source, const DeviceRasterTarget& target,
                          const std::vector<TexelRect>& rects) const {
  made_here<GlDeviceRasterTarget>(target, "raster target")
      .target()
      .copy_from(made_here<GlDeviceRasterTarget>(source, "raster target").target(), rects);
}

void Context::draw(const QueryProgram& program, const DeviceVertices& vertices, const std::vector<VertexRun>& runs,
                   const DeviceRasterTarget& target, const std::vector<TexelRect>& rects,
                   const PassResources& resources) const {
  const GlRasterProgram& raster = gl_raster_program(program);
  require_raster_resources(resources, "raster");
  PassBindings bind(*this);
  bind_resources(bind, resources);
  made_here<GlDeviceRasterTarget>(target, "raster target")
      .target()
      .draw(raster.program(), made_here<GlDeviceVertices>(vertices, "vertex buffer").buffer(), runs, rects);
}

}  // namespace pn
