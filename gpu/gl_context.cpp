#include "gpu/gl_context.h"
#include "gpu/loaded_objects.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <dlfcn.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <stdexcept>
#include <vector>

namespace skylit::gpu {
namespace {

bool has_token(const char* list, std::string_view token) {
  if (!list) return false;
  std::string_view s(list);
  for (std::size_t pos = 0; pos < s.size();) {
    const std::size_t end = std::min(s.find(' ', pos), s.size());
    if (s.substr(pos, end - pos) == token) return true;
    pos = end + 1;
  }
  return false;
}

std::string egl_error_text() {
  char buf[32];
  std::snprintf(buf, sizeof buf, "EGL error 0x%04x", static_cast<unsigned>(eglGetError()));
  return buf;
}

// EGL displays are per-process singletons per native display: two contexts on the same
// display share it, so eglTerminate may run only when the last user lets go.
std::mutex gDisplayMutex;
std::map<EGLDisplay, int> gDisplayUsers;

bool acquire_display(EGLDisplay display) {
  std::lock_guard lock(gDisplayMutex);
  if (gDisplayUsers[display]++ > 0) return true;
  EGLint major = 0, minor = 0;
  if (eglInitialize(display, &major, &minor)) return true;
  gDisplayUsers.erase(display);
  return false;
}

void release_display(EGLDisplay display) {
  std::lock_guard lock(gDisplayMutex);
  if (--gDisplayUsers[display] > 0) return;
  gDisplayUsers.erase(display);
  eglTerminate(display);
}

struct Created {
  EGLDisplay display;
  EGLContext context;
};

// Initialises `display`, creates a GL 4.5 core context and makes it current with no
// surface. Returns nullopt and sets `why` on failure (leaving nothing behind).
std::optional<Created> create_on(EGLDisplay display, std::string& why) {
  if (display == EGL_NO_DISPLAY) {
    why = "no display (" + egl_error_text() + ")";
    return std::nullopt;
  }
  if (!acquire_display(display)) {
    why = "eglInitialize failed (" + egl_error_text() + ")";
    return std::nullopt;
  }
  const char* exts = eglQueryString(display, EGL_EXTENSIONS);
  auto fail = [&](std::string reason) -> std::optional<Created> {
    why = std::move(reason);
    release_display(display);
    return std::nullopt;
  };
  if (!has_token(exts, "EGL_KHR_surfaceless_context"))
    return fail("EGL_KHR_surfaceless_context missing");
  if (!eglBindAPI(EGL_OPENGL_API)) return fail("eglBindAPI(OpenGL) failed: " + egl_error_text());

  EGLConfig config = EGL_NO_CONFIG_KHR;
  if (!has_token(exts, "EGL_KHR_no_config_context")) {
    const EGLint want[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                           EGL_OPENGL_BIT, EGL_NONE};
    EGLint count = 0;
    if (!eglChooseConfig(display, want, &config, 1, &count) || count < 1)
      return fail("no EGL config renders OpenGL");
  }
  const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                            EGL_CONTEXT_OPENGL_PROFILE_MASK,
                            EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, attribs);
  if (context == EGL_NO_CONTEXT)
    return fail("eglCreateContext(GL 4.5 core) failed: " + egl_error_text());
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    const std::string err = egl_error_text();
    eglDestroyContext(display, context);
    return fail("eglMakeCurrent failed: " + err);
  }
  GLint work_group_invocations = 0;
  glGetIntegerv(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS, &work_group_invocations);
  if (epoxy_gl_version() < 45 || work_group_invocations <= 0) {
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display, context);
    return fail(std::string("context is GL ") + (version ? version : "?") +
                ", compute shaders need 4.5");
  }
  return Created{display, context};
}

bool is_software_device(EGLDeviceEXT device) {
  return has_token(eglQueryDeviceStringEXT(device, EGL_EXTENSIONS), "EGL_MESA_device_software");
}

// Tries each EGL device in order, hardware first; `allow_software` admits llvmpipe's.
std::optional<Created> create_on_device(bool allow_software, std::string& why) {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!has_token(client, "EGL_EXT_platform_device") ||
      !has_token(client, "EGL_EXT_device_enumeration")) {
    why = "EGL_EXT_platform_device not supported";
    return std::nullopt;
  }
  EGLint count = 0;
  eglQueryDevicesEXT(0, nullptr, &count);
  std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(std::max(count, 0)));
  if (count > 0) eglQueryDevicesEXT(count, devices.data(), &count);
  devices.resize(static_cast<std::size_t>(std::max(count, 0)));
  std::stable_partition(devices.begin(), devices.end(),
                        [](EGLDeviceEXT d) { return !is_software_device(d); });

  std::string tried;
  for (EGLDeviceEXT device : devices) {
    if (is_software_device(device) && !allow_software) continue;
    std::string reason;
    EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
    if (auto created = create_on(display, reason)) return created;
    tried += (tried.empty() ? "" : "; ") + reason;
  }
  why = devices.empty() ? "no EGL devices"
        : tried.empty() ? "only software EGL devices"
                        : tried;
  return std::nullopt;
}

std::optional<Created> create_surfaceless(std::string& why) {
  if (!has_token(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS), "EGL_MESA_platform_surfaceless")) {
    why = "EGL_MESA_platform_surfaceless not supported";
    return std::nullopt;
  }
  return create_on(eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY,
                                            nullptr),
                   why);
}

std::string gl_string(GLenum name) {
  const char* s = reinterpret_cast<const char*>(glGetString(name));
  return s ? s : "";
}

}  // namespace

HeadlessContext::HeadlessContext(const ContextOptions& options) {
  // libepoxy aborts the process if it cannot load libEGL; check first so callers (and
  // tests that skip without GL) get an exception instead.
  if (!dlopen("libEGL.so.1", RTLD_LAZY | RTLD_GLOBAL))
    throw std::runtime_error(
        "no OpenGL 4.5 context could be created: libEGL.so.1 not found (install libegl1 "
        "and a driver, e.g. libegl-mesa0 + libgl1-mesa-dri for llvmpipe)");
  const LoadedObjects before;
  std::string errors;
  auto attempt = [&](const char* label, auto&& create) -> bool {
    std::string why;
    if (auto created = create(why)) {
      mDisplay = created->display;
      mContext = created->context;
      mPlatform = label;
      return true;
    }
    errors += (errors.empty() ? "" : "; ") + std::string(label) + ": " + why;
    return false;
  };
  auto device_hw = [](std::string& why) { return create_on_device(false, why); };
  auto device_any = [](std::string& why) { return create_on_device(true, why); };
  bool ok = false;
  switch (options.platform) {
    case EglPlatform::Automatic:
      ok = attempt("EGL device", device_hw) || attempt("EGL surfaceless", create_surfaceless) ||
           attempt("EGL software device", device_any);
      break;
    case EglPlatform::Device:
      ok = attempt("EGL device", device_any);
      break;
    case EglPlatform::Surfaceless:
      ok = attempt("EGL surfaceless", create_surfaceless);
      break;
  }
  before.keep_the_new_loaded();
  if (!ok) throw std::runtime_error("no OpenGL 4.5 context could be created: " + errors);
  mRenderer = gl_string(GL_RENDERER);
  mVersion = gl_string(GL_VERSION);
}

HeadlessContext::HeadlessContext(const AdoptCurrentContext& adopt) : mOwned(false), mPlatform(adopt.platform) {
  mRenderer = gl_string(GL_RENDERER);
  mVersion = gl_string(GL_VERSION);
  if (mRenderer.empty() || epoxy_gl_version() < 45)
    throw std::runtime_error("no OpenGL 4.5 context is current (GL_VERSION '" + mVersion + "')");
}

HeadlessContext::~HeadlessContext() {
  if (!mOwned) return;
  if (eglGetCurrentContext() == mContext)
    eglMakeCurrent(mDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(mDisplay, mContext);
  release_display(mDisplay);
}

void HeadlessContext::make_current() const {
  if (!mOwned) return;
  if (!eglMakeCurrent(mDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, mContext))
    throw std::runtime_error("HeadlessContext::make_current: " + egl_error_text());
}

void HeadlessContext::release_current() const {
  if (!mOwned) return;
  eglMakeCurrent(mDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

bool is_software_renderer(std::string_view renderer) {
  return renderer.find("llvmpipe") != std::string_view::npos || renderer.find("softpipe") != std::string_view::npos;
}

bool HeadlessContext::is_software() const { return is_software_renderer(mRenderer); }

void throw_on_gl_error(std::string_view where) {
  std::string codes;
  for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError()) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%04x", e);
    codes += (codes.empty() ? "" : ", ") + std::string(buf);
  }
  if (!codes.empty()) throw std::runtime_error(std::string(where) + ": GL error " + codes);
}

}  // namespace skylit::gpu
