#include "gpu/resident_field.h"

#include <algorithm>
#include <stdexcept>

#include "gpu/buffers.h"

namespace skylit::gpu {
namespace {

// Words [word0, word1) of the packed valid mask (the shaders' valid_bytes: 1 byte per
// texel, four per word, little end first).
std::vector<std::uint32_t> valid_words(const terrain::HeightField& field, std::size_t word0, std::size_t word1) {
  std::vector<std::uint32_t> words(word1 - word0, 0u);
  for (std::size_t k = word0 * 4; k < std::min(word1 * 4, field.size()); ++k)
    words[k / 4 - word0] |= static_cast<std::uint32_t>(field.valid[k] != 0) << (8 * (k % 4));
  return words;
}

}  // namespace

std::size_t ResidentField::sync(const terrain::HeightField& field) {
  const std::size_t texels = field.size();
  if (field.width < 1 || field.height < 1 || texels != static_cast<std::size_t>(field.width) * field.height ||
      field.valid.size() != texels || static_cast<int>(field.dx_per_row.size()) != field.height)
    throw std::invalid_argument("GPU pipeline: malformed height field");
  const terrain::PixelRect& dirty = field.last_dirty;
  const bool edited = field.id.value() == mSourceId && field.width == mWidth && field.height == mHeight && field.dy == mDy &&
                      field.dx_per_row == mDx && field.one_edit_since(mRevision);
  const bool unchanged = field.id.value() == mSourceId && field.width == mWidth && field.height == mHeight &&
                         field.dy == mDy && field.dx_per_row == mDx && field.revision == mRevision;
  if (unchanged) return 0;  // every change goes through mark_dirty (terrain/height_field.h)
  if (!edited) return upload_whole(field);
  // Rows y0 … y1 − 1: contiguous in the heights, and in the valid words that hold them.
  const std::size_t w = static_cast<std::size_t>(field.width);
  const std::size_t first = dirty.y0 * w, count = dirty.height * w;
  mHeights.upload(field.heights.data() + first, count * sizeof(float), first * sizeof(float));
  const std::size_t word0 = first / 4, word1 = (first + count + 3) / 4;
  const std::vector<std::uint32_t> words = valid_words(field, word0, word1);
  mValid.upload(words.data(), words.size() * sizeof(std::uint32_t), word0 * sizeof(std::uint32_t));
  mRevision = field.revision;
  return count * sizeof(float) + words.size() * sizeof(std::uint32_t);
}

std::size_t ResidentField::upload_whole(const terrain::HeightField& field) {
  check_storage_size(field.size() * sizeof(float), "GPU pipeline: the heights");
  const std::vector<std::uint32_t> valid = valid_words(field, 0, (field.size() + 3) / 4);
  const std::vector<float> row_dx(field.dx_per_row.begin(), field.dx_per_row.end());
  if (mHeights.size_bytes() == field.size() * sizeof(float) && mRowDx.size_bytes() == row_dx.size() * sizeof(float)) {
    mHeights.upload(field.heights.data(), mHeights.size_bytes());
    mValid.upload(valid.data(), valid.size() * sizeof(std::uint32_t));
    mRowDx.upload(row_dx.data(), mRowDx.size_bytes());
  } else {
    mHeights = Buffer::from(std::span<const float>(field.heights));
    mValid = Buffer::from(std::span<const std::uint32_t>(valid));
    mRowDx = Buffer::from(std::span<const float>(row_dx));
  }
  mSourceId = field.id.value();
  mWidth = field.width;
  mHeight = field.height;
  mDy = field.dy;
  mDx = field.dx_per_row;
  mRevision = field.revision;
  return mHeights.size_bytes() + mValid.size_bytes() + mRowDx.size_bytes();
}

std::size_t ResidentTable::assign(std::span<const float> values) {
  if (mSet && values.size() == mValues.size() && std::equal(values.begin(), values.end(), mValues.begin())) return 0;
  mValues.assign(values.begin(), values.end());
  if (mValues.empty()) mValues.assign(1, 0.0f);  // GL wants non-empty buffers bound
  if (mBuffer.size_bytes() == mValues.size() * sizeof(float))
    mBuffer.upload(mValues.data(), mBuffer.size_bytes());
  else
    mBuffer = Buffer::from(std::span<const float>(mValues));
  mSet = true;
  return mBuffer.size_bytes();
}

}  // namespace skylit::gpu
