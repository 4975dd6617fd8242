#include "gpu/compute_program.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "gpu/gl_context.h"

namespace skylit::gpu {
namespace {

std::string shader_log(GLuint shader) {
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  glGetShaderInfoLog(shader, length, nullptr, log.data());
  log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
  return log;
}

std::string program_log(GLuint program) {
  GLint length = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  glGetProgramInfoLog(program, length, nullptr, log.data());
  log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
  return log;
}

int groups(int n, int local) { return n <= 0 ? 0 : (n + local - 1) / local; }

}  // namespace

ComputeProgram ComputeProgram::from_embedded(std::string_view name, const GlslDefines& defines) {
  return ComputeProgram(assemble_shader(name, defines));
}

ComputeProgram::ComputeProgram(const AssembledShader& source) : mName(source.source_names.at(1)) {
  const GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
  const char* text = source.text.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    const std::string log = shader_log(shader);
    glDeleteShader(shader);
    throw std::runtime_error("compiling " + mName + " failed:\n" + source.map_log(log));
  }
  mProgram = glCreateProgram();
  glAttachShader(mProgram, shader);
  glLinkProgram(mProgram);
  glDetachShader(mProgram, shader);
  glDeleteShader(shader);
  glGetProgramiv(mProgram, GL_LINK_STATUS, &ok);
  if (!ok) {
    const std::string log = program_log(mProgram);
    glDeleteProgram(mProgram);
    mProgram = 0;
    throw std::runtime_error("linking " + mName + " failed:\n" + log);
  }
  glGetProgramiv(mProgram, GL_COMPUTE_WORK_GROUP_SIZE, mLocalSize.data());
  throw_on_gl_error("ComputeProgram(" + mName + ")");
}

ComputeProgram::~ComputeProgram() {
  if (mProgram) glDeleteProgram(mProgram);
}

ComputeProgram::ComputeProgram(ComputeProgram&& other) noexcept
    : mProgram(std::exchange(other.mProgram, 0)),
      mName(std::move(other.mName)),
      mLocalSize(other.mLocalSize) {}

ComputeProgram& ComputeProgram::operator=(ComputeProgram&& other) noexcept {
  if (this != &other) {
    if (mProgram) glDeleteProgram(mProgram);
    mProgram = std::exchange(other.mProgram, 0);
    mName = std::move(other.mName);
    mLocalSize = other.mLocalSize;
  }
  return *this;
}

int ComputeProgram::uniform_location(std::string_view name) const {
  const GLint location = glGetUniformLocation(mProgram, std::string(name).c_str());
  if (location < 0)
    throw std::runtime_error(mName + ": no active uniform '" + std::string(name) + "'");
  return location;
}

bool ComputeProgram::has_uniform(std::string_view name) const {
  return glGetUniformLocation(mProgram, std::string(name).c_str()) >= 0;
}

void ComputeProgram::set_uniform(std::string_view name, int value) const {
  glProgramUniform1i(mProgram, uniform_location(name), value);
}

void ComputeProgram::set_uniform(std::string_view name, unsigned value) const {
  glProgramUniform1ui(mProgram, uniform_location(name), value);
}

void ComputeProgram::set_uniform(std::string_view name, float value) const {
  glProgramUniform1f(mProgram, uniform_location(name), value);
}

void ComputeProgram::set_uniform(std::string_view name, double value) const {
  glProgramUniform1d(mProgram, uniform_location(name), value);
}

void ComputeProgram::set_uniform(std::string_view name, float x, float y, float z) const {
  glProgramUniform3f(mProgram, uniform_location(name), x, y, z);
}

void ComputeProgram::set_uniform(std::string_view name, int x, int y) const {
  glProgramUniform2i(mProgram, uniform_location(name), x, y);
}

void ComputeProgram::dispatch_covering(int nx, int ny, int nz) const {
  const int gx = groups(nx, mLocalSize[0]), gy = groups(ny, mLocalSize[1]),
            gz = groups(nz, mLocalSize[2]);
  if (gx == 0 || gy == 0 || gz == 0) return;
  glUseProgram(mProgram);
  glDispatchCompute(static_cast<GLuint>(gx), static_cast<GLuint>(gy), static_cast<GLuint>(gz));
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
  throw_on_gl_error(mName + ": dispatch");
}

}  // namespace skylit::gpu
