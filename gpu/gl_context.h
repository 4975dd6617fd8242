// A headless OpenGL 4.5 core context through EGL, for compute work without a window.
// Platforms: the EGL device platform (EGL_EXT_platform_device; how NVIDIA drivers run
// headless) and Mesa's surfaceless platform (EGL_MESA_platform_surfaceless; llvmpipe
// when there is no GPU, which is how CI runs the GL tests).
#pragma once

#include <string>
#include <string_view>

namespace skylit::gpu {

enum class EglPlatform {
  Automatic,    // hardware device, else surfaceless, else any device (software)
  Device,       // EGL_EXT_platform_device, preferring a non-software device
  Surfaceless,  // EGL_MESA_platform_surfaceless
};

struct ContextOptions {
  EglPlatform platform = EglPlatform::Automatic;
};

// Tag: use the GL 4.5 context already current on this thread (a window's, made by GLFW).
struct AdoptCurrentContext {
  std::string platform = "window";  // what platform() reports
};

// Owns an EGL display reference and a GL 4.5 core context (with compute shaders), made
// current on the constructing thread. GL objects (buffers, programs) must be
// destroyed while their context is current, i.e. before the HeadlessContext.
class HeadlessContext {
 public:
  // Throws std::runtime_error("no OpenGL 4.5 context could be created: …") naming
  // what each platform tried answered.
  explicit HeadlessContext(const ContextOptions& options = {});
  // Owns nothing: make_current() and release_current() leave the window's context to
  // its owner, whose thread then draws and computes (one context, so the renderer's
  // buffers are the viewer's textures). Throws std::runtime_error without a current
  // GL 4.5 context.
  explicit HeadlessContext(const AdoptCurrentContext& adopt);
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  void make_current() const;     // on the calling thread
  void release_current() const;  // the calling thread then has no current context

  const std::string& renderer() const { return mRenderer; }  // GL_RENDERER
  const std::string& version() const { return mVersion; }    // GL_VERSION
  const std::string& platform() const { return mPlatform; }  // e.g. "EGL surfaceless"
  // True for Mesa's CPU rasterisers (llvmpipe, softpipe): slow; timings not representative.
  bool is_software() const;

 private:
  void* mDisplay = nullptr;  // EGLDisplay
  void* mContext = nullptr;  // EGLContext
  bool mOwned = true;
  std::string mRenderer, mVersion, mPlatform;
};

// True for Mesa's CPU rasterisers (llvmpipe, softpipe), by their GL_RENDERER string.
bool is_software_renderer(std::string_view renderer);

// Throws std::runtime_error("<where>: GL error 0x…") if glGetError reports one
// (all pending errors are drained). Needs a current context.
void throw_on_gl_error(std::string_view where);

}  // namespace skylit::gpu
