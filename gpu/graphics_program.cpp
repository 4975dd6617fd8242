#include "gpu/graphics_program.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "gpu/gl_context.h"

namespace skylit::gpu {
namespace {

std::string info_log(GLuint object, bool program) {
  GLint length = 0;
  if (program) glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  else glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  if (program) glGetProgramInfoLog(object, length, nullptr, log.data());
  else glGetShaderInfoLog(object, length, nullptr, log.data());
  log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
  return log;
}

GLuint compile(GLenum stage, const AssembledShader& source) {
  const GLuint shader = glCreateShader(stage);
  const char* text = source.text.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    const std::string log = info_log(shader, false);
    glDeleteShader(shader);
    throw std::runtime_error("compiling " + source.source_names.at(1) + " failed:\n" + source.map_log(log));
  }
  return shader;
}

}  // namespace

GraphicsProgram::GraphicsProgram(std::string_view vertex, std::string_view fragment, const GlslDefines& defines)
    : mName(std::string(vertex) + " + " + std::string(fragment)) {
  const AssembledShader vs = assemble_shader(vertex, defines), fs = assemble_shader(fragment, defines);
  mSourceText = vs.text + fs.text;
  const GLuint v = compile(GL_VERTEX_SHADER, vs);
  GLuint f = 0;
  try {
    f = compile(GL_FRAGMENT_SHADER, fs);
  } catch (...) {
    glDeleteShader(v);
    throw;
  }
  mProgram = glCreateProgram();
  glAttachShader(mProgram, v);
  glAttachShader(mProgram, f);
  glLinkProgram(mProgram);
  glDetachShader(mProgram, v);
  glDetachShader(mProgram, f);
  glDeleteShader(v);
  glDeleteShader(f);
  GLint ok = GL_FALSE;
  glGetProgramiv(mProgram, GL_LINK_STATUS, &ok);
  if (!ok) {
    const std::string log = info_log(mProgram, true);
    glDeleteProgram(mProgram);
    mProgram = 0;
    throw std::runtime_error("linking " + mName + " failed:\n" + log);
  }
  throw_on_gl_error("GraphicsProgram(" + mName + ")");
}

GraphicsProgram::~GraphicsProgram() {
  if (mProgram) glDeleteProgram(mProgram);
}

GraphicsProgram::GraphicsProgram(GraphicsProgram&& other) noexcept
    : mProgram(std::exchange(other.mProgram, 0)), mName(std::move(other.mName)), mSourceText(std::move(other.mSourceText)) {}

GraphicsProgram& GraphicsProgram::operator=(GraphicsProgram&& other) noexcept {
  if (this != &other) {
    if (mProgram) glDeleteProgram(mProgram);
    mProgram = std::exchange(other.mProgram, 0);
    mName = std::move(other.mName);
    mSourceText = std::move(other.mSourceText);
  }
  return *this;
}

void GraphicsProgram::use() const { glUseProgram(mProgram); }

int GraphicsProgram::location(std::string_view name) const {
  const std::string n(name);
  const GLint loc = glGetUniformLocation(mProgram, n.c_str());
  if (loc < 0 && mSourceText.find(n) == std::string::npos)
    throw std::logic_error(mName + " declares no uniform '" + n + "'");
  return loc;
}

void GraphicsProgram::set(std::string_view name, int value) const {
  if (const int loc = location(name); loc >= 0) glProgramUniform1i(mProgram, loc, value);
}
void GraphicsProgram::set(std::string_view name, int x, int y) const {
  if (const int loc = location(name); loc >= 0) glProgramUniform2i(mProgram, loc, x, y);
}
void GraphicsProgram::set(std::string_view name, float value) const {
  if (const int loc = location(name); loc >= 0) glProgramUniform1f(mProgram, loc, value);
}
void GraphicsProgram::set(std::string_view name, float x, float y) const {
  if (const int loc = location(name); loc >= 0) glProgramUniform2f(mProgram, loc, x, y);
}
void GraphicsProgram::set(std::string_view name, float x, float y, float z) const {
  if (const int loc = location(name); loc >= 0) glProgramUniform3f(mProgram, loc, x, y, z);
}
void GraphicsProgram::set(std::string_view name, float x, float y, float z, float w) const {
  if (const int loc = location(name); loc >= 0) glProgramUniform4f(mProgram, loc, x, y, z, w);
}
void GraphicsProgram::set_mat4(std::string_view name, const float* column_major) const {
  if (const int loc = location(name); loc >= 0) glProgramUniformMatrix4fv(mProgram, loc, 1, GL_FALSE, column_major);
}

void GraphicsProgram::set_mat3(std::string_view name, const float* column_major) const {
  if (const int loc = location(name); loc >= 0) glProgramUniformMatrix3fv(mProgram, loc, 1, GL_FALSE, column_major);
}

}  // namespace skylit::gpu
