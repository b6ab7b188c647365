#include "designers/scan/cam_scan_profile.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <vector>

#include "designers/scan/cloud_plane.h"
#include "src/error.h"
#include "src/number_text.h"
#include "src/units.h"

namespace polarform {

namespace {

double quantile(std::vector<double> v, double q) {
  const auto k = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

Eigen::Matrix2Xd columns(const Eigen::Matrix2Xd& x, const std::vector<Eigen::Index>& keep) {
  Eigen::Matrix2Xd out(2, static_cast<Eigen::Index>(keep.size()));
  for (std::size_t a = 0; a < keep.size(); ++a)
    out.col(static_cast<Eigen::Index>(a)) = x.col(keep[a]);
  return out;
}

// The points of one face: those near an extreme level of the axial coordinate h (within a tenth
// of the 1 %–99 % range of h from it), narrowed to the face itself by the median level and the
// median absolute deviation (Hampel's robust scale), which the side-wall points in the band do not
// move because the face points are the majority.
std::vector<Eigen::Index> face_points(const std::vector<double>& h, double from, double to) {
  std::vector<Eigen::Index> band;
  std::vector<double> level;
  for (std::size_t c = 0; c < h.size(); ++c)
    if (h[c] >= from && h[c] <= to)
      band.push_back(static_cast<Eigen::Index>(c)), level.push_back(h[c]);
  if (band.size() < 16) return band;
  const double median = quantile(level, 0.5);
  for (double& t : level) t = std::abs(t - median);
  const double spread = std::max(5 * 1.4826 * quantile(level, 0.5), 1e-9 * (std::abs(median) + 1));
  std::vector<Eigen::Index> face;
  for (Eigen::Index c : band)
    if (std::abs(h[static_cast<std::size_t>(c)] - median) <= spread) face.push_back(c);
  return face;
}

// The two faces of a plate seen along k (1 % quantiles, so outliers do not set the range).
struct Faces {
  std::vector<Eigen::Index> bottom, top;
  Eigen::Vector3d bottom_mean = Eigen::Vector3d::Zero(), top_mean = Eigen::Vector3d::Zero();
};

Faces find_faces(const Eigen::Matrix3Xd& x, const Eigen::Vector3d& k) {
  std::vector<double> h(static_cast<std::size_t>(x.cols()));
  for (Eigen::Index c = 0; c < x.cols(); ++c) h[static_cast<std::size_t>(c)] = x.col(c).dot(k);
  const double lo = quantile(h, 0.01), hi = quantile(h, 0.99), w = hi - lo;
  Faces f;
  f.bottom = face_points(h, -INFINITY, lo + 0.1 * w);
  f.top = face_points(h, hi - 0.1 * w, INFINITY);
  if (f.bottom.size() < 16 || f.top.size() < 16)
    throw InputError(
        "cam scan: the 3D scan has " + std::to_string(f.bottom.size()) + " and " +
        std::to_string(f.top.size()) +
        " points on its two extreme levels along the axis; expected both faces of a plate cam "
        "(at least 16 points each)");
  for (Eigen::Index c : f.bottom) f.bottom_mean += x.col(c);
  for (Eigen::Index c : f.top) f.top_mean += x.col(c);
  f.bottom_mean /= static_cast<double>(f.bottom.size());
  f.top_mean /= static_cast<double>(f.top.size());
  return f;
}

// The common normal of two parallel planes fitted to the faces: the direction of least scatter of
// the face points, each face about its own mean.
Eigen::Vector3d face_normal(const Eigen::Matrix3Xd& x, const Faces& f,
                            const Eigen::Vector3d& previous) {
  Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
  for (Eigen::Index c : f.bottom)
    S += (x.col(c) - f.bottom_mean) * (x.col(c) - f.bottom_mean).transpose();
  for (Eigen::Index c : f.top) S += (x.col(c) - f.top_mean) * (x.col(c) - f.top_mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(S);
  const Eigen::Vector3d k = es.eigenvectors().col(0);
  return k.dot(previous) < 0 ? Eigen::Vector3d(-k) : k;
}

double face_flatness(const Eigen::Matrix3Xd& x, const Faces& f, const Eigen::Vector3d& k) {
  double sum = 0.0;
  for (Eigen::Index c : f.bottom) sum += std::pow((x.col(c) - f.bottom_mean).dot(k), 2);
  for (Eigen::Index c : f.top) sum += std::pow((x.col(c) - f.top_mean).dot(k), 2);
  return std::sqrt(sum / static_cast<double>(f.bottom.size() + f.top.size()));
}

std::string vector_text(const Eigen::Vector3d& v) {
  std::ostringstream s;
  s.precision(6);
  s << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
  return s.str();
}

// The widest empty sector of the points' polar angles about the origin, in radians.
double largest_angular_gap(const Eigen::Matrix2Xd& points) {
  std::vector<double> angle(static_cast<std::size_t>(points.cols()));
  for (Eigen::Index c = 0; c < points.cols(); ++c)
    angle[static_cast<std::size_t>(c)] = std::atan2(points(1, c), points(0, c));
  std::sort(angle.begin(), angle.end());
  double gap = angle.front() + 2 * std::numbers::pi - angle.back();
  for (std::size_t i = 0; i + 1 < angle.size(); ++i) gap = std::max(gap, angle[i + 1] - angle[i]);
  return gap;
}

}  // namespace

void split_bore(const Eigen::Matrix2Xd& q, const Eigen::Vector2d& centre, Eigen::Matrix2Xd& inner,
                Eigen::Matrix2Xd& outer) {
  const Eigen::VectorXd r = (q.colwise() - centre).colwise().norm().transpose();
  std::vector<double> sorted(r.data(), r.data() + r.size());
  std::sort(sorted.begin(), sorted.end());
  std::size_t at = 0;
  double gap = -1.0;
  for (std::size_t i = 0; i + 1 < sorted.size(); ++i)
    if (sorted[i + 1] - sorted[i] > gap) gap = sorted[i + 1] - sorted[i], at = i;
  std::vector<Eigen::Index> in, out;
  for (Eigen::Index c = 0; c < q.cols(); ++c) (r[c] <= sorted[at] ? in : out).push_back(c);
  bool bore = in.size() >= 12 && out.size() >= 12 && gap >= 0.1 * sorted.back();
  if (bore) {
    try {
      const CircleFit circle = fit_circle(columns(q, in));
      bore = circle.rms <= 0.02 * circle.radius;
    } catch (const InputError&) {
      bore = false;
    }
  }
  if (!bore) {
    in.clear();
    out.resize(static_cast<std::size_t>(q.cols()));
    for (Eigen::Index c = 0; c < q.cols(); ++c) out[static_cast<std::size_t>(c)] = c;
  }
  inner = columns(q, in);
  outer = columns(q, out);
}

CamProfile extract_cam_profile(const Eigen::Matrix3Xd& points, const CamProfileOptions& o) {
  if (points.cols() < 16)
    throw InputError("cam scan: " + std::to_string(points.cols()) +
                     " points, expected at least 16");
  if (!points.allFinite()) throw InputError("cam scan: a point is not finite");
  if (!((points.colwise() - points.col(0)).cwiseAbs().maxCoeff() > 0))
    throw InputError("cam scan: all points coincide");
  CamProfile p;
  const CloudPlane cloud = fit_plane(points, o.axis);
  p.three_d = !cloud.planar();
  Eigen::Vector3d k = cloud.frame.axes.col(2), origin = cloud.frame.origin;
  std::vector<Eigen::Index> slice;
  if (p.three_d) {
    const Eigen::Vector3d centroid = points.rowwise().mean();
    const Eigen::Matrix3Xd x = points.colwise() - centroid;
    if (!o.axis)
      for (int it = 0; it < 3; ++it) k = face_normal(x, find_faces(x, k), k);
    if (!o.axis && k.z() < 0) k = -k;
    const Faces f = find_faces(x, k);
    p.thickness = (f.top_mean - f.bottom_mean).dot(k);
    p.face_flatness = face_flatness(x, f, k);
    p.face_points = f.bottom.size() + f.top.size();
    const double size = x.colwise().norm().maxCoeff();
    if (!(p.face_flatness <= kMaxFaceFlatness * size))
      throw InputError("cam scan: a 3D scan whose faces are not flat (" +
                       number_text(p.face_flatness) + " mm rms from their planes, " +
                       number_text(100 * p.face_flatness / size) + " % of the scan's radius " +
                       number_text(size) + " mm, at most " + number_text(100 * kMaxFaceFlatness) +
                       " %): not a plate cam; a 2D profile scan needs no faces");
    const double mid = 0.5 * (f.top_mean + f.bottom_mean).dot(k);
    for (Eigen::Index c = 0; c < x.cols(); ++c)
      if (std::abs(x.col(c).dot(k) - mid) <= std::abs(p.thickness) / 4) slice.push_back(c);
    origin = centroid + mid * k;
    std::ostringstream why;
    why.precision(4);
    why << (o.axis ? "given" : "common normal of the two faces") << "; thickness "
        << std::abs(p.thickness) << " mm, faces flat within " << p.face_flatness
        << " mm rms; profile = the " << slice.size()
        << " points within thickness/4 of mid-thickness";
    p.axis_reason = why.str();
  } else {
    for (Eigen::Index c = 0; c < points.cols(); ++c) slice.push_back(c);
    std::ostringstream why;
    why.precision(4);
    why << (o.axis          ? "given"
            : cloud.snapped ? "2D scan in the plane z = const"
                            : "2D scan: normal of its best-fit plane")
        << (cloud.rms_distance > 0
                ? " (points within " + number_text(cloud.rms_distance) + " mm rms of the plane)"
                : std::string(" (every point exactly in the plane)"));
    p.axis_reason = why.str();
  }
  p.plane.axes = fit_plane(points, k).frame.axes;
  p.plane.origin = origin;
  Eigen::Matrix2Xd q(2, static_cast<Eigen::Index>(slice.size()));
  for (std::size_t a = 0; a < slice.size(); ++a)
    q.col(static_cast<Eigen::Index>(a)) =
        p.plane.to_local(Eigen::Vector3d(points.col(slice[a]))).head<2>();

  Eigen::Vector2d centre;
  std::ostringstream why;
  why.precision(6);
  if (o.centre) {
    centre = p.plane.to_local(*o.centre).head<2>();
    split_bore(q, centre, p.bore, p.contour);
    why << "given " << vector_text(*o.centre);
    if (p.bore.cols() > 0) p.bore_circle = fit_circle(p.bore);
  } else {
    split_bore(q, q.rowwise().mean(), p.bore, p.contour);
    if (p.bore.cols() == 0)
      throw InputError(
          "cam scan: no bore found (no inner loop of points separated from the contour by a "
          "gap of at least a tenth of its radius); give the centre of rotation with --center");
    for (int it = 0; it < 2; ++it) {
      const CircleFit c = fit_circle(p.bore);
      split_bore(q, c.centre, p.bore, p.contour);
      if (p.bore.cols() == 0)
        throw InputError(
            "cam scan: the bore found at first does not persist about its own centre; give "
            "--center");
    }
    p.bore_circle = fit_circle(p.bore);
    centre = p.bore_circle->centre;
    why << "bore centre: circle fit (Taubin) of " << p.bore.cols() << " bore points, diameter "
        << 2 * p.bore_circle->radius << " mm, rms " << p.bore_circle->rms << " mm";
  }
  p.centre_reason = why.str();
  p.plane.origin = p.plane.to_global(Eigen::Vector3d(centre.x(), centre.y(), 0.0));
  p.contour.colwise() -= centre;
  if (p.bore.cols() > 0) {
    p.bore.colwise() -= centre;
    p.bore_circle->centre -= centre;
  }
  if (p.contour.cols() < 16)
    throw InputError("cam scan: " + std::to_string(p.contour.cols()) +
                     " contour points, expected at least 16");
  const double gap = largest_angular_gap(p.contour);
  if (gap > kMaxContourGap)
    throw InputError("cam scan: the contour does not surround the centre of rotation " +
                     vector_text(p.plane.origin) +
                     ": seen from it, the contour points leave a gap of " +
                     number_text(gap * kDegreesPerRadian) + "° (at most " +
                     number_text(kMaxContourGap * kDegreesPerRadian) +
                     "°); a plate cam's contour goes round its axis — check --center");
  return p;
}

}  // namespace polarform
