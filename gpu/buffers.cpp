#include "gpu/buffers.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace skylit::gpu {
namespace {

void check_range(std::size_t offset, std::size_t bytes, std::size_t size, const char* what) {
  if (offset > size || bytes > size - offset)
    throw std::out_of_range(std::string(what) + ": bytes [" + std::to_string(offset) + ", " +
                            std::to_string(offset + bytes) + ") outside a buffer of " +
                            std::to_string(size));
}

GLenum internal_format(TextureFormat f) {
  switch (f) {
    case TextureFormat::R32F: return GL_R32F;
    case TextureFormat::RG32F: return GL_RG32F;
    case TextureFormat::RGBA32F: return GL_RGBA32F;
    case TextureFormat::RGBA8: return GL_RGBA8;
  }
  return GL_RGBA32F;
}
GLenum pixel_format(TextureFormat f) {
  return f == TextureFormat::R32F ? GL_RED : f == TextureFormat::RG32F ? GL_RG : GL_RGBA;
}

}  // namespace

void check_storage_size(std::size_t bytes, const char* what, std::size_t limit_bytes) {
  GLint64 max_block = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &max_block);
  const std::size_t gl_limit = static_cast<std::size_t>(max_block);
  const bool lowered = limit_bytes != 0 && limit_bytes < gl_limit;
  if (bytes > (lowered ? limit_bytes : gl_limit))
    throw std::runtime_error(std::string(what) + " needs " + std::to_string(bytes) + " bytes, over " +
                             (lowered ? "the binding limit " + std::to_string(limit_bytes) + " set below " : "") +
                             "GL_MAX_SHADER_STORAGE_BLOCK_SIZE " + std::to_string(gl_limit) +
                             "; split the field into tiles");
}

void check_texture_buffer_size(std::size_t texels, const char* what) {
  GLint max_texels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &max_texels);
  if (texels > static_cast<std::size_t>(max_texels))
    throw std::runtime_error(std::string(what) + " needs " + std::to_string(texels) +
                             " texels, over GL_MAX_TEXTURE_BUFFER_SIZE " + std::to_string(max_texels) +
                             "; split the field into tiles");
}

std::size_t storage_offset_alignment() {
  GLint alignment = 0;
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &alignment);
  return static_cast<std::size_t>(std::max(alignment, 1));
}

Buffer::Buffer(std::size_t size_bytes, const void* data) : mSize(size_bytes) {
  glCreateBuffers(1, &mId);
  // GL forbids zero-sized storage; one byte keeps an "empty" buffer bindable.
  glNamedBufferStorage(mId, static_cast<GLsizeiptr>(std::max<std::size_t>(size_bytes, 1)),
                       size_bytes ? data : nullptr, GL_DYNAMIC_STORAGE_BIT);
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    glDeleteBuffers(1, &mId);
    throw std::runtime_error("Buffer: allocating " + std::to_string(size_bytes) +
                             " bytes failed (GL error " + std::to_string(error) + ")");
  }
}

Buffer::~Buffer() {
  if (mId) glDeleteBuffers(1, &mId);
}

Buffer::Buffer(Buffer&& other) noexcept
    : mId(std::exchange(other.mId, 0)), mSize(std::exchange(other.mSize, 0)) {}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    if (mId) glDeleteBuffers(1, &mId);
    mId = std::exchange(other.mId, 0);
    mSize = std::exchange(other.mSize, 0);
  }
  return *this;
}

void Buffer::upload(const void* data, std::size_t bytes, std::size_t offset) {
  check_range(offset, bytes, mSize, "Buffer::upload");
  if (bytes)
    glNamedBufferSubData(mId, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
}

void Buffer::download(void* data, std::size_t bytes, std::size_t offset) const {
  check_range(offset, bytes, mSize, "Buffer::download");
  if (bytes)
    glGetNamedBufferSubData(mId, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes),
                            data);
}

void Buffer::fill_zero() {
  glClearNamedBufferData(mId, GL_R8UI, GL_RED_INTEGER, GL_UNSIGNED_BYTE, nullptr);
}

Buffer Buffer::copy() const {
  Buffer out(mSize);
  if (mSize) glCopyNamedBufferSubData(mId, out.mId, 0, 0, static_cast<GLsizeiptr>(mSize));
  return out;
}

void Buffer::assign(const Buffer& from) {
  if (mSize != from.mSize) {
    *this = Buffer();  // the old storage goes first
    *this = Buffer(from.mSize);
  }
  if (mSize) glCopyNamedBufferSubData(from.mId, mId, 0, 0, static_cast<GLsizeiptr>(mSize));
}

void Buffer::bind_storage(unsigned binding) const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, mId);
}

void Buffer::bind_storage_range(unsigned binding, std::size_t offset, std::size_t bytes) const {
  check_range(offset, bytes, mSize, "Buffer::bind_storage_range");
  if (offset % storage_offset_alignment() != 0)
    throw std::invalid_argument("Buffer::bind_storage_range: offset " + std::to_string(offset) +
                                " is not a multiple of GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT");
  glBindBufferRange(GL_SHADER_STORAGE_BUFFER, binding, mId, static_cast<GLintptr>(offset),
                    static_cast<GLsizeiptr>(bytes));
}

void Buffer::bind_uniform(unsigned binding) const {
  glBindBufferBase(GL_UNIFORM_BUFFER, binding, mId);
}

Texture2D::Texture2D(int width, int height, TextureFormat format)
    : mWidth(width), mHeight(height), mFormat(format) {
  if (width < 1 || height < 1)
    throw std::invalid_argument("Texture2D: size must be positive");
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  if (width > max_size || height > max_size)
    throw std::runtime_error("Texture2D: " + std::to_string(width) + "×" +
                             std::to_string(height) + " exceeds GL_MAX_TEXTURE_SIZE " +
                             std::to_string(max_size) + " (process in tiles)");
  glCreateTextures(GL_TEXTURE_2D, 1, &mId);
  glTextureStorage2D(mId, 1, internal_format(format), width, height);
  glTextureParameteri(mId, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(mId, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(mId, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(mId, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

Texture2D::~Texture2D() {
  if (mId) glDeleteTextures(1, &mId);
}

Texture2D::Texture2D(Texture2D&& other) noexcept
    : mId(std::exchange(other.mId, 0)),
      mWidth(other.mWidth),
      mHeight(other.mHeight),
      mFormat(other.mFormat) {}

Texture2D& Texture2D::operator=(Texture2D&& other) noexcept {
  if (this != &other) {
    if (mId) glDeleteTextures(1, &mId);
    mId = std::exchange(other.mId, 0);
    mWidth = other.mWidth;
    mHeight = other.mHeight;
    mFormat = other.mFormat;
  }
  return *this;
}

void Texture2D::upload(std::span<const float> texels) {
  if (texels.size() != static_cast<std::size_t>(mWidth) * mHeight * channels())
    throw std::invalid_argument("Texture2D::upload: wrong number of values");
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(mId, 0, 0, 0, mWidth, mHeight, pixel_format(mFormat), GL_FLOAT,
                      texels.data());
}

std::vector<float> Texture2D::download() const {
  std::vector<float> out(static_cast<std::size_t>(mWidth) * mHeight * channels());
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTextureImage(mId, 0, pixel_format(mFormat), GL_FLOAT,
                    static_cast<GLsizei>(out.size() * sizeof(float)), out.data());
  return out;
}

void Texture2D::set_linear_filter() {
  glTextureParameteri(mId, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(mId, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

void Texture2D::bind_sampler(unsigned unit) const { glBindTextureUnit(unit, mId); }

void Texture2D::bind_image(unsigned unit, bool read, bool write) const {
  const GLenum access = read && write ? GL_READ_WRITE : write ? GL_WRITE_ONLY : GL_READ_ONLY;
  glBindImageTexture(unit, mId, 0, GL_FALSE, 0, access, internal_format(mFormat));
}

TextureArray::TextureArray(int width, int height, int layers) : mWidth(width), mHeight(height), mLayers(layers) {
  if (width < 1 || height < 1 || layers < 1) throw std::invalid_argument("TextureArray: size must be positive");
  GLint max_size = 0, max_layers = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &max_layers);
  if (width > max_size || height > max_size || layers > max_layers)
    throw std::runtime_error("TextureArray: " + std::to_string(width) + "×" + std::to_string(height) + "×" +
                             std::to_string(layers) + " exceeds GL_MAX_TEXTURE_SIZE " + std::to_string(max_size) +
                             " or GL_MAX_ARRAY_TEXTURE_LAYERS " + std::to_string(max_layers) + " (process in tiles)");
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &mId);
  glTextureStorage3D(mId, 1, GL_R16UI, width, height, layers);
  glTextureParameteri(mId, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(mId, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(mId, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(mId, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

TextureArray::~TextureArray() {
  if (mId) glDeleteTextures(1, &mId);
}

TextureArray::TextureArray(TextureArray&& other) noexcept
    : mId(std::exchange(other.mId, 0)), mWidth(other.mWidth), mHeight(other.mHeight), mLayers(other.mLayers) {}

TextureArray& TextureArray::operator=(TextureArray&& other) noexcept {
  if (this != &other) {
    if (mId) glDeleteTextures(1, &mId);
    mId = std::exchange(other.mId, 0);
    mWidth = other.mWidth, mHeight = other.mHeight, mLayers = other.mLayers;
  }
  return *this;
}

void TextureArray::clear(std::uint16_t value) const {
  glClearTexImage(mId, 0, GL_RED_INTEGER, GL_UNSIGNED_SHORT, &value);
}

void TextureArray::upload_layer(int layer, std::span<const std::uint16_t> codes) const {
  if (layer < 0 || layer >= mLayers || codes.size() != static_cast<std::size_t>(mWidth) * mHeight)
    throw std::out_of_range("TextureArray::upload_layer: no such layer, or not one layer's texels");
  glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
  glTextureSubImage3D(mId, 0, 0, 0, layer, mWidth, mHeight, 1, GL_RED_INTEGER, GL_UNSIGNED_SHORT, codes.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
}

std::vector<std::uint16_t> TextureArray::download() const {
  std::vector<std::uint16_t> out(static_cast<std::size_t>(mWidth) * mHeight * mLayers);
  glPixelStorei(GL_PACK_ALIGNMENT, 2);
  glGetTextureImage(mId, 0, GL_RED_INTEGER, GL_UNSIGNED_SHORT, static_cast<GLsizei>(out.size() * sizeof(std::uint16_t)),
                    out.data());
  return out;
}

void TextureArray::bind_sampler(unsigned unit) const { glBindTextureUnit(unit, mId); }

void TextureArray::bind_image(unsigned unit, bool read, bool write) const {
  const GLenum access = read && write ? GL_READ_WRITE : write ? GL_WRITE_ONLY : GL_READ_ONLY;
  glBindImageTexture(unit, mId, 0, GL_TRUE, 0, access, GL_R16UI);
}

BufferTexture::BufferTexture(const Buffer& values, TextureFormat format) {
  check_texture_buffer_size(values.size_bytes() / (sizeof(float) * (format == TextureFormat::R32F ? 1 : 4)),
                            "BufferTexture");
  glCreateTextures(GL_TEXTURE_BUFFER, 1, &mId);
  glTextureBuffer(mId, internal_format(format), values.id());
}

BufferTexture::~BufferTexture() {
  if (mId) glDeleteTextures(1, &mId);
}

BufferTexture::BufferTexture(BufferTexture&& other) noexcept : mId(std::exchange(other.mId, 0)) {}

BufferTexture& BufferTexture::operator=(BufferTexture&& other) noexcept {
  if (this != &other) {
    if (mId) glDeleteTextures(1, &mId);
    mId = std::exchange(other.mId, 0);
  }
  return *this;
}

void BufferTexture::bind_sampler(unsigned unit) const { glBindTextureUnit(unit, mId); }

}  // namespace skylit::gpu
