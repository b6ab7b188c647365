#include "src/fit/frame_candidates.h"

#include <Eigen/Dense>
#include <cmath>
#include <sstream>

#include "src/fit/meridian_function.h"
#include "src/fit/point_subset.h"
#include "src/fit/principal_frame.h"
#include "src/fit/rotation_axis.h"

namespace polarform {

namespace {

constexpr Eigen::Index kMaxPoints = 20000;
constexpr Eigen::Index kMaxProfilePoints = 50000;
constexpr double kExtraStartRatio = 2.0;

// Two unit vectors completing `a` to an orthonormal basis.
void basis(const Eigen::Vector3d& a, Eigen::Vector3d& e1, Eigen::Vector3d& e2) {
  e1 = (std::abs(a.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY())
           .cross(a)
           .normalized();
  e2 = a.cross(e1);
}

// Residuals of the line (o, a) with the profile r(t) fitted by linear least squares.
Eigen::VectorXd axis_residuals(const Eigen::Matrix3Xd& p, const Eigen::Vector3d& o,
                               const Eigen::Vector3d& a) {
  const Eigen::Index n = p.cols();
  Eigen::VectorXd t(n), d(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Vector3d q = p.col(k) - o;
    t[k] = q.dot(a);
    d[k] = (q - t[k] * a).norm();
  }
  const double scale = std::max(t.cwiseAbs().maxCoeff(), 1e-12);
  Eigen::MatrixXd V(n, 3);
  V.col(0).setOnes();
  V.col(1) = t / scale;
  V.col(2) = (t / scale).cwiseProduct(t / scale);
  const Eigen::Vector3d c = V.colPivHouseholderQr().solve(d);
  return d - V * c;
}

double rms(const Eigen::VectorXd& r) {
  return std::sqrt(r.squaredNorm() / double(std::max<Eigen::Index>(r.size(), 1)));
}

}  // namespace

// Gauss–Newton with a forward-difference Jacobian over (two axis rotations, two origin shifts
// across the axis), the profile eliminated by linear least squares (variable projection, Golub &
// Pereyra 1973).
FrameCandidate least_squares_axis(const Eigen::Matrix3Xd& points,
                                  const Eigen::Vector3d& start_origin,
                                  const Eigen::Vector3d& start_axis, bool fix_origin,
                                  bool fix_axis) {
  const Eigen::Matrix3Xd p = strided_columns(points, kMaxPoints);
  Eigen::Vector3d o = start_origin, a = start_axis.normalized();
  const double size = (p.colwise() - p.rowwise().mean()).rowwise().norm().maxCoeff() + 1e-12;
  Eigen::VectorXd r = axis_residuals(p, o, a);
  const double start_rms = rms(r);
  double lambda = 1e-3;
  int it = 0;
  for (; it < 50; ++it) {
    Eigen::Vector3d e1, e2;
    basis(a, e1, e2);
    // Parameters: rotations about e1, e2 (rad), shifts along e1, e2 (in units of size).
    auto line = [&](const Eigen::Vector4d& x, Eigen::Vector3d& o2, Eigen::Vector3d& a2) {
      a2 = (a + x[0] * e2 - x[1] * e1).normalized();
      o2 = o + size * (x[2] * e1 + x[3] * e2);
    };
    Eigen::MatrixXd J(r.size(), 4);
    J.setZero();
    const double h = 1e-7;
    for (int j = 0; j < 4; ++j) {
      if ((j < 2 && fix_axis) || (j >= 2 && fix_origin)) continue;
      Eigen::Vector4d x = Eigen::Vector4d::Zero();
      x[j] = h;
      Eigen::Vector3d o2, a2;
      line(x, o2, a2);
      J.col(j) = (axis_residuals(p, o2, a2) - r) / h;
    }
    const Eigen::Matrix4d A = J.transpose() * J;
    const Eigen::Vector4d g = J.transpose() * r;
    bool improved = false;
    for (int tries = 0; tries < 10 && !improved; ++tries) {
      Eigen::Matrix4d M = A;
      M.diagonal() +=
          lambda * A.diagonal() + Eigen::Vector4d::Constant(1e-12 * (A.trace() + 1e-300));
      const Eigen::Vector4d step = -M.ldlt().solve(g);
      Eigen::Vector3d o2, a2;
      line(step, o2, a2);
      const Eigen::VectorXd r2 = axis_residuals(p, o2, a2);
      if (r2.squaredNorm() < r.squaredNorm()) {
        improved = true;
        const double gain = r.squaredNorm() - r2.squaredNorm();
        o = o2, a = a2, r = r2;
        lambda = std::max(lambda / 10.0, 1e-9);
        if (gain <= 1e-12 * r.squaredNorm() + 1e-300) it = 50;
      } else {
        lambda *= 10.0;
      }
    }
    if (!improved) break;
  }
  // The origin moved to the foot of the data's centroid on the line.
  const Eigen::Vector3d centroid = p.rowwise().mean();
  if (!fix_origin) o += a * a.dot(centroid - o);
  FrameCandidate c;
  c.name = "least-squares axis";
  c.origin = o;
  c.axis = a;
  std::ostringstream how;
  how.precision(4);
  how << "Gauss–Newton on the distance to the axis of a surface of revolution r = c0 + c1 t + c2 "
         "t² ("
      << p.cols() << " points" << (fix_axis ? ", axis given" : "")
      << (fix_origin ? ", origin given" : "") << "): rms residual " << start_rms
      << " mm at the start, " << rms(r) << " mm";
  c.how = how.str();
  return c;
}

// Gauss–Newton on |p − c| − R (the geometric sphere fit, e.g. Ahn 2004, §3.2), R eliminated.
FrameCandidate least_squares_centre(const Eigen::Matrix3Xd& points,
                                    const Eigen::Vector3d& start_centre,
                                    const Eigen::Vector3d& axis) {
  const Eigen::Matrix3Xd p = strided_columns(points, kMaxPoints);
  Eigen::Vector3d c = start_centre;
  auto residuals = [&](const Eigen::Vector3d& x, Eigen::VectorXd& d) {
    d = (p.colwise() - x).colwise().norm().transpose();
    d.array() -= d.mean();
  };
  Eigen::VectorXd r;
  residuals(c, r);
  const double start_rms = rms(r);
  for (int it = 0; it < 50; ++it) {
    Eigen::MatrixXd J(p.cols(), 3);
    for (Eigen::Index k = 0; k < p.cols(); ++k) {
      const Eigen::Vector3d q = p.col(k) - c;
      J.row(k) = -(q / std::max(q.norm(), 1e-300)).transpose();
    }
    J.rowwise() -= J.colwise().mean();
    const Eigen::Vector3d step = -(J.transpose() * J).ldlt().solve(J.transpose() * r);
    Eigen::VectorXd r2;
    residuals(c + step, r2);
    if (!(r2.squaredNorm() < r.squaredNorm())) break;
    c += step, r = r2;
    if (step.norm() < 1e-12 * (c.norm() + 1.0)) break;
  }
  FrameCandidate f;
  f.name = "least-squares centre";
  f.origin = c;
  f.axis = axis.normalized();
  std::ostringstream how;
  how.precision(4);
  how << "Gauss–Newton on |p − c| − R (" << p.cols() << " points): rms residual " << start_rms
      << " mm at the start, " << rms(r) << " mm";
  f.how = how.str();
  return f;
}

// Kantz 2003, §5.1 (PCA) and §5.3 (refinement against the meridian profile).
FrameCandidate profile_refined_axis(const Eigen::Matrix3Xd& points,
                                    const std::vector<AxisStart>& starts,
                                    const AxisConstraint& given) {
  const Eigen::Matrix3Xd p = strided_columns(points, kMaxProfilePoints);
  const PrincipalFrame pca = principal_frame(p);
  std::vector<AxisStart> all{{"PCA", pca.centroid, pca.axis(FrameAxis::most_distinct)}};
  all.insert(all.end(), starts.begin(), starts.end());
  const auto constrained = [&](AxisStart s) {
    if (given.point) s.origin = *given.point;
    if (given.direction) s.axis = *given.direction;
    return s;
  };
  for (AxisStart& s : all) s = constrained(s);
  // The other two principal axes start too where a meridian profile about them is within
  // kExtraStartRatio of the best start's residual: on a partial scan the most distinct eigenvalue
  // can belong to a transverse axis (a prolate spheroid over 270° of azimuth: 1.3×), while about a
  // transverse axis of a cylinder the profile misses by the radius (100× the noise and more).
  if (!given.direction) {
    const auto profile_rms = [&](const AxisStart& s) {
      const Eigen::Matrix2Xd zr = meridian_coordinates(p, {s.origin, s.axis.normalized()});
      try {
        return fit_meridian_function(zr, choose_meridian_function_size(zr)).rms;
      } catch (const std::exception&) {
        return HUGE_VAL;
      }
    };
    double best_start = HUGE_VAL;
    for (const AxisStart& s : all) best_start = std::min(best_start, profile_rms(s));
    const int distinct = pca.axis_index(FrameAxis::most_distinct);
    for (int i = 0; i < 3; ++i) {
      const AxisStart s =
          constrained({"PCA axis " + std::to_string(i + 1), pca.centroid, pca.axes.col(i)});
      if (i != distinct && profile_rms(s) <= kExtraStartRatio * best_start) all.push_back(s);
    }
  }
  AxisRefinementOptions o;
  o.size = (pca.box_high - pca.box_low).norm();
  o.max_iterations = 40;
  o.step_tolerance = 1e-12;
  o.fix_point = given.point.has_value();
  o.fix_direction = given.direction.has_value();
  std::ostringstream how;
  how.precision(4);
  how << "robust Gauss–Newton of the axis against a least-squares meridian profile r(z) ("
      << p.cols() << " points), from";
  FrameCandidate best;
  best.name = given.point       ? "PCA + profile refinement through the given centre"
              : given.direction ? "PCA + profile refinement along the given axis"
                                : "PCA + profile refinement";
  double best_rms = HUGE_VAL;
  std::string best_start;
  for (const AxisStart& s : all) {
    AxisLine line{s.origin, s.axis.normalized()};
    double before = 0.0, after = HUGE_VAL;
    int iterations = 0, size = 0;
    try {
      for (int pass = 0; pass < 2; ++pass) {
        size = choose_meridian_function_size(meridian_coordinates(p, line, o.threads));
        const AxisRefinement r = refine_axis_by_profile(p, line, meridian_function_model(size), o);
        if (pass == 0) before = r.rms_before;
        after = r.rms_after, iterations += r.iterations, line = r.axis;
      }
    } catch (const std::exception&) {
      after = HUGE_VAL;
    }
    how << (&s == &all.front() ? " " : "; ") << s.name;
    if (!std::isfinite(after) || !line.direction.allFinite() || !line.point.allFinite()) {
      how << " (failed)";
      continue;
    }
    how << " (rms " << before << " → " << after << " mm, " << iterations
        << " iterations, profile of " << size << " coefficients)";
    if (after < best_rms) {
      best_rms = after, best_start = s.name;
      best.origin = line.point, best.axis = line.direction;
    }
  }
  if (!std::isfinite(best_rms)) {
    best.origin = all.front().origin, best.axis = all.front().axis;
    how << "; every refinement failed: the PCA axis";
  } else {
    how << "; kept the refinement from " << best_start;
  }
  best.how = how.str();
  return best;
}

}  // namespace polarform
