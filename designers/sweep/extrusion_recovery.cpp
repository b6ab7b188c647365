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
#include "src/fit/grid_index.h"
#include "src/fit/parallel.h"
#include "src/fit/polar_curve_fit.h"
#include "src/fit/rotation_axis.h"
#include "src/nurbs/extrusion.h"

namespace polarform {

namespace {

// Kantz §5.2.1 step 2: every point projected along d onto the plane through c.
Eigen::Matrix2Xd project(const Eigen::Matrix3Xd& P, const Eigen::Vector3d& c,
                         const Eigen::Vector3d& e1, const Eigen::Vector3d& e2) {
  Eigen::Matrix<double, 2, 3> B;
  B.row(0) = e1.transpose();
  B.row(1) = e2.transpose();
  return B * (P.colwise() - c);
}

// The section: one closed loop by the polar fit about the origin when rays from it cross the band
// once (Bae 2002, ch. 2; spec K10 step 3), else the loops of the MLS-thinned band (spec K7).
MeridianProfile section_loops(const Eigen::Matrix2Xd& q, const MeridianOptions& mo) {
  PolarFitOptions po;
  po.centre = Eigen::Vector2d::Zero();
  po.function.degree_v = mo.degree;
  po.function.tolerance = mo.tolerance;
  po.function.threads = mo.threads;
  po.closure = Closure::closed;
  po.outliers = OutlierPolicy::keep;
  try {
    const PolarCurveFit f = fit_polar_curve(q, po);
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
  } catch (const InputError&) {
    return recover_meridian_profile(q, mo);
  }
}

}  // namespace

// Hoppe et al. 1992 normals; the extrusion direction minimises Σ ⟨n, d⟩² (an eigenproblem).
Eigen::Vector3d normals_direction(const Eigen::Matrix3Xd& P, int k, const Eigen::Vector3d& hint,
                                  int threads) {
  const GridIndex3d grid(P);
  const int chunks = worker_count(threads, static_cast<std::size_t>(P.cols()));
  std::vector<Eigen::Matrix3d> sums(static_cast<std::size_t>(chunks), Eigen::Matrix3d::Zero());
  parallel_chunks(static_cast<std::size_t>(P.cols()), chunks,
                  [&](std::size_t b, std::size_t e, int w) {
                    std::vector<int> near;
                    for (std::size_t i = b; i < e; ++i) {
                      grid.nearest(P.col(static_cast<Eigen::Index>(i)), k, near);
                      if (near.size() < 3) continue;
                      Eigen::Vector3d m = Eigen::Vector3d::Zero();
                      for (int j : near) m += P.col(j);
                      m /= static_cast<double>(near.size());
                      Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
                      for (int j : near) C += (P.col(j) - m) * (P.col(j) - m).transpose();
                      const Eigen::Vector3d n =
                          Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(C).eigenvectors().col(0);
                      sums[static_cast<std::size_t>(w)] += n * n.transpose();
                    }
                  });
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  for (const Eigen::Matrix3d& s : sums) M += s;
  Eigen::Vector3d d = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(M).eigenvectors().col(0);
  return d.dot(hint) < 0 ? Eigen::Vector3d(-d) : d;
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
  out.direction = o.direction ? Eigen::Vector3d(o.direction->normalized())
                              : normals_direction(sub, o.normal_neighbours, hint, o.threads);
  std::tie(out.e1, out.e2) = normal_pair(out.direction);
  out.timings_s.direction = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  out.projected = project(points, out.origin, out.e1, out.e2);
  out.section = section_loops(out.projected, mo);
  const Eigen::VectorXd h = (points.colwise() - out.origin).transpose() * out.direction;
  out.v_low = h.minCoeff();
  out.v_high = h.maxCoeff();
  out.timings_s.profile = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  for (const MeridianLoop& l : out.section.loops) {
    NurbsCurve3d::Points pts;
    for (const Eigen::Vector2d& p : l.curve.control_points())
      pts.push_back(out.origin + p.x() * out.e1 + p.y() * out.e2);
    const NurbsCurve3d c(l.curve.degree(), l.curve.knots(), pts, l.curve.weights());
    out.surfaces.push_back(extrude(c, out.direction, out.v_low, out.v_high));
  }
  out.timings_s.surface = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  // Every point lies within the extent, so its 3D distance is its section-plane distance.
  PointErrors e = point_errors(out.section, out.projected, out.tolerance, o.threads);
  out.distances = std::move(e.distances);
  out.error = e.error;
  out.unexplained = e.unexplained;
  out.timings_s.error = seconds_since(t0);
  return out;
}

}  // namespace polarform
