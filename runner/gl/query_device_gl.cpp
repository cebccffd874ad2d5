#include "gl/query_device_gl.h"

#include <string>

#include "core/error.h"
#include "gl/pass_bindings.h"

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

}  // namespace pn
