// Binary PLY element data: fixed-size records are addressed directly, records with list
// properties are walked property by property; every step is bounds-checked against the file end.
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "src/io/binary_load.h"
#include "src/io/ply_data.h"

namespace polarform::io_detail {

namespace {

template <class T>
bool load_count_as(const char* p, ByteOrder order, std::uint64_t& count) {
  const T value = load<T>(p, order);
  if constexpr (std::is_signed_v<T>)
    if (value < 0) return false;
  count = static_cast<std::uint64_t>(value);
  return true;
}

// The list count of integer type `type` (the header guarantees an integer) at p; false if negative.
bool load_count(const char* p, PlyType type, ByteOrder order, std::uint64_t& count) {
  switch (type) {
    case PlyType::int8:
      return load_count_as<std::int8_t>(p, order, count);
    case PlyType::uint8:
      return load_count_as<std::uint8_t>(p, order, count);
    case PlyType::int16:
      return load_count_as<std::int16_t>(p, order, count);
    case PlyType::uint16:
      return load_count_as<std::uint16_t>(p, order, count);
    case PlyType::int32:
      return load_count_as<std::int32_t>(p, order, count);
    default:
      return load_count_as<std::uint32_t>(p, order, count);
  }
}

double load_real(const char* p, PlyType type, ByteOrder order) {
  return type == PlyType::float32 ? load<float>(p, order) : load<double>(p, order);
}

// Bytes per record if the element has no list property.
std::optional<std::size_t> fixed_record_size(const PlyElement& element) {
  std::size_t size = 0;
  for (const PlyProperty& property : element.properties) {
    if (property.is_list) return std::nullopt;
    size += ply_type_size(property.type);
  }
  return size;
}

// The end of the record starting at p, or nullptr if it runs past `end` or a list count is
// negative. If `starts` is given, it receives the address of each property.
const char* walk_record(const PlyElement& element, const char* p, const char* end, ByteOrder order,
                        const char** starts) {
  for (std::size_t k = 0; k < element.properties.size(); ++k) {
    const PlyProperty& property = element.properties[k];
    if (starts) starts[k] = p;
    const auto left = static_cast<std::size_t>(end - p);
    if (!property.is_list) {
      if (ply_type_size(property.type) > left) return nullptr;
      p += ply_type_size(property.type);
      continue;
    }
    const std::size_t count_size = ply_type_size(property.count_type);
    std::uint64_t count;
    if (count_size > left || !load_count(p, property.count_type, order, count)) return nullptr;
    if (count > (left - count_size) / ply_type_size(property.type)) return nullptr;
    p += count_size + count * ply_type_size(property.type);
  }
  return p;
}

class BinaryReader {
 public:
  BinaryReader(std::string_view bytes, const PlyHeader& header, CloudBuilder& builder)
      : begin_(bytes.data()),
        end_(bytes.data() + bytes.size()),
        order_(header.storage == PlyStorage::binary_big_endian ? ByteOrder::big
                                                               : ByteOrder::little),
        builder_(builder) {}

  // "what index (byte offset n)", locating an error.
  std::string at(std::string_view what, std::uint64_t index, const char* p) const {
    return std::string(what) + " " + std::to_string(index) + " (byte offset " +
           std::to_string(p - begin_) + ")";
  }

  // Skips every record of `element` starting at p; returns the end of the element's data.
  const char* skip(const PlyElement& element, const char* p) const {
    if (const auto size = fixed_record_size(element)) {
      if (*size == 0) return p;
      if (element.count > static_cast<std::size_t>(end_ - p) / *size)
        builder_.fail("element '" + element.name + "'",
                      "binary data ends before its " + std::to_string(element.count) +
                          " records: the file is truncated or the count is wrong");
      return p + element.count * *size;
    }
    for (std::uint64_t r = 0; r < element.count; ++r) {
      const char* next = walk_record(element, p, end_, order_, nullptr);
      if (!next)
        builder_.fail(
            at("element '" + element.name + "' record", r, p),
            "binary data ends inside this record: the file is truncated or a count is wrong");
      p = next;
      builder_.progress(p - begin_);
    }
    return p;
  }

  // Reads the vertex element starting at p; returns the end of its data.
  const char* read_vertices(const PlyElement& vertex, const PlyVertexLayout& layout,
                            const char* p) {
    PlyType type[3];
    for (int k = 0; k < 3; ++k) type[k] = vertex.properties[layout.xyz[k]].type;
    if (const auto stride = fixed_record_size(vertex)) {
      std::size_t offset[3] = {0, 0, 0};
      for (int k = 0; k < 3; ++k)
        for (std::size_t j = 0; j < layout.xyz[k]; ++j)
          offset[k] += ply_type_size(vertex.properties[j].type);
      check_fits(vertex, *stride, p);
      for (std::uint64_t i = 0; i < vertex.count; ++i) {
        const char* record = p;
        p += *stride;
        builder_.add(load_real(record + offset[0], type[0], order_),
                     load_real(record + offset[1], type[1], order_),
                     load_real(record + offset[2], type[2], order_),
                     [&] { return at("vertex", i, record); });
        builder_.progress(p - begin_);
      }
      return p;
    }
    std::vector<const char*> starts(vertex.properties.size());
    for (std::uint64_t i = 0; i < vertex.count; ++i) {
      const char* next = walk_record(vertex, p, end_, order_, starts.data());
      if (!next)
        builder_.fail(at("vertex", i, p),
                      "binary data ends inside this vertex: the file is truncated, or the vertex "
                      "count or a list count is wrong");
      builder_.add(load_real(starts[layout.xyz[0]], type[0], order_),
                   load_real(starts[layout.xyz[1]], type[1], order_),
                   load_real(starts[layout.xyz[2]], type[2], order_),
                   [&] { return at("vertex", i, p); });
      p = next;
      builder_.progress(p - begin_);
    }
    return p;
  }

 private:
  // Fails unless vertex.count records of `stride` bytes fit between p and the end.
  void check_fits(const PlyElement& vertex, std::size_t stride, const char* p) const {
    const auto left = static_cast<std::size_t>(end_ - p);
    if (vertex.count <= left / stride) return;
    const std::uint64_t complete = left / stride;
    if (left % stride == 0)
      builder_.fail("element 'vertex'", "header declares " + std::to_string(vertex.count) +
                                            " vertices but the file holds only " +
                                            std::to_string(complete));
    builder_.fail(at("vertex", complete, p + complete * stride),
                  "the file is truncated inside this vertex (header declares " +
                      std::to_string(vertex.count) + " vertices of " + std::to_string(stride) +
                      " bytes)");
  }

  const char* begin_;
  const char* end_;
  ByteOrder order_;
  CloudBuilder& builder_;
};

}  // namespace

void read_ply_binary(std::string_view bytes, const PlyHeader& header, const PlyVertexLayout& layout,
                     CloudBuilder& builder) {
  BinaryReader reader(bytes, header, builder);
  const char* p = bytes.data() + header.data_offset;
  for (std::size_t e = 0; e < header.elements.size(); ++e)
    p = e == layout.element ? reader.read_vertices(header.elements[e], layout, p)
                            : reader.skip(header.elements[e], p);
}

}  // namespace polarform::io_detail
