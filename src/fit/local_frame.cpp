#include "src/fit/local_frame.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "src/error.h"

namespace polarform {

Eigen::Vector3d LocalFrame::to_local(const Eigen::Vector3d& g) const {
  return axes.transpose() * (g - origin);
}

Eigen::Matrix3Xd LocalFrame::to_local(const Eigen::Matrix3Xd& g) const {
  return axes.transpose() * (g.colwise() - origin);
}

Eigen::Vector3d LocalFrame::to_global(const Eigen::Vector3d& l) const { return axes * l + origin; }

Eigen::Matrix3Xd LocalFrame::to_global(const Eigen::Matrix3Xd& l) const {
  return (axes * l).colwise() + origin;
}

namespace {

// (w·P, w) -> (w·(R^{-1} P + T), w): Bae 2002, eq. (4.6) on homogeneous coordinates.
Eigen::MatrixXd transform_homogeneous(const LocalFrame& f, const Eigen::MatrixXd& h) {
  Eigen::MatrixXd out = h;
  out.topRows(3) = f.axes * h.topRows(3) + f.origin * h.row(3);
  return out;
}

Eigen::Vector3d unit(const Eigen::Vector3d& v, const char* what) {
  const double n = v.norm();
  if (!(n > 0.0) || !std::isfinite(n))
    throw InputError(std::string("local frame: ") + what + " must be a finite non-zero vector");
  return v / n;
}

// Σ ((x − o)·d)³: the sign that makes a direction follow the data under rigid motions.
double third_moment(const Eigen::Matrix3Xd& x, const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
  double s = 0.0;
  for (Eigen::Index k = 0; k < x.cols(); ++k) {
    const double t = (x.col(k) - o).dot(d);
    s += t * t * t;
  }
  return s;
}

// The direction of largest spread of the data across k.
Eigen::Vector3d principal_across(const Eigen::Matrix3Xd& x, const Eigen::Vector3d& o,
                                 const Eigen::Vector3d& k) {
  const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - k * k.transpose();
  const Eigen::Matrix3Xd y = P * (x.colwise() - o);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(y * y.transpose());
  return es.eigenvectors().col(2);
}

// The signature columns k and K of Bae 2002, Table 4.1, in words.
std::string signature_words(const QuadricClassification& c) {
  const auto sign = [](bool same) { return same ? "share one sign" : "differ in sign"; };
  return std::string("the non-zero eigenvalues of Qu ") + sign(c.k_same) + ", those of Q " +
         sign(c.K_same);
}

}  // namespace

NurbsSurface LocalFrame::to_global(const NurbsSurface& s) const {
  const BSplineSurface& h = s.homogeneous();
  return NurbsSurface(BSplineSurface(h.degree_u(), h.degree_v(), h.knots_u(), h.knots_v(),
                                     transform_homogeneous(*this, h.coefs())));
}

NurbsCurve3d LocalFrame::to_global(const NurbsCurve3d& c) const {
  const BSpline& h = c.homogeneous();
  return NurbsCurve3d(BSpline(h.degree(), h.knots(), transform_homogeneous(*this, h.coefs())));
}

FrameEstimate estimate_frame(const Eigen::Matrix3Xd& points, const FrameOptions& opt) {
  if (points.cols() < 1 || !points.allFinite())
    throw InputError("local frame: expected at least one point, all finite");
  FrameEstimate out;
  std::ostringstream why;
  Eigen::Vector3d o, k, i;
  if (opt.origin && opt.axis) {
    o = *opt.origin;
    k = unit(*opt.axis, "axis");
    why << "origin and axis given";
  } else {
    const QuadricFit qf = fit_quadric(points, opt.quadric);
    const QuadricClassification& c = qf.classification;
    why << "best-fit quadric: " << to_string(c.type) << " (rank Qu " << c.rank_Qu << ", rank Q "
        << c.rank_Q << "; " << signature_words(c) << "; RMS distance " << qf.rms_distance << ")";
    if (!defines_frame(c.type))
      throw InputError("local frame: " + why.str() +
                       " defines no centre and axis (Bae 2002, Sec. 4.3 needs an ellipsoid, "
                       "hyperboloid, cone, elliptic paraboloid or elliptic cylinder); give the "
                       "centre and axis");
    const Eigen::Vector3d lam = c.eigenvalues;
    const Eigen::Matrix3d V = c.eigenvectors;
    const Eigen::Vector3d vb = V.transpose() * qf.normalized.v();
    // Origin in the normalised coordinates, then back: x = centroid + scale · y.
    Eigen::Vector3d y = Eigen::Vector3d::Zero();
    int null_index = 0;
    for (int a = 0; a < 3; ++a) {
      if (c.zero_eigenvalue[a] == 0.0) y -= V.col(a) * vb[a] / (2 * lam[a]);  // (4.3) / particular
      else null_index = a;
    }
    if (c.rank_Qu == 2) {
      // Appendix E: o = p + t_o q, t_o = q · mean(Ψ − p), and the normalised data has mean 0.
      const Eigen::Vector3d q = V.col(null_index);
      y -= q * q.dot(y);
    }
    o = opt.origin ? *opt.origin : Eigen::Vector3d(qf.centroid + qf.scale * y);
    why << "; origin " << (opt.origin ? "given" : c.rank_Qu == 3 ? "by eq. (4.3)" : "by Appendix E");
    int ki = 0;
    if (c.rank_Qu == 2) {
      ki = null_index;
      why << "; k: the zero eigenvalue's eigenvector";
    } else if (!c.k_same) {
      const int pos = (lam.array() > 0).count();
      for (int a = 0; a < 3; ++a)
        if ((lam[a] > 0) == (pos == 1)) ki = a;
      why << "; k: the eigenvector of the lone-sign eigenvalue";
    } else if (opt.ellipsoid_axis == EllipsoidAxis::largest_eigenvalue) {
      lam.cwiseAbs().maxCoeff(&ki);
      why << "; k: the largest eigenvalue's eigenvector";
    } else {
      std::array<int, 3> by = {0, 1, 2};  // by |λ|: the most distinct one is an end
      std::sort(by.begin(), by.end(), [&](int x, int y) { return std::abs(lam[x]) < std::abs(lam[y]); });
      const double low = std::abs(lam[by[1]]) - std::abs(lam[by[0]]);
      const double high = std::abs(lam[by[2]]) - std::abs(lam[by[1]]);
      ki = low > high ? by[0] : by[2];
      why << "; k: the most distinct eigenvalue's eigenvector (spheroid axis)";
    }
    if (opt.axis) {
      k = unit(*opt.axis, "axis");
      why << " (overridden: axis given)";
    } else {
      k = V.col(ki);
      if (third_moment(points, o, k) < 0) k = -k;
      int ii = -1;
      for (int a = 0; a < 3; ++a)
        if (a != ki && (ii < 0 || std::abs(lam[a]) > std::abs(lam[ii]))) ii = a;
      i = V.col(ii);
    }
    out.quadric = qf;
  }
  if (opt.reference) {
    i = *opt.reference - k * k.dot(*opt.reference);
    i = unit(i, "reference direction (across the axis)");
    why << "; i from the reference direction";
  } else {
    if (opt.axis || !out.quadric) i = principal_across(points, o, k);
    i = (i - k * k.dot(i)).normalized();
    if (third_moment(points, o, i) < 0) i = -i;
  }
  out.frame.origin = o;
  out.frame.axes.col(0) = i;
  out.frame.axes.col(1) = k.cross(i);
  out.frame.axes.col(2) = k;
  out.reason = why.str();
  return out;
}

LocalCloud local_cloud(const Eigen::Matrix3Xd& points, FrameOptions options, int threads,
                       const std::string& fit_name) {
  if (points.cols() < 16)
    throw InputError(fit_name + ": " + std::to_string(points.cols()) +
                     " points, expected at least 16");
  if (!points.allFinite()) throw InputError(fit_name + ": a point is not finite");
  // A surface about an axis or a centre needs points that span more than a line: the spread
  // across the principal direction against the spread along it (square roots of the
  // covariance's eigenvalues).
  const Eigen::Matrix3Xd centred = points.colwise() - points.rowwise().mean();
  const Eigen::Vector3d spread =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(centred * centred.transpose() / points.cols(),
                                                     Eigen::EigenvaluesOnly)
          .eigenvalues()
          .cwiseMax(0.0)
          .cwiseSqrt();
  if (!(spread(2) > 0.0)) throw InputError(fit_name + ": all points coincide");
  if (!(spread(1) > 1e-6 * spread(2))) {
    std::ostringstream msg;
    msg.precision(4);
    msg << fit_name << ": the points lie on a straight line (spread " << spread(1)
        << " mm across it, " << spread(2) << " mm along it): no surface about an axis or a centre";
    throw InputError(msg.str());
  }
  options.quadric.threads = threads;
  LocalCloud out{estimate_frame(points, options), {}};
  out.points = out.frame.frame.to_local(points);
  return out;
}

}  // namespace polarform
