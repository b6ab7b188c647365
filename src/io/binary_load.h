// Loads fixed-size little- or big-endian scalars from an unaligned byte buffer (binary PLY, STL).
// Callers check bounds first; these only convert bytes.
#pragma once

#include <bit>
#include <cstddef>
#include <cstring>
#include <utility>

namespace polarform::io_detail {

enum class ByteOrder { little, big };

// The scalar of type T stored at p in the given byte order.
template <class T>
T load(const char* p, ByteOrder order) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, p, sizeof(T));
  const bool native = (order == ByteOrder::little) == (std::endian::native == std::endian::little);
  if (!native)
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
  T value;
  std::memcpy(&value, bytes, sizeof(T));
  return value;
}

}  // namespace polarform::io_detail
