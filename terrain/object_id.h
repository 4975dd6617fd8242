// A process-unique identity for a data object whose derived GPU copies must know
// whether they still belong to it (gpu/resident_field.h). Unlike an address it is never
// reused: a copy is another object (it may diverge) and gets a new id; a move hands the
// id over and leaves the source a new one; assigning makes the target another object.
#pragma once

#include <cstdint>

namespace skylit::terrain {

class ObjectId {
 public:
  ObjectId() : mValue(next()) {}
  ObjectId(const ObjectId&) : mValue(next()) {}
  ObjectId(ObjectId&& other) noexcept : mValue(other.mValue) { other.mValue = next(); }
  ObjectId& operator=(const ObjectId&) {
    mValue = next();
    return *this;
  }
  ObjectId& operator=(ObjectId&& other) noexcept {
    if (this != &other) {
      mValue = other.mValue;
      other.mValue = next();
    }
    return *this;
  }
  std::uint64_t value() const { return mValue; }

 private:
  static std::uint64_t next();  // thread-safe counter, starts at 1
  std::uint64_t mValue;
};

}  // namespace skylit::terrain
