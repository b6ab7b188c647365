#include "ui/studio/gpu_layer.h"

#include <algorithm>
#include <numeric>
#include <random>

#include "ui/studio/gl_api.h"

namespace polarform::studio {

GpuLayer::~GpuLayer() { clear(); }

void GpuLayer::clear() {
  if (vao_) glDeleteVertexArrays(1, &vao_);
  glDeleteBuffers(3, buffers_);
  if (index_buffer_) glDeleteBuffers(1, &index_buffer_);
  vao_ = index_buffer_ = 0;
  buffers_[0] = buffers_[1] = buffers_[2] = 0;
  count_ = 0;
}

void GpuLayer::prepare() {
  clear();
  glGenVertexArrays(1, &vao_);
  glBindVertexArray(vao_);
}

// Attribute `slot` (0 position, 1 colour, 2 normal) from three floats per vertex.
unsigned GpuLayer::buffer(int slot, const std::vector<float>& data) {
  glGenBuffers(1, &buffers_[slot]);
  glBindBuffer(GL_ARRAY_BUFFER, buffers_[slot]);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(),
               GL_STATIC_DRAW);
  glEnableVertexAttribArray(slot);
  glVertexAttribPointer(slot, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
  return buffers_[slot];
}

void GpuLayer::upload(const PointSet& points) {
  prepare();
  kind_ = Kind::points;
  const std::size_t n = points.positions.size() / 3;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::shuffle(order.begin(), order.end(), std::mt19937(2002));
  PointSet shuffled;
  shuffled.positions.resize(3 * n);
  shuffled.colors.resize(3 * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k < 3; ++k) {
      shuffled.positions[3 * i + k] = points.positions[3 * order[i] + k];
      shuffled.colors[3 * i + k] = points.colors[3 * order[i] + k];
    }
  buffer(0, shuffled.positions);
  buffer(1, shuffled.colors);
  count_ = static_cast<int>(n);
  glBindVertexArray(0);
}

void GpuLayer::upload(const LineSet& lines) {
  prepare();
  kind_ = Kind::lines;
  buffer(0, lines.positions);
  buffer(1, lines.colors);
  count_ = static_cast<int>(lines.positions.size() / 3);
  glBindVertexArray(0);
}

void GpuLayer::upload(const TriangleMesh& mesh) {
  prepare();
  kind_ = Kind::triangles;
  buffer(0, mesh.positions);
  buffer(1, mesh.colors);
  buffer(2, mesh.normals);
  glGenBuffers(1, &index_buffer_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER,
               static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(unsigned)), mesh.indices.data(),
               GL_STATIC_DRAW);
  count_ = static_cast<int>(mesh.indices.size());
  glBindVertexArray(0);
}

void GpuLayer::draw(int point_budget) const {
  if (!count_) return;
  glBindVertexArray(vao_);
  switch (kind_) {
    case Kind::points:
      glDrawArrays(GL_POINTS, 0, std::min(count_, point_budget));
      break;
    case Kind::lines:
      glDrawArrays(GL_LINES, 0, count_);
      break;
    case Kind::triangles:
      glDrawElements(GL_TRIANGLES, count_, GL_UNSIGNED_INT, nullptr);
      break;
  }
  glBindVertexArray(0);
}

}  // namespace polarform::studio
