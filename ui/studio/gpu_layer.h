// One drawable of a 3D view on the GPU: a vertex array with positions, colours and (for meshes)
// normals and indices, uploaded from a PointSet, LineSet or TriangleMesh and drawn as points,
// lines or triangles. Points are uploaded in a fixed shuffled order, so that drawing only the
// first n of them shows a uniform subset (a level of detail while the view moves). Created and
// drawn with the view's OpenGL context current.
#pragma once

#include <vector>

#include "ui/studio/scene_geometry.h"

namespace polarform::studio {

class GpuLayer {
 public:
  enum class Kind { points, lines, triangles };

  GpuLayer() = default;
  ~GpuLayer();
  GpuLayer(const GpuLayer&) = delete;
  GpuLayer& operator=(const GpuLayer&) = delete;

  void upload(const PointSet& points);
  void upload(const LineSet& lines);
  void upload(const TriangleMesh& mesh);
  void clear();
  bool empty() const { return count_ == 0; }
  int count() const { return count_; }
  Kind kind() const { return kind_; }
  // Draws the layer; of a point layer at most `point_budget` points.
  void draw(int point_budget) const;

 private:
  void prepare();
  unsigned buffer(int slot, const std::vector<float>& data);

  Kind kind_ = Kind::points;
  unsigned vao_ = 0, buffers_[3] = {0, 0, 0}, index_buffer_ = 0;
  int count_ = 0;  // vertices (points, lines) or indices (triangles)
};

}  // namespace polarform::studio
