// Extrusion recovery (Kantz 2003, §5.2.1; spec K10): direction, projection, section, extent,
// surface, errors.
#include "designers/sweep/extrusion_recovery.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <tuple>

#include "designers/sweep/recovery_steps.h"
#include "src/error.h"
#include "src/fit/local_normals.h"
#include "src/fit/polar_curve_fit.h"
#include "src/fit/rotation_axis.h"
#include "src/nurbs/extrusion.h"

namespace polarform {

namespace {

// The section: one closed loop by the polar fit about the origin when rays from it cross the band
// once (Bae 2002, ch. 2; spec K10 step 3), else the loops of the MLS-thinned band (spec K7). A band
// the polar fit cannot bring within the tolerance (noise, or a direction still off while it is
// refined) gets the largest net the fit allows, its tolerance marked as not met.
MeridianProfile section_loops(const Eigen::Matrix2Xd& q, const MeridianOptions& mo) {
  PolarFitOptions po;
  po.centre = Eigen::Vector2d::Zero();
  po.function.degree_v = mo.degree;
  // Below 1e-7 of the band's size a tolerance only chases rounding (the refinement to it is
  // capped there; the measured distances still face the tolerance asked for).
  po.function.tolerance =
      std::max(mo.tolerance, 1e-7 * (q.rowwise().maxCoeff() - q.rowwise().minCoeff()).norm());
  po.function.threads = mo.threads;
  po.closure = Closure::closed;
  po.outliers = OutlierPolicy::keep;
  auto polar = [&](const PolarFitOptions& options) {
    const PolarCurveFit f = fit_polar_curve(q, options);
    MeridianProfile p;
    p.size = (q.rowwise().maxCoeff() - q.rowwise().minCoeff()).norm();
    p.tolerance = mo.tolerance;
    p.clusters = static_cast<int>(q.cols());
    MeridianLoop l;
    l.curve = f.curve;
    l.closed = true;
    l.points = q;
    l.fit_max = f.report.error.max;
    l.tolerance_met = l.fit_max <= mo.tolerance;
    p.loops.push_back(std::move(l));
    return p;
  };
  try {
    return polar(po);
  } catch (const NumericalError&) {
    po.function.size_v = po.function.max_size_v;
    po.function.tolerance = 0.0;
    return polar(po);
  } catch (const InputError&) {
    return recover_meridian_profile(q, mo);
  }
}

}  // namespace

// The extrusion direction minimises Σ ⟨n, d⟩² over the local normals (an eigenproblem).
NormalsDirection normals_direction(const Eigen::Matrix3Xd& normals, const Eigen::Vector3d& hint) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(normals * normals.transpose());
  const Eigen::Vector3d d = eig.eigenvectors().col(0);
  const double sum = eig.eigenvalues().sum();
  return {d.dot(hint) < 0 ? Eigen::Vector3d(-d) : d,
          sum > 0 ? std::max(eig.eigenvalues()[0], 0.0) / sum : 0.0};
}

ExtrusionRecovery recover_extrusion(const Eigen::Matrix3Xd& points, const ExtrusionOptions& o) {
  check_sweep_input(points, o.direction, "extrusion recovery");
  ExtrusionRecovery out;
  auto t0 = std::chrono::steady_clock::now();
  out.size = (points.rowwise().maxCoeff() - points.rowwise().minCoeff()).norm();
  out.tolerance = o.tolerance > 0 ? o.tolerance : 1e-4 * out.size;
  out.pca = principal_frame(points);
  out.origin = out.pca.centroid;
  out.timings_s.frame = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  MeridianOptions mo;
  mo.tolerance = out.tolerance;
  mo.degree = o.degree;
  mo.corner_angle = o.corner_angle;
  mo.axis_ends = false;
  mo.threads = o.threads;
  const Eigen::Matrix3Xd sub = strided(points, o.max_direction_points);
  const Eigen::Vector3d hint = out.pca.axis(FrameAxis::principal);
  const NormalsDirection normals =
      normals_direction(local_normals(sub, o.normal_neighbours, o.threads), hint);
  out.normals_flatness = normals.flatness;
  out.start_direction =
      o.direction ? Eigen::Vector3d(o.direction->normalized()) : normals.direction;
  out.direction = out.refinement.direction = out.start_direction;
  if (o.refine_direction) {
    AxisRefinementOptions ro;
    ro.size = out.size;
    ro.threads = o.threads;
    ro.scale_floor = out.tolerance / 3;
    ro.max_iterations = 12;
    ro.step_tolerance = 1e-10;
    const MeridianModel model = [&](const Eigen::Matrix2Xd& q) {
      const MeridianProfile p = section_loops(q, mo);
      const MeridianDistances d = meridian_distances(p, q, o.threads);
      return MeridianResiduals{d.distance, d.normal,
                               std::vector<char>(static_cast<std::size_t>(q.cols()), 1)};
    };
    out.refinement = refine_extrusion_direction(strided(points, o.max_refine_points), out.origin,
                                                out.start_direction, model, ro);
    out.direction = out.refinement.direction;
  }
  std::tie(out.e1, out.e2) = normal_pair(out.direction);
  out.timings_s.direction = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  out.plane = project_onto_plane(points, out.origin, out.e1, out.e2);
  out.profile = section_loops(out.plane, mo);
  const Eigen::VectorXd h = (points.colwise() - out.origin).transpose() * out.direction;
  out.v_low = h.minCoeff();
  out.v_high = h.maxCoeff();
  out.timings_s.profile = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  for (const MeridianLoop& l : out.profile.loops) {
    NurbsCurve3d::Points pts;
    for (const Eigen::Vector2d& p : l.curve.control_points())
      pts.push_back(out.origin + p.x() * out.e1 + p.y() * out.e2);
    const NurbsCurve3d c(l.curve.degree(), l.curve.knots(), pts, l.curve.weights());
    out.surfaces.push_back(extrude(c, out.direction, out.v_low, out.v_high));
  }
  out.timings_s.surface = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  measure_point_errors(out, o.threads);
  out.timings_s.error = seconds_since(t0);
  return out;
}

}  // namespace polarform
