// The GPU foundation: headless EGL context, shader embedding and assembly (generated
// #defines, includes, #line mapping), compile-error reporting, buffers, textures,
// C++-computed tables and timers. Runs on Mesa llvmpipe where there is no GPU.
#include "gpu_test_util.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <memory>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "gpu/buffers.h"
#include "gpu/compute_program.h"
#include "gpu/embedded_shaders.h"
#include "gpu/gl_context.h"
#include "gpu/shader_source.h"
#include "gpu/timer.h"
#include "shading/sh/wedge.h"

namespace skylit::gpu {
namespace {

using GpuContextTest = testing::GpuTest;

ComputeProgram inline_program(std::string_view name, std::string_view text,
                              const GlslDefines& defines = {}) {
  return ComputeProgram(assemble_shader_text(name, text, defines));
}

std::string compile_error(std::string_view name, std::string_view text) {
  try {
    inline_program(name, text);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

// --- no GL needed ---------------------------------------------------------------

TEST(ShaderSource, EmbeddedShadersArePortableGlsl) {
  ASSERT_FALSE(embedded_shaders().empty());
  for (const EmbeddedShader& s : embedded_shaders()) {
    const std::string_view text = s.text;
    const std::string_view name = s.name;
    if (name.ends_with(".comp")) {
      EXPECT_TRUE(text.starts_with("#version 450")) << name;
    }
    // Drivers differ on non-ASCII bytes, even in comments.
    for (char c : text) ASSERT_GE(static_cast<signed char>(c), 0) << name << " has non-ASCII text";
  }
  EXPECT_FALSE(embedded_shader("horizon_exact.comp").empty());
  EXPECT_THROW(embedded_shader("no_such.comp"), std::out_of_range);
}

TEST(ShaderSource, DefinesGoAfterVersionAndLinesMapBack) {
  GlslDefines defines;
  defines.set("W", 32).set("R_EFF", 7322988.5).set("NEG", -2);
  const AssembledShader s = assemble_shader_text(
      "main.comp", "#version 450\nline2\n#include \"horizon_ray.glsl\"\nline4\n", defines);
  EXPECT_TRUE(s.text.starts_with("#version 450\n#define W 32\n#define R_EFF 7322988.5\n"
                                 "#define NEG (-2)\nline2\n"));
  EXPECT_TRUE(s.text.ends_with("\nline4\n"));
  ASSERT_EQ(s.source_names.size(), 3u);
  EXPECT_EQ(s.source_names[2], "horizon_ray.glsl");
  // Assembled line 6 is the include's first line; the last line is main.comp:4.
  EXPECT_EQ(s.map_log("0:3(1): error: x"), "<generated defines>:2(1): error: x");
  EXPECT_EQ(s.map_log("0(6) : error C0000: y"), "horizon_ray.glsl:1 : error C0000: y");
  const int last = static_cast<int>(s.line_origins.size());
  EXPECT_EQ(s.map_log("ERROR: 0:" + std::to_string(last) + ": z"), "ERROR: main.comp:4: z");
  EXPECT_EQ(s.map_log("10:3 stays"), "10:3 stays");
}

TEST(ShaderSource, RejectsBadInput) {
  GlslDefines d;
  d.set("A", 1);
  EXPECT_THROW(d.set("A", 2), std::invalid_argument);
  EXPECT_THROW(d.set("1A", 2), std::invalid_argument);
  EXPECT_THROW(assemble_shader_text("x.comp", "void main() {}\n", d), std::runtime_error);
  EXPECT_THROW(assemble_shader_text("x.comp", "#version 450\n#include \"nope.glsl\"\n", d),
               std::runtime_error);
}

TEST(ShaderSource, FloatLiteralsRoundTripFloat32) {
  for (double v : {std::numbers::pi, 6371000.0 / 0.87, 1.0 / (2.0 * 7322988.5), 0.5, 3.0, -1e-30}) {
    const std::string s = glsl_float_literal(v);
    EXPECT_NE(s.find_first_of(".eE"), std::string::npos) << s;
    EXPECT_EQ(std::strtof(s.c_str(), nullptr), static_cast<float>(v)) << s;
  }
}

// --- with a context ---------------------------------------------------------------

TEST_F(GpuContextTest, CreatesGl45CoreContext) {
  std::cout << "[ renderer ] " << context->renderer() << " | " << context->version() << " | "
            << context->platform() << "\n";
  EXPECT_FALSE(context->renderer().empty());
  EXPECT_TRUE(context->version().starts_with("4.")) << context->version();
  EXPECT_NO_THROW(throw_on_gl_error("after context creation"));
}

// Each platform either gives a 4.5 context or says why in the documented form.
TEST_F(GpuContextTest, EachPlatformWorksOrSaysWhy) {
  for (EglPlatform platform : {EglPlatform::Device, EglPlatform::Surfaceless}) {
    try {
      HeadlessContext c({platform});
      std::cout << "[ platform ] " << c.platform() << ": " << c.renderer() << "\n";
      EXPECT_TRUE(c.version().starts_with("4.")) << c.version();
    } catch (const std::runtime_error& e) {
      std::cout << "[ platform ] " << e.what() << "\n";
      EXPECT_TRUE(std::string_view(e.what()).starts_with("no OpenGL 4.5 context could be created: "))
          << e.what();
    }
  }
  context->make_current();
  EXPECT_NO_THROW(throw_on_gl_error("back on the first context"));
}

TEST_F(GpuContextTest, ContextsOnTheSameDisplayOutliveEachOther) {
  { HeadlessContext second; }  // shares the display; must not terminate it
  context->make_current();
  Buffer b(16);
  EXPECT_NO_THROW(throw_on_gl_error("after a second context came and went"));
}

// Paths of the shared objects mapped now, read from /proc/self/maps (not the loader's
// list that gl_context.cpp pins by).
std::set<std::string> mapped_objects() {
  std::ifstream maps("/proc/self/maps");
  std::set<std::string> paths;
  for (std::string line; std::getline(maps, line);)
    if (const auto slash = line.find('/'); slash != std::string::npos && line.find(".so", slash) != std::string::npos)
      paths.insert(line.substr(slash));
  return paths;
}

// eglTerminate would unload the driver with the last context; it stays, so LeakSanitizer
// still sees the globals that hold the driver's once-only allocations.
TEST_F(GpuContextTest, DriverStaysLoadedAfterTheLastContext) {
  const std::set<std::string> with_context = mapped_objects();
  context.reset();
  const std::set<std::string> without = mapped_objects();
  for (const std::string& path : with_context) EXPECT_TRUE(without.contains(path)) << path << " was unloaded";
}

TEST_F(GpuContextTest, CompileErrorCarriesInfoLogAndSourceNames) {
  const std::string msg = compile_error(
      "broken.comp", "#version 450\nlayout(local_size_x = 1) in;\nvoid main() { undeclared_thing = 1; }\n");
  EXPECT_NE(msg.find("compiling broken.comp failed"), std::string::npos) << msg;
  EXPECT_NE(msg.find("undeclared_thing"), std::string::npos) << msg;
  EXPECT_NE(msg.find("broken.comp:3"), std::string::npos) << msg;
}

TEST_F(GpuContextTest, CompileErrorInAnIncludeNamesTheInclude) {
  // horizon_ray.glsl needs HEIGHTS_BINDING & co.; without the defines it must fail,
  // and the message must point into horizon_ray.glsl.
  const std::string msg = compile_error(
      "uses_include.comp",
      "#version 450\n#include \"horizon_ray.glsl\"\nlayout(local_size_x = 1) in;\nvoid main() {}\n");
  EXPECT_NE(msg.find("horizon_ray.glsl:"), std::string::npos) << msg;
}

TEST_F(GpuContextTest, LinkedProgramReportsLocalSizeAndRejectsUnknownUniforms) {
  GlslDefines d;
  d.set("LOCAL_X", 16).set("LOCAL_Y", 4);
  const ComputeProgram p = inline_program(
      "sizes.comp", "#version 450\nlayout(local_size_x = LOCAL_X, local_size_y = LOCAL_Y) in;\nvoid main() {}\n", d);
  EXPECT_EQ(p.local_size(), (std::array<int, 3>{16, 4, 1}));
  EXPECT_THROW(p.set_uniform("not_there", 1), std::runtime_error);
}

// C++ values reach the shader unchanged through the generated #define block, scalars
// and whole constant arrays (here the shading library's wedge operator, as the surface
// kernel gets its wedge matrix).
TEST_F(GpuContextTest, GeneratedDefinesAndConstantArraysReachTheShader) {
  const sh::WedgeOperator& op = sh::wedge_operator(4, 8, 32, sh::WedgeInterpolation::Linear);
  const std::span<const double> m = op.matrix();
  GlslDefines d;
  d.set("PI", std::numbers::pi).set("ANSWER", 42).set("WEDGE_SIZE", static_cast<int>(m.size()));
  d.set_literal("WEDGE", glsl_float_array_literal(m));
  const ComputeProgram p = inline_program("constants.comp", R"(#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) writeonly buffer Out { float result[]; };
void main() {
  const float wedge[WEDGE_SIZE] = WEDGE;
  uint k = gl_GlobalInvocationID.x;
  if (k == 0u) { result[0] = PI; result[1] = float(ANSWER); }
  if (k < uint(WEDGE_SIZE)) result[2u + k] = wedge[k];
}
)", d);
  Buffer out((2 + m.size()) * sizeof(float));
  out.bind_storage(0);
  p.dispatch_covering(static_cast<int>(m.size()));
  const std::vector<float> r = out.download_all<float>();
  EXPECT_EQ(r[0], static_cast<float>(std::numbers::pi));
  EXPECT_EQ(r[1], 42.0f);
  for (std::size_t k = 0; k < m.size(); ++k) ASSERT_EQ(r[2 + k], static_cast<float>(m[k])) << "element " << k;
}

TEST_F(GpuContextTest, BuffersAndTexturesRoundTrip) {
  const std::vector<float> values{1.5f, -2.0f, 3.25f, 4.0f, 5.0f, 6.0f};
  Buffer b = Buffer::from(std::span<const float>(values));
  EXPECT_EQ(b.download_all<float>(), values);
  const float patch = 9.0f;
  b.upload(&patch, sizeof patch, 2 * sizeof(float));
  EXPECT_EQ(b.download_all<float>()[2], 9.0f);
  EXPECT_THROW(b.upload(&patch, sizeof patch, values.size() * sizeof(float)), std::out_of_range);
  b.fill_zero();
  EXPECT_EQ(b.download_all<float>(), std::vector<float>(values.size(), 0.0f));

  Texture2D t(3, 2, TextureFormat::R32F);
  t.upload(values);
  EXPECT_EQ(t.download(), values);
  // Through an image binding: a shader doubles every texel in place.
  const ComputeProgram p = inline_program("double.comp", R"(#version 450
layout(local_size_x = 4, local_size_y = 4) in;
layout(r32f, binding = 0) uniform image2D img;
void main() {
  ivec2 q = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(q, imageSize(img)))) return;
  imageStore(img, q, 2.0 * imageLoad(img, q));
}
)");
  t.bind_image(0, true, true);
  p.dispatch_covering(t.width(), t.height());
  const std::vector<float> doubled = t.download();
  for (std::size_t k = 0; k < values.size(); ++k) EXPECT_EQ(doubled[k], 2.0f * values[k]);
}

TEST_F(GpuContextTest, TimerMeasuresADispatch) {
  const ComputeProgram p = inline_program("busy.comp", R"(#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Out { float v[]; };
void main() {
  float x = float(gl_GlobalInvocationID.x);
  for (int k = 0; k < 256; ++k) x = sin(x) + 1.0;
  v[gl_GlobalInvocationID.x] = x;
}
)");
  Buffer out(4096 * sizeof(float));
  out.bind_storage(0);
  GpuTimer timer;
  EXPECT_THROW((void)timer.elapsed_ms(), std::logic_error);
  {
    ScopedGpuTimer scope(timer);
    p.dispatch_covering(4096);
  }
  const double ms = timer.elapsed_ms();
  std::cout << "[ timing   ] 4096 × 256 sin: " << ms << " ms\n";
  EXPECT_GE(ms, 0.0);
  EXPECT_LT(ms, 10000.0);
}

}  // namespace
}  // namespace skylit::gpu
