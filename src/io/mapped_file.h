// A whole file mapped read-only into memory, so readers parse it in place without copying it.
// The bytes stay valid while the MappedFile lives; an empty file maps to an empty view.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string_view>

namespace polarform::io_detail {

class MappedFile {
 public:
  // Throws InputError naming the path if it cannot be opened or mapped.
  explicit MappedFile(const std::filesystem::path& path);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  std::string_view bytes() const { return {data_, size_}; }

 private:
  const char* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace polarform::io_detail
