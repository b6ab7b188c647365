// Surface-of-revolution recovery (Kantz 2003, §5.3; spec K11): frame, axis, profile, surface,
// errors.
#include "designers/sweep/revolution_recovery.h"

#include <algorithm>
#include <chrono>
#include <string>

#include "designers/sweep/azimuthal_coverage.h"
#include "designers/sweep/recovery_steps.h"
#include "src/error.h"
#include "src/fit/coordinate_rounding.h"
#include "src/nurbs/surface_of_revolution.h"

namespace polarform {

// NURBS Book A8.1 on the profile placed in a meridian plane: (z, r) ↦ c + z a + r e.
NurbsSurface revolve_meridian(const NurbsCurve2d& profile, const AxisLine& axis) {
  const Eigen::Vector3d a = axis.direction.normalized();
  const Eigen::Vector3d t =
      std::abs(a.x()) < 0.6 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d e = (t - t.dot(a) * a).normalized();
  NurbsCurve3d::Points pts;
  for (const Eigen::Vector2d& q : profile.control_points())
    pts.push_back(axis.point + q.x() * a + q.y() * e);
  return revolve(NurbsCurve3d(profile.degree(), profile.knots(), pts, profile.weights()),
                 axis.point, a);
}

RevolutionRecovery recover_revolution(const Eigen::Matrix3Xd& points, const RevolutionOptions& o) {
  check_sweep_input(points, o.axis_direction, "revolution recovery");
  RevolutionRecovery out;
  auto t0 = std::chrono::steady_clock::now();
  out.size = (points.rowwise().maxCoeff() - points.rowwise().minCoeff()).norm();
  out.tolerance = o.tolerance > 0 ? o.tolerance : 1e-4 * out.size;
  out.pca = principal_frame(points);
  out.tie_ratio = out.pca.tie_ratio(FrameAxis::most_distinct);
  out.start_axis.direction = o.axis_direction ? Eigen::Vector3d(o.axis_direction->normalized())
                                              : out.pca.axis(FrameAxis::most_distinct);
  out.start_axis.point = o.axis_point ? *o.axis_point : out.pca.centroid;
  out.axis = out.start_axis;
  out.timings_s.frame = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  MeridianOptions mo;
  mo.tolerance = out.tolerance;
  mo.degree = o.degree;
  mo.corner_angle = o.corner_angle;
  mo.threads = o.threads;
  mo.rounding = coordinate_rounding(points);
  if (o.refine_axis) {
    const Eigen::Matrix3Xd sub = strided(points, o.max_axis_points);
    AxisRefinementOptions ro;
    ro.size = out.size;
    ro.threads = o.threads;
    // Ring-structured meshes: exact clusters decide (accepted when they collapse to the
    // coordinates' rounding, at most 1 % of the tolerance), from a merge radius below the spacing
    // of dense rings (1e-4 of the size: 1000 rings along a profile are ~1e-3 apart) that grows
    // until the rings of a start axis that is off collapse into clusters.
    const double collapsed = std::max(
        {1e-9 * out.size, 4 * mo.rounding, std::min(1e-2 * out.tolerance, 1e-6 * out.size)});
    auto rings = [&](const AxisLine& from) {
      AxisRefinement r;
      for (double merge : {1e-4, 1e-3, 4e-3, 1.6e-2}) {
        r = refine_axis_by_rings(sub, from, merge * out.size, ro);
        if (r.converged && r.clustered >= 0.8 && r.rms_after <= collapsed)
          return std::pair<AxisRefinement, bool>{r, true};
      }
      return std::pair<AxisRefinement, bool>{r, false};
    };
    auto [ring, ok] = rings(out.start_axis);
    if (!ok) {
      ro.scale_floor = out.tolerance / 3;
      ro.max_iterations = 10;
      ro.step_tolerance = 1e-9;
      // The profile is fitted to the points a surface of revolution can explain (a feature on
      // one side is set aside by its azimuths), the axis refined against it; twice, the points
      // set aside again about the refined axis.
      const Eigen::Matrix3Xd fit_sub = strided(sub, o.max_profile_axis_points);
      std::vector<char> keep;
      const MeridianModel model = [&](const Eigen::Matrix2Xd& zr) {
        const MeridianProfile p = recover_meridian_profile(kept_columns(zr, keep), mo);
        const MeridianDistances d = meridian_distances(p, zr, o.threads);
        return MeridianResiduals{d.distance, d.normal, keep};
      };
      AzimuthalCoverage c = azimuthal_coverage(fit_sub, out.start_axis, o.coverage_cell * out.size);
      keep = c.rotational;
      out.refinement = refine_axis_by_profile(fit_sub, out.start_axis, model, ro);
      if (c.set_aside > 0) {
        c = azimuthal_coverage(fit_sub, out.refinement.axis, o.coverage_cell * out.size);
        if (c.rotational != keep) {
          keep = c.rotational;
          const double before = out.refinement.rms_before;
          out.refinement = refine_axis_by_profile(fit_sub, out.refinement.axis, model, ro);
          out.refinement.rms_before = before;
        }
      }
      ro.scale_floor = 0.0;
      ro.max_iterations = 30;
      ro.step_tolerance = 1e-10;
      std::tie(ring, ok) = rings(out.refinement.axis);
      if (ok) {
        ring.rms_before = out.refinement.rms_before;
        out.refinement = ring;
      }
    } else {
      out.refinement = ring;
    }
    out.ring_axis = ok;
    out.axis = out.refinement.axis;
  }
  out.timings_s.axis = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  out.plane = meridian_coordinates(points, out.axis, o.threads);
  if (out.ring_axis || !o.refine_axis) {
    out.profile = recover_meridian_profile(out.plane, mo);
  } else {
    const AzimuthalCoverage c = azimuthal_coverage(points, out.axis, o.coverage_cell * out.size);
    out.set_aside = c.set_aside;
    out.profile = recover_meridian_profile(kept_columns(out.plane, c.rotational), mo);
  }
  out.timings_s.profile = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  for (const MeridianLoop& l : out.profile.loops)
    out.surfaces.push_back(revolve_meridian(l.curve, out.axis));
  out.timings_s.surface = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  measure_point_errors(out, o.threads);
  out.timings_s.error = seconds_since(t0);
  return out;
}

}  // namespace polarform
