// Which sweep explains a cloud (Kantz 2003, §5.1: the object frame and the normals decide between
// a surface of revolution and an extrusion). The evidence, on the local normals n of an evenly
// strided subset (src/fit/local_normals.h):
// - extrusion: every normal ⟂ one direction d, measured by λ_min / Σλ of Σ n nᵀ (0 for an
//   extrusion, 1/3 for a sphere);
// - revolution: every normal in a plane through the axis (PCA's most distinct eigenvector through
//   the centroid), measured by the median |n · t|, t the azimuthal direction about that axis
//   (0 for a surface of revolution; a cylinder is both).
#pragma once

#include <Eigen/Core>
#include <string>

namespace polarform {

struct SweepKindEvidence {
  double tie_ratio = 0.0;         // PCA: of the two eigenvalues other than the axis's
  double normals_flatness = 0.0;  // λ_min / Σλ of Σ n nᵀ
  double azimuthal_normal = 0.0;  // median |n · t| about the PCA axis
  static constexpr double kFlat = 0.01, kMeridional = 0.05;  // the thresholds below
  bool extrusion_like() const { return normals_flatness <= kFlat; }
  bool revolution_like() const { return azimuthal_normal <= kMeridional; }
  std::string text() const;  // the three figures against their thresholds
};

// At most max_points evenly strided points are used; needs at least 8 finite points.
SweepKindEvidence sweep_kind_evidence(const Eigen::Matrix3Xd& points, int neighbours = 16,
                                      int max_points = 20000, int threads = 2);

}  // namespace polarform
