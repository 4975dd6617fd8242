// RAII owners of GL buffer and texture objects (DSA, immutable storage). Construct
// and destroy them while a context is current; they are movable, not copyable.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace skylit::gpu {

// Throws std::runtime_error("<what> needs … bytes, over GL_MAX_SHADER_STORAGE_BLOCK_SIZE …")
// where one storage block (one bound range) would exceed the driver's limit, or
// `limit_bytes` where that is lower (0: the driver's; tests lower it). Needs a current context.
void check_storage_size(std::size_t bytes, const char* what, std::size_t limit_bytes = 0);

// Throws std::runtime_error("<what> needs … texels, over GL_MAX_TEXTURE_BUFFER_SIZE …")
// where a buffer texture of that many texels would exceed the driver's limit.
void check_texture_buffer_size(std::size_t texels, const char* what);

// GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT: Buffer::bind_storage_range offsets are multiples of it.
std::size_t storage_offset_alignment();

// A buffer object usable as SSBO or UBO; contents can be rewritten and read back.
class Buffer {
 public:
  Buffer() = default;  // no GL object
  explicit Buffer(std::size_t size_bytes, const void* data = nullptr);
  template <class T>
  static Buffer from(std::span<const T> values) {
    return Buffer(values.size_bytes(), values.data());
  }
  ~Buffer();
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  std::uint32_t id() const { return mId; }
  std::size_t size_bytes() const { return mSize; }

  // Byte ranges must lie inside the buffer (throws std::out_of_range otherwise).
  void upload(const void* data, std::size_t bytes, std::size_t offset = 0);
  void download(void* data, std::size_t bytes, std::size_t offset = 0) const;
  template <class T>
  std::vector<T> download_all() const {
    std::vector<T> out(mSize / sizeof(T));
    download(out.data(), out.size() * sizeof(T));
    return out;
  }
  void fill_zero();
  // A new buffer holding this one's bytes (copied on the GL side).
  Buffer copy() const;
  // This buffer's bytes become `from`'s; reallocated when the sizes differ.
  void assign(const Buffer& from);

  void bind_storage(unsigned binding) const;  // layout(std430, binding = …) buffer
  // Bytes [offset, offset + bytes) as the storage block at `binding`: the block-size
  // limit applies to the range, not the buffer. offset: a multiple of
  // storage_offset_alignment() (throws std::invalid_argument otherwise).
  void bind_storage_range(unsigned binding, std::size_t offset, std::size_t bytes) const;
  void bind_uniform(unsigned binding) const;  // layout(std140, binding = …) uniform

 private:
  std::uint32_t mId = 0;
  std::size_t mSize = 0;
};

// RGBA8: unsigned normalised bytes, which a software rasteriser filters far faster than floats.
enum class TextureFormat { R32F, RG32F, RGBA32F, RGBA8 };

// A single-level 2D texture, float or RGBA8 (read as floats in [0, 1]): no mipmaps,
// nearest filtering unless set_linear_filter(), clamp to edge. Shaders read it with texelFetch (exact) or bind it as an image.
class Texture2D {
 public:
  Texture2D() = default;
  Texture2D(int width, int height, TextureFormat format);
  ~Texture2D();
  Texture2D(Texture2D&& other) noexcept;
  Texture2D& operator=(Texture2D&& other) noexcept;
  Texture2D(const Texture2D&) = delete;
  Texture2D& operator=(const Texture2D&) = delete;

  std::uint32_t id() const { return mId; }
  int width() const { return mWidth; }
  int height() const { return mHeight; }
  int channels() const { return mFormat == TextureFormat::R32F ? 1 : mFormat == TextureFormat::RG32F ? 2 : 4; }
  // Bilinear filtering for texture() lookups (texelFetch stays exact).
  void set_linear_filter();

  // Whole-texture transfers, row 0 first; size must be width·height·channels.
  void upload(std::span<const float> texels);
  std::vector<float> download() const;

  void bind_sampler(unsigned unit) const;                       // sampler2D at `unit`
  void bind_image(unsigned unit, bool read, bool write) const;  // image2D at `unit`

 private:
  std::uint32_t mId = 0;
  int mWidth = 0, mHeight = 0;
  TextureFormat mFormat = TextureFormat::R32F;
};

// A single-level r16ui 2D array texture of 16-bit codes (nearest, clamp to edge): one
// layer per band, written as a layered uimage2DArray and read with texelFetch from a
// usampler2DArray (the sweep's far slopes, horizon::encode_far_slope).
// No storage-block or buffer-texture limit applies, only GL_MAX_TEXTURE_SIZE and
// GL_MAX_ARRAY_TEXTURE_LAYERS (throws std::runtime_error beyond them).
class TextureArray {
 public:
  TextureArray() = default;
  TextureArray(int width, int height, int layers);
  ~TextureArray();
  TextureArray(TextureArray&& other) noexcept;
  TextureArray& operator=(TextureArray&& other) noexcept;
  TextureArray(const TextureArray&) = delete;
  TextureArray& operator=(const TextureArray&) = delete;

  std::uint32_t id() const { return mId; }
  void clear(std::uint16_t value) const;  // every texel of every layer
  std::vector<std::uint16_t> download() const;  // layer-major, row 0 first
  // One layer's width × height codes, row 0 first (throws std::out_of_range otherwise).
  void upload_layer(int layer, std::span<const std::uint16_t> codes) const;
  void bind_sampler(unsigned unit) const;                       // sampler2DArray at `unit`
  void bind_image(unsigned unit, bool read, bool write) const;  // image2DArray, all layers

 private:
  std::uint32_t mId = 0;
  int mWidth = 0, mHeight = 0, mLayers = 0;
};

// A buffer texture (samplerBuffer, texelFetch by index) viewing a Buffer as r32f or rgba32f.
// Mesa llvmpipe gathers texel fetches with vector code, where an SSBO load with
// per-invocation offsets is a scalar loop over the SIMD lanes: the march reads its
// heights and pyramid through these. The Buffer must outlive the view.
class BufferTexture {
 public:
  BufferTexture() = default;
  // Throws std::runtime_error if the buffer exceeds GL_MAX_TEXTURE_BUFFER_SIZE texels.
  explicit BufferTexture(const Buffer& values, TextureFormat format = TextureFormat::R32F);
  ~BufferTexture();
  BufferTexture(BufferTexture&& other) noexcept;
  BufferTexture& operator=(BufferTexture&& other) noexcept;
  BufferTexture(const BufferTexture&) = delete;
  BufferTexture& operator=(const BufferTexture&) = delete;

  void bind_sampler(unsigned unit) const;  // samplerBuffer at `unit`
  std::uint32_t id() const { return mId; }  // 0: none

 private:
  std::uint32_t mId = 0;
};

}  // namespace skylit::gpu
