// A height field kept on the GPU between computations (the dynamic height field of
// DESIGN.md): heights, valid mask and row spacing stay resident, and an edited field
// re-uploads only the rows its edit touched.
//
// Which field is "the same": the same object (HeightField::id, never reused, unlike an
// address), of the same size and spacing, whose revision is exactly one past the
// resident copy's (one mark_dirty() since, terrain/height_field.h) with its last_dirty
// rectangle inside the grid. Then rows last_dirty.y0 … y1 − 1 of the heights and the
// valid-mask words holding them are uploaded; the same object at the same revision
// uploads nothing; anything else (another field, several edits since) is uploaded whole.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "gpu/buffers.h"
#include "terrain/height_field.h"

namespace skylit::gpu {

class ResidentField {
 public:
  // Brings the GPU copy up to `field`; returns the bytes uploaded. Needs a current
  // context. Throws std::runtime_error if the field exceeds the storage-buffer limit.
  std::size_t sync(const terrain::HeightField& field);

  const Buffer& heights() const { return mHeights; }  // float32, row-major
  const Buffer& valid() const { return mValid; }      // 1 B/texel, 4 per word, little end first
  const Buffer& row_dx() const { return mRowDx; }     // float32 per row

 private:
  std::size_t upload_whole(const terrain::HeightField& field);
  Buffer mHeights, mValid, mRowDx;
  std::uint64_t mSourceId = 0;  // HeightField::id of the resident copy (0: none)
  int mWidth = 0, mHeight = 0;
  double mDy = 0.0;
  std::vector<double> mDx;
  std::uint64_t mRevision = 0;
};

// A small table kept on the GPU, re-uploaded only when its contents change.
class ResidentTable {
 public:
  // Returns the bytes uploaded (0 when `values` equal the resident ones).
  std::size_t assign(std::span<const float> values);
  const Buffer& buffer() const { return mBuffer; }

 private:
  Buffer mBuffer;
  std::vector<float> mValues;
  bool mSet = false;
};

}  // namespace skylit::gpu
