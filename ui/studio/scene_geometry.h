// What the 3D views draw, on the CPU side: point sets, line sets and shaded triangle meshes in
// float coordinates relative to a scene origin (so scans far from the world origin keep their
// precision), and the builders from kernel types — a NURBS surface sampled into a mesh with
// normals, its control net as lines, a point cloud coloured by a per-point scalar.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "src/nurbs/nurbs_surface.h"

namespace polarform::studio {

struct PointSet {
  std::vector<float> positions;  // x, y, z per point
  std::vector<float> colors;     // r, g, b per point
};

struct LineSet {
  std::vector<float> positions;  // two points per segment
  std::vector<float> colors;
};

struct TriangleMesh {
  std::vector<float> positions, normals, colors;  // per vertex
  std::vector<unsigned> indices;                  // three per triangle
};

struct SceneBounds {
  Eigen::Vector3d min = Eigen::Vector3d::Constant(1e300), max = Eigen::Vector3d::Constant(-1e300);
  void add(const Eigen::Vector3d& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  bool empty() const { return !(max.x() >= min.x()); }
  Eigen::Vector3d center() const { return 0.5 * (min + max); }
  double radius() const { return empty() ? 1.0 : std::max(0.5 * (max - min).norm(), 1e-9); }
};

// Points relative to `origin`, all in one colour; with `values` (one per point) coloured by the
// diverging map of value / scale.
PointSet make_point_set(const Eigen::Matrix3Xd& points, const Eigen::Vector3d& origin,
                        const float* rgb);
PointSet make_point_set(const Eigen::Matrix3Xd& points, const Eigen::Vector3d& origin,
                        const Eigen::VectorXd& values, double scale);

// The surface tessellated (src/nurbs/tessellation.h): samples_u and samples_v equal steps plus
// every distinct interior knot, with unit normals (degenerate ones from the neighbour along u).
TriangleMesh make_surface_mesh(const NurbsSurface& surface, const Eigen::Vector3d& origin,
                               const float* rgb, int samples_u = 64, int samples_v = 64);
// Appends a mesh (indices shifted).
void append_mesh(TriangleMesh& to, const TriangleMesh& from);
// The control net's rows and columns as segments.
void add_control_net(LineSet& lines, const NurbsSurface& surface, const Eigen::Vector3d& origin,
                     const float* rgb);
void add_segment(LineSet& lines, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                 const Eigen::Vector3d& origin, const float* rgb);
// Consecutive points joined by segments.
void add_polyline(LineSet& lines, const std::vector<Eigen::Vector3d>& points,
                  const Eigen::Vector3d& origin, const float* rgb);

SceneBounds bounds_of(const Eigen::Matrix3Xd& points);
SceneBounds bounds_of(const NurbsSurface& surface);

}  // namespace polarform::studio
