// Keeps a GL driver loaded for the rest of the process. Closing the last context
// (eglTerminate, glfwTerminate) unloads Mesa's driver, whose globals then no longer
// root what it allocated once per process: LeakSanitizer reports those tables as leaks
// of an "<unknown module>" (seen with Mesa 22.3.6-1+deb12u2). Kept loaded, they stay
// reachable, a real leak of the driver is still reported under the driver's name, and
// a later context does not reload it.
#pragma once

#include <set>
#include <string>

namespace skylit::gpu {

class LoadedObjects {
 public:
  LoadedObjects();  // the shared objects mapped now
  // Pins (RTLD_NODELETE) every object loaded since construction: the EGL or GLX vendor,
  // its driver, LLVM.
  void keep_the_new_loaded() const;

 private:
  std::set<std::string> paths_;
};

}  // namespace skylit::gpu
