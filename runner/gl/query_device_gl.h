// The OpenGL executor of the query passes (device/query_device.h): Context implements
// QueryDevice with these. A texture a GL pass made (a pyramid, a moments table) goes into a
// query pass as a GlDeviceTexture that borrows it.
#pragma once

#include <vector>

#include "device/query_device.h"
#include "gl/compute_program.h"
#include "gl/objects.h"
#include "gl/raster_target.h"
#include "gl/texture.h"

namespace pn {

class GlDeviceTexture final : public DeviceTexture {
 public:
  // Borrows `texture`, which must outlive this object and belong to the context it is used on;
  // `shape` where a pass writes it as a storage image (its format) or the device reads it back.
  explicit GlDeviceTexture(const GlObject& texture, const TextureShape& shape = {})
      : DeviceTexture(shape), texture_(&texture) {}
  GlDeviceTexture(GlObject&&, const TextureShape& = {}) = delete;  // would borrow a temporary
  // Owns `owned` (an rvalue: a FloatTexture lvalue is borrowed by the constructor above).
  explicit GlDeviceTexture(FloatTexture&& owned)
      : DeviceTexture(float_shape(owned.width, owned.height, owned.channels)), owned_(std::move(owned)),
        texture_(&owned_) {}
  GlDeviceTexture(FloatTexture&& owned, const TextureShape& shape)
      : DeviceTexture(shape), owned_(std::move(owned)), texture_(&owned_) {}
  const GlObject& object() const { return *texture_; }
  // The texture this object owns, moved out (for GL code that keeps a pass's result as a
  // FloatTexture). Throws Error for one that borrows.
  FloatTexture take();

 private:
  FloatTexture owned_;
  const GlObject* texture_;
};

class GlDeviceBuffer final : public DeviceBuffer {
 public:
  explicit GlDeviceBuffer(GlObject buffer) : buffer_(std::move(buffer)) {}
  const GlObject& object() const { return buffer_; }

 private:
  GlObject buffer_;
};

// A TriangleBuffer and a RasterTarget of a GL context behind the device's kept raster path.
class GlDeviceVertices final : public DeviceVertices {
 public:
  GlDeviceVertices(const Context& context, const std::vector<glm::vec3>& vertices)
      : DeviceVertices(static_cast<int>(vertices.size())), buffer_(context, vertices) {}
  TriangleBuffer& buffer() const { return buffer_; }

 private:
  mutable TriangleBuffer buffer_;
};

class GlDeviceRasterTarget final : public DeviceRasterTarget {
 public:
  GlDeviceRasterTarget(const Context& context, int size, TexelFormat format)
      : target_(context, size, texel_channels(format)), view_(target_.texture(), float_shape(size, size, texel_channels(format))) {}
  const DeviceTexture& texture() const override { return view_; }
  const RasterTarget& target() const { return target_; }

 private:
  RasterTarget target_;
  GlDeviceTexture view_;
};

// The GL texture behind a DeviceTexture of a GL context. Throws Error for one made elsewhere.
const GlObject& gl_texture(const DeviceTexture& texture);
// A texture made on a GL context (make_texture, upload, a pass's result) as the FloatTexture it owns.
FloatTexture take_float_texture(std::unique_ptr<DeviceTexture> texture);

class GlQueryProgram final : public QueryProgram {
 public:
  explicit GlQueryProgram(ComputeProgram program) : program_(std::move(program)) {}
  const ComputeProgram& program() const { return program_; }

 private:
  ComputeProgram program_;
};

// A vertex + fragment program (QueryDevice::compile_raster) and the format it draws into.
class GlRasterProgram final : public QueryProgram {
 public:
  GlRasterProgram(GlObject program, TexelFormat target) : program_(std::move(program)), target_(target) {}
  const GlObject& program() const { return program_; }
  TexelFormat target() const { return target_; }

 private:
  GlObject program_;
  TexelFormat target_;
};
// The GL program of a raster program made on a GL context. Throws Error for one made elsewhere.
const GlRasterProgram& gl_raster_program(const QueryProgram& program);

class GlQueryBatch final : public QueryBatch {
 public:
  GlQueryBatch(const Context& context, const std::vector<Image>& inputs, std::size_t results,
               std::size_t word_results);
  int width() const override { return width_; }
  int height() const override { return height_; }
  std::size_t inputs() const override { return inputs_.size(); }
  std::size_t results() const override { return results_.size(); }
  std::size_t word_results() const override { return word_results_.size(); }
  QueryResults read() const override;

 private:
  friend class Context;
  const Context* context_;
  int width_ = 0, height_ = 0;
  std::vector<FloatTexture> inputs_, results_;
  std::vector<GlObject> word_results_;
};

}  // namespace pn
