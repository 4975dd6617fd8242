// Which renderer computes (DESIGN.md "Backends"), chosen in the library so that no front
// end picks a backend or caches a pipeline itself.
#pragma once

#include "shading/renderer.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace skylit::gpu {

enum class Backend {
  // The GPU where an OpenGL 4.5 context can be created and the GPU has the product with
  // the frame's options (gpu_supports: the lit products not with the exact march), else
  // the CPU reference; also the reference when the GPU fails at run time (a field over
  // its buffer limits, say), with a note.
  Auto,
  Gpu,        // OpenGL 4.5 compute; an error where no context can be created
  Reference,  // CPU, double precision
};

std::vector<std::string> backend_names();  // "auto", "gpu", "reference": the default first
std::string_view backend_name(Backend backend);
std::optional<Backend> parse_backend(std::string_view name);

// A note for the user (one line), e.g. why `Auto` computed on the CPU.
using NoteCallback = std::function<void(const std::string&)>;

// Throws std::runtime_error (one line) for Gpu where no context can be created.
std::unique_ptr<shading::Renderer> make_renderer(Backend backend, NoteCallback note = {});

}  // namespace skylit::gpu
