#include "src/fit/frame_candidates.h"

#include <Eigen/Dense>
#include <cmath>
#include <sstream>

namespace polarform {

namespace {

constexpr Eigen::Index kMaxPoints = 20000;

Eigen::Matrix3Xd strided(const Eigen::Matrix3Xd& p) {
  if (p.cols() <= kMaxPoints) return p;
  const Eigen::Index stride = (p.cols() + kMaxPoints - 1) / kMaxPoints;
  Eigen::Matrix3Xd out(3, (p.cols() + stride - 1) / stride);
  for (Eigen::Index a = 0; a < out.cols(); ++a) out.col(a) = p.col(a * stride);
  return out;
}

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
  const Eigen::Matrix3Xd p = strided(points);
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
  const Eigen::Matrix3Xd p = strided(points);
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

}  // namespace polarform
