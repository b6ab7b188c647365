// The local coordinate system ω = {o, i, j, k} of a fit (Bae 2002, §4.3): estimated from the
// best-fit general quadric (origin by eq. (4.3) or Appendix E, axes by the three eigenvector rules),
// or given by the user in part or whole; and the transforms (4.5) into it and (4.6) back.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "src/fit/quadric_fit.h"
#include "src/nurbs/nurbs_curve.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform {

struct LocalFrame {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  // columns i, j, k (right-handed, orthonormal)

  // ^ωΨ = R(^ΩΨ − T), R with rows i, j, k; Bae 2002, eq. (4.5).
  Eigen::Vector3d to_local(const Eigen::Vector3d& global) const;
  Eigen::Matrix3Xd to_local(const Eigen::Matrix3Xd& global) const;
  // ^Ωs = R^{-1} ^ωs + T; Bae 2002, eq. (4.6), applied to homogeneous control points.
  Eigen::Vector3d to_global(const Eigen::Vector3d& local) const;
  // Every column; without it a 3×N matrix would silently bind to the Vector3d overload.
  Eigen::Matrix3Xd to_global(const Eigen::Matrix3Xd& local) const;
  NurbsSurface to_global(const NurbsSurface& local) const;
  NurbsCurve3d to_global(const NurbsCurve3d& local) const;
};

// Which eigenvector of a real ellipsoid becomes k.
enum class EllipsoidAxis {
  largest_eigenvalue,  // Bae 2002, §4.3 (the shortest semi-axis): natural poles for spherical fits
  most_distinct,       // the eigenvalue farthest from the other two: the symmetry axis of a
                       // spheroid, elongated or flat (used by cylindrical fits)
};

struct FrameOptions {
  // User overrides; any of them may be given. axis is k, reference a direction in the ij plane
  // (made orthogonal to k) that becomes i, i.e. θ = 0.
  std::optional<Eigen::Vector3d> origin, axis, reference;
  EllipsoidAxis ellipsoid_axis = EllipsoidAxis::largest_eigenvalue;
  QuadricFitOptions quadric;
};

struct FrameEstimate {
  LocalFrame frame;
  std::optional<QuadricFit> quadric;  // absent when the user gave origin and axis
  std::string reason;                 // how origin and axes were found
};

// Fits and classifies a quadric unless origin and axis are both given. Axis rules (Bae 2002,
// §4.3): rank Q_u = 2 → k is the zero-eigenvalue eigenvector; mixed signs → the lone-sign one; a
// real ellipsoid → by options.ellipsoid_axis. i is the remaining eigenvector of larger |λ| (or the
// data's principal direction across k when k is given). Signs are fixed by the data (third
// moments along k and i positive), so the frame moves with the data under rigid motions.
// Throws InputError when the quadric type defines no frame (Table 4.1 types outside Fig. 4.2) and
// the user did not give origin and axis.
FrameEstimate estimate_frame(const Eigen::Matrix3Xd& points, const FrameOptions& options = {});

// The start of the surface fits (Bae 2002, §4.3): at least 16 finite points, their frame
// estimated with `threads` quadric threads, and the points in that frame. InputError messages
// begin with `fit_name` ("spherical fit: 9 points, expected at least 16").
struct LocalCloud {
  FrameEstimate frame;
  Eigen::Matrix3Xd points;  // frame.frame.to_local of the input
};
LocalCloud local_cloud(const Eigen::Matrix3Xd& points, FrameOptions options, int threads,
                       const std::string& fit_name);

}  // namespace polarform
