// Evidence for the kind of a sweep: flat normals (extrusion) or meridional normals (revolution).
#include "designers/sweep/sweep_kind.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "designers/sweep/extrusion_recovery.h"
#include "designers/sweep/recovery_steps.h"
#include "src/fit/local_normals.h"
#include "src/fit/principal_frame.h"
#include "src/number_text.h"

namespace polarform {

std::string SweepKindEvidence::text() const {
  return "normals flatness " + number_text(normals_flatness) +
         (extrusion_like() ? " (<= 0.01: extrusion-like)" : " (> 0.01: not an extrusion)") +
         ", median azimuthal normal " + number_text(azimuthal_normal) +
         (revolution_like() ? " (<= 0.05: rotational)" : " (> 0.05: not rotational)") +
         ", PCA tie ratio " + number_text(tie_ratio);
}

SweepKindEvidence sweep_kind_evidence(const Eigen::Matrix3Xd& points, int neighbours,
                                      int max_points, int threads) {
  const Eigen::Matrix3Xd P = strided(points, max_points);
  const Eigen::Matrix3Xd n = local_normals(P, neighbours, threads);
  const PrincipalFrame pca = principal_frame(points);
  const Eigen::Vector3d a = pca.axis(FrameAxis::most_distinct), c = pca.centroid;
  SweepKindEvidence e;
  e.tie_ratio = pca.tie_ratio(FrameAxis::most_distinct);
  e.normals_flatness = normals_direction(n, a).flatness;
  std::vector<double> azimuthal;
  for (Eigen::Index k = 0; k < P.cols(); ++k) {
    const Eigen::Vector3d t = a.cross(Eigen::Vector3d(P.col(k) - c));
    if (t.norm() > 0 && n.col(k).norm() > 0)
      azimuthal.push_back(std::abs(n.col(k).dot(t.normalized())));
  }
  if (!azimuthal.empty()) {
    std::nth_element(azimuthal.begin(), azimuthal.begin() + azimuthal.size() / 2, azimuthal.end());
    e.azimuthal_normal = azimuthal[azimuthal.size() / 2];
  } else {
    e.azimuthal_normal = 1.0;
  }
  return e;
}

}  // namespace polarform
