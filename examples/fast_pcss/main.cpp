// fast_pcss_example — Fast PCSS (glsl/fast_pcss.glsl) in a small forward
// renderer, written to be read top to bottom. It takes from penumbra only
// what an engine would take, two files generated at build time by the
// `penumbra` binary — no C++ of the runner:
//   fast_pcss_bundle.glsl  `penumbra bundle glsl/fast_pcss.glsl --bare`: the module with all its
//                          includes, pasted after each shader's #version line (example_shaders.h)
//   sample_table.inc       `penumbra sample-table`: the 21x8 RG32F sample table's 336 floats
//
// Step 0  a headless GL 4.5 context (headless_gl.cpp) and the programs
// Step 1  the scene: a model (Assimp) on a ground slab, light and camera (scene_setup.h)
// Step 2  the shadow map: linear light depth in an R32F target (shaders/shadow_depth.*),
//         or with --depth-buffer only the light's hardware depth buffer (D32F)
// Step 3  the aligned min/max mip chain of the map, one compute dispatch a level (shaders/mip_build.comp;
//         from a depth buffer converted to linear depth on the way: shaders/mip_from_depth_buffer.glsl)
// Step 4  the sample table: a 21x8 RG32F texture
// Step 5  the forward pass: lit.frag calls pnFastPcss for every fragment (shaders/lit.*)
// Step 6  the lit image and the visibility as PNG
//
//   fast_pcss_example [--model PATH] [--out DIR | FILE.png] [--size N] [--bias B] [--depth-buffer]
// Exit status: 0 written; 2 bad command line, model or output path; 1 no GL context or a GL failure.

#include <glad/gl.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "example_shaders.h"  // generated: the shaders' text and the Fast PCSS bundle (example::text)
#include "command_line.h"
#include "gl_util.h"
#include "headless_gl.h"
#include "interface.h"
#include "mesh_model.h"
#include "png_file.h"
#include "scene_setup.h"

namespace example {
namespace {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------
// Step 0: every program is the same pieces in order — the #version line, the
// bindings (interface.h), for the two that call the module the bundle of
// fast_pcss.glsl, then the example's own file. (The bundle carries #line
// markers of its own; `#line 1` before the example's file makes a driver's
// message name that file's line numbers.)

const char* const kVersion = "#version 450 core\n";
const char* const kOwnFile = "#line 1\n";

struct Programs {
  GlName shadow_depth, mip_build, lit;
};

Programs make_programs(bool depth_buffer) {
  using namespace text;
  const auto mip_build = [&] {
    if (!depth_buffer)
      return compile_program("mip_build",
                             {{GL_COMPUTE_SHADER, {kVersion, kInterface, kFastPcssBundle, kOwnFile, kMipBuildComp}}});
    // PN_MIP_LEVEL0_DEPTH is defined before the bundle, which then uses it in pnMipFirstTexel.
    return compile_program("mip_build from a depth buffer",
                           {{GL_COMPUTE_SHADER, {kVersion, kInterface, kMipFromDepthBuffer, kFastPcssBundle, kOwnFile,
                                                 kMipBuildComp}}});
  };
  return {
      compile_program("shadow_depth", {{GL_VERTEX_SHADER, {kVersion, kInterface, kOwnFile, kShadowDepthVert}},
                                       {GL_FRAGMENT_SHADER, {kVersion, kInterface, kOwnFile, kShadowDepthFrag}}}),
      mip_build(),
      // The lit shader reads the map's texels too: through the same PN_MIP_LEVEL0_DEPTH.
      depth_buffer ? compile_program("lit from a depth buffer",
                                     {{GL_VERTEX_SHADER, {kVersion, kInterface, kOwnFile, kLitVert}},
                                      {GL_FRAGMENT_SHADER, {kVersion, kInterface, kMipFromDepthBuffer,
                                                            kFastPcssBundle, kOwnFile, kLitFrag}}})
                   : compile_program("lit", {{GL_VERTEX_SHADER, {kVersion, kInterface, kOwnFile, kLitVert}},
                                             {GL_FRAGMENT_SHADER, {kVersion, kInterface, kFastPcssBundle, kOwnFile,
                                                                   kLitFrag}}})};
}

// ---------------------------------------------------------------------------
// Step 1: the light and camera (scene_setup.h). PnLight is light_model.glsl's
// struct; lit.frag declares it as a uniform at EX_LIGHT_LOCATION, its six
// floats at six consecutive locations.

struct Light {
  glm::mat4 view, projection;
  float pn_light[6];  // PnLight: width, near, nearPlaneWidth, mapSize, spread, texelWorld
};

Light make_light() {
  return {glm::lookAt(kLightPosition, kLightPosition + kLightDirection, kLightMapUp),
          glm::perspective(static_cast<float>(kLightFovRadians), 1.0f, kLightNear, kLightFar),
          {kLightWidth, kLightNear,
           static_cast<float>(2.0 * kLightNear * std::tan(0.5 * kLightFovRadians)),  // W_n = 2 n tan(fov / 2)
           static_cast<float>(kShadowMapSize),
           0.0f,    // spread: 0 for an area light (a sun's is 2 tan(theta / 2))
           0.0f}};  // texelWorld: 0 for a perspective map (an orthographic one's texel width)
}

glm::mat4 camera_view_projection() {
  return glm::perspective(glm::radians(kCameraFovDegrees), 1.0f, kCameraNear, kCameraFar) *
         glm::lookAt(kCameraEye, kCameraTarget, glm::vec3(0.0f, 1.0f, 0.0f));
}

// The scene's vertices in one buffer: the ground slab first, then the model.
struct SceneGeometry {
  int ground_vertices = 0, model_vertices = 0;
  GlName buffer, vertex_array;
};

SceneGeometry upload_scene(const std::vector<glm::vec3>& model) {
  std::vector<glm::vec3> vertices = ground_slab_triangles();
  const int ground = static_cast<int>(vertices.size());
  vertices.insert(vertices.end(), model.begin(), model.end());
  GlName buffer = make_buffer(vertices.data(), vertices.size() * sizeof(glm::vec3));
  GlName vertex_array = make_vertex_array(buffer);
  return {ground, static_cast<int>(model.size()), std::move(buffer), std::move(vertex_array)};
}

// ---------------------------------------------------------------------------
// Step 2: the shadow map, as LINEAR light depth (distance along the light's
// axis): what the module compares. By default an R32F colour target holds it,
// cleared to +Inf, which the module reads as "no occluder"; the depth buffer
// keeps the nearest surface. With --depth-buffer only the hardware depth
// buffer is kept, as many engines' shadow passes have it, and Step 3 converts
// it (cleared depth 1 becomes the far plane: no occluder nearer).

GlName render_shadow_map(const Programs& programs, const SceneGeometry& scene, const Light& light, bool depth_buffer) {
  const int n = kShadowMapSize;
  GlName depth = make_texture(GL_DEPTH_COMPONENT32F, n, n);
  GlName map = depth_buffer ? GlName(0, nullptr) : make_texture(GL_R32F, n, n);
  const GlName framebuffer = depth_buffer ? make_framebuffer({{GL_DEPTH_ATTACHMENT, depth.id()}})
                                          : make_framebuffer({{GL_COLOR_ATTACHMENT0, map.id()},
                                                              {GL_DEPTH_ATTACHMENT, depth.id()}});
  const float far[4] = {std::numeric_limits<float>::infinity(), 0.0f, 0.0f, 0.0f}, one = 1.0f;
  if (!depth_buffer) glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, far);
  glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &one);

  const GLuint program = programs.shadow_depth.id();
  glProgramUniformMatrix4fv(program, EX_LIGHT_VIEW_LOCATION, 1, GL_FALSE, glm::value_ptr(light.view));
  glProgramUniformMatrix4fv(program, EX_LIGHT_PROJECTION_LOCATION, 1, GL_FALSE, glm::value_ptr(light.projection));
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
  glViewport(0, 0, n, n);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glUseProgram(program);
  glBindVertexArray(scene.vertex_array.id());
  glDrawArrays(GL_TRIANGLES, 0, scene.ground_vertices + scene.model_vertices);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  check_gl("Step 2, the shadow map");
  return depth_buffer ? std::move(depth) : std::move(map);
}

// ---------------------------------------------------------------------------
// Step 3: the aligned min/max mip chain, in minmax_mip.glsl's storage: P the
// least power of two >= N (at least 4), an RGBA32F texture (P/8) x (P/4) with
// log2 P - 1 levels (node levels 2 .. log2 P: below, the map itself), two
// nodes a texel — 0.17x the map's bytes. One dispatch a level, each reading
// the level below through the sampler: a barrier between them. Rebuilt
// whenever the shadow map changes (every frame, in an engine).

GlName build_mip_chain(const Programs& programs, const GlName& shadow_map, const Light& light, bool depth_buffer) {
  constexpr int kFirstLevel = 2;  // minmax_mip.h's PN_MIP_FIRST_LEVEL
  int padded = 1 << kFirstLevel, log2_padded = kFirstLevel;
  while (padded < kShadowMapSize) padded *= 2, ++log2_padded;
  const int levels = log2_padded - kFirstLevel + 1;
  GlName chain = make_texture(GL_RGBA32F, std::max((padded >> kFirstLevel) / 2, 1), padded >> kFirstLevel, levels);

  const GLuint program = programs.mip_build.id();
  if (depth_buffer)  // what pnLightDepthFromDepthBuffer inverts
    glProgramUniformMatrix4fv(program, EX_MIP_LIGHT_PROJECTION_LOCATION, 1, GL_FALSE,
                              glm::value_ptr(light.projection));
  glUseProgram(program);
  glBindTextureUnit(EX_MIP_SHADOW_MAP_BINDING, shadow_map.id());
  glBindTextureUnit(EX_MIP_READ_BINDING, chain.id());
  for (int level = kFirstLevel; level <= log2_padded; ++level) {
    const int rows = padded >> level, columns = std::max(rows / 2, 1);
    glProgramUniform1i(program, EX_MIP_LEVEL_LOCATION, level);
    glBindImageTexture(EX_MIP_WRITE_IMAGE, chain.id(), level - kFirstLevel, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    const int groups_x = (columns + EX_MIP_GROUP_SIZE - 1) / EX_MIP_GROUP_SIZE;
    const int groups_y = (rows + EX_MIP_GROUP_SIZE - 1) / EX_MIP_GROUP_SIZE;
    glDispatchCompute(groups_x, groups_y, 1);
    // The next level reads this one through the sampler.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
  glBindImageTexture(EX_MIP_WRITE_IMAGE, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glBindTextureUnit(EX_MIP_SHADOW_MAP_BINDING, 0);
  glBindTextureUnit(EX_MIP_READ_BINDING, 0);
  check_gl("Step 3, the min/max mip chain");
  return chain;
}

// ---------------------------------------------------------------------------
// Step 4: the sample table as `penumbra sample-table` prints it: 21 columns
// (the 1-, 4- and 16-sample groups) x 8 rows (sets), (x, y) a texel. Made
// once; it never changes.

constexpr int kSampleTableColumns = 21, kSampleTableSets = 8;
const float kSampleTable[] = {
#include "sample_table.inc"
};
static_assert(sizeof kSampleTable == sizeof(float) * kSampleTableColumns * kSampleTableSets * 2,
              "penumbra sample-table prints 21 x 8 (x, y) pairs");

GlName upload_sample_table() {
  GlName table = make_texture(GL_RG32F, kSampleTableColumns, kSampleTableSets);
  glTextureSubImage2D(table.id(), 0, 0, 0, kSampleTableColumns, kSampleTableSets, GL_RG, GL_FLOAT, kSampleTable);
  check_gl("Step 4, the sample table");
  return table;
}

// ---------------------------------------------------------------------------
// Step 5: the forward pass. lit.frag computes each fragment's receiver
// (pnLightProject), calls pnFastPcss with the chain and the table, and
// shades: albedo x (ambient + (1 - ambient) x N.L x visibility). It writes
// the colour and, for the comparison, the visibility itself; where nothing
// is drawn the colour is the sky and the visibility 1.

struct Frame {
  FloatImage lit, visibility;
};

FloatImage read_texture(const GlName& texture, int size, int channels) {
  FloatImage image{size, size, channels, std::vector<float>(static_cast<std::size_t>(size) * size * channels)};
  glGetTextureImage(texture.id(), 0, channels == 1 ? GL_RED : GL_RGBA, GL_FLOAT,
                    static_cast<GLsizei>(image.texels.size() * sizeof(float)), image.texels.data());
  return image;
}

Frame draw_lit(const Programs& programs, const SceneGeometry& scene, const Light& light, const GlName& shadow_map,
               const GlName& mip_chain, const GlName& sample_table, int size, float bias) {
  const GlName colour = make_texture(GL_RGBA32F, size, size), visibility = make_texture(GL_R32F, size, size);
  const GlName depth = make_texture(GL_DEPTH_COMPONENT32F, size, size);
  const GlName framebuffer = make_framebuffer({{GL_COLOR_ATTACHMENT0 + EX_LIT_COLOUR_OUTPUT, colour.id()},
                                               {GL_COLOR_ATTACHMENT0 + EX_LIT_VISIBILITY_OUTPUT, visibility.id()},
                                               {GL_DEPTH_ATTACHMENT, depth.id()}});
  const float sky[4] = {kSkyColour.r, kSkyColour.g, kSkyColour.b, 1.0f}, lit[4] = {1.0f, 0.0f, 0.0f, 0.0f};
  const float one = 1.0f;
  glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, EX_LIT_COLOUR_OUTPUT, sky);
  glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, EX_LIT_VISIBILITY_OUTPUT, lit);
  glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &one);

  const GLuint program = programs.lit.id();
  glProgramUniformMatrix4fv(program, EX_CAMERA_VIEW_PROJECTION_LOCATION, 1, GL_FALSE,
                            glm::value_ptr(camera_view_projection()));
  glProgramUniform3fv(program, EX_CAMERA_POSITION_LOCATION, 1, glm::value_ptr(kCameraEye));
  glProgramUniform3fv(program, EX_LIGHT_POSITION_LOCATION, 1, glm::value_ptr(kLightPosition));
  glProgramUniform1f(program, EX_AMBIENT_LOCATION, kAmbient);
  // What Fast PCSS needs: the light's matrices, PnLight, the bias and the normal offset.
  glProgramUniformMatrix4fv(program, EX_LIGHT_VIEW_LOCATION, 1, GL_FALSE, glm::value_ptr(light.view));
  glProgramUniformMatrix4fv(program, EX_LIGHT_PROJECTION_LOCATION, 1, GL_FALSE, glm::value_ptr(light.projection));
  for (int i = 0; i < 6; ++i) glProgramUniform1f(program, EX_LIGHT_LOCATION + i, light.pn_light[i]);
  glProgramUniform1f(program, EX_BIAS_LOCATION, bias);
  glProgramUniform1f(program, EX_NORMAL_OFFSET_LOCATION, kNormalOffsetTexels);
  glBindTextureUnit(EX_LIT_MIP_BINDING, mip_chain.id());
  glBindTextureUnit(EX_LIT_SAMPLE_TABLE_BINDING, sample_table.id());
  glBindTextureUnit(EX_LIT_SHADOW_MAP_BINDING, shadow_map.id());

  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
  glViewport(0, 0, size, size);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glUseProgram(program);
  glBindVertexArray(scene.vertex_array.id());
  glProgramUniform3fv(program, EX_ALBEDO_LOCATION, 1, glm::value_ptr(kGroundAlbedo));
  glDrawArrays(GL_TRIANGLES, 0, scene.ground_vertices);
  glProgramUniform3fv(program, EX_ALBEDO_LOCATION, 1, glm::value_ptr(kModelAlbedo));
  glDrawArrays(GL_TRIANGLES, scene.ground_vertices, scene.model_vertices);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindTextureUnit(EX_LIT_MIP_BINDING, 0);
  glBindTextureUnit(EX_LIT_SAMPLE_TABLE_BINDING, 0);
  glBindTextureUnit(EX_LIT_SHADOW_MAP_BINDING, 0);
  check_gl("Step 5, the forward pass");

  Frame frame{read_texture(colour, size, 4), read_texture(visibility, size, 1)};
  check_gl("reading the pictures back");
  return frame;
}

// ---------------------------------------------------------------------------
// Step 6 and the command line: where the pictures go, and the options.

struct Options : CommonOptions {
  bool depth_buffer = false;  // Step 2 keeps only the light's depth buffer; Step 3 converts it
};

Options parse_options(int argc, char** argv) {
  Options o;
  o.out = "fast_pcss_out";
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--help" || flag == "-h") {
      std::cout << "usage: fast_pcss_example [--model PATH] [--out DIR | FILE.png] [--size N] [--bias B] "
                   "[--depth-buffer]\n"
                << common_usage("fast_pcss_out")
                << "  --depth-buffer  build the mip chain straight from the light's D32F depth buffer\n"
                   "                (PN_MIP_LEVEL0_DEPTH) instead of an R32F map of linear depth\n";
      std::exit(0);
    }
    if (flag == "--depth-buffer") o.depth_buffer = true;
    else if (!read_common_option(argc, argv, i, o))
      throw std::invalid_argument("'" + flag + "': unknown option (--help lists them)");
  }
  check_common_options(o);
  return o;
}

int run(const Options& options) {
  // Bad input is refused before any GL work: the model (Step 1), then the output place.
  const std::vector<glm::vec3> model = load_placed_model(options.model);
  const Outputs outputs = plan_outputs(options);

  std::unique_ptr<HeadlessGl> gl;
  try {
    gl = std::make_unique<HeadlessGl>();
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("no OpenGL 4.5 context: ") + e.what());
  }
  std::cout << "OpenGL: " << gl->renderer() << "\n";
  const Programs programs = make_programs(options.depth_buffer);

  // Step 1
  const SceneGeometry scene = upload_scene(model);
  const Light light = make_light();
  // Step 2
  const GlName shadow_map = render_shadow_map(programs, scene, light, options.depth_buffer);
  // Step 3
  const GlName mip_chain = build_mip_chain(programs, shadow_map, light, options.depth_buffer);
  // Step 4
  const GlName sample_table = upload_sample_table();
  // Step 5
  const Frame frame = draw_lit(programs, scene, light, shadow_map, mip_chain, sample_table, options.size, options.bias);
  // Step 6
  make_directory(outputs.directory);
  write_files({{outputs.lit, encode_png(frame.lit)}, {outputs.visibility, encode_png(frame.visibility)}});
  std::cout << "model " << options.model.string() << ": " << model.size() / 3 << " triangles, shadow map "
            << kShadowMapSize << "x" << kShadowMapSize << (options.depth_buffer ? " (depth buffer)" : " (linear R32F)")
            << ", screen " << options.size << "x" << options.size << "\n"
            << "wrote " << outputs.lit.string() << "\nwrote " << outputs.visibility.string() << "\n";
  return 0;
}

}  // namespace
}  // namespace example

int main(int argc, char** argv) {
  try {
    return example::run(example::parse_options(argc, argv));
  } catch (const std::invalid_argument& e) {
    std::cerr << "fast_pcss_example: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "fast_pcss_example: error: " << e.what() << "\n";
    return 1;
  }
}
