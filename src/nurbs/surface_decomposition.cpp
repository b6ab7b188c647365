// Crack-free quadrilateral decomposition (Piegl & Tiller 2001, §3.1; spec P4).
#include "src/nurbs/surface_decomposition.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

#include "src/error.h"
#include "src/nurbs/error_text.h"
#include "src/nurbs/periodic.h"

namespace polarform {

namespace {

struct Rectangle {
  double u0, u1, v0, v1;
  int depth;
};

// Greville abscissae of a clamped knot vector, mapped to [0, 1] over its domain (NURBS Book eq.
// (9.44)-style averages of p consecutive knots).
std::vector<double> greville(int p, const Knots& U) {
  const int n = static_cast<int>(U.size()) - p - 1;
  std::vector<double> g(n);
  for (int i = 0; i < n; ++i) {
    double sum = 0.0;
    for (int k = 1; k <= p; ++k) sum += U[i + k];
    g[i] = (sum / p - U[p]) / (U[n] - U[p]);
  }
  return g;
}

// The Cartesian control net (nu × nv) of the sub-patch over a rectangle (clip: NURBS Book A5.1),
// with the Greville parameters of its control points in [0, 1]².
struct SubNet {
  int nu, nv;
  Eigen::Matrix3Xd P;  // column i·nv + j
  std::vector<double> gu, gv;
  Eigen::Vector3d at(int i, int j) const { return P.col(i * nv + j); }
};

SubNet sub_net(const BSplineSurface& h, const Rectangle& r) {
  const BSplineSurface s = clip_v(clip_u(h, r.u0, r.u1), r.v0, r.v1);
  SubNet net{s.size_u(), s.size_v(), Eigen::Matrix3Xd(3, s.coefs().cols()),
             greville(s.degree_u(), s.knots_u()), greville(s.degree_v(), s.knots_v())};
  for (Eigen::Index k = 0; k < s.coefs().cols(); ++k)
    net.P.col(k) = s.coefs().col(k).head<3>() / s.coefs()(3, k);
  return net;
}

// Max distance of the net from the plane through the corners' centroid with normal d1 × d2 (P&T
// 2001, §3.1); a degenerate corner normal (collapsed edges) falls back to the LSQ plane of the net.
double plane_deviation(const SubNet& n) {
  const Eigen::Vector3d p00 = n.at(0, 0), p10 = n.at(n.nu - 1, 0), p01 = n.at(0, n.nv - 1),
                        p11 = n.at(n.nu - 1, n.nv - 1);
  const Eigen::Vector3d d1 = p11 - p00, d2 = p01 - p10;
  Eigen::Vector3d centre = 0.25 * (p00 + p10 + p01 + p11), normal = d1.cross(d2);
  if (!(normal.norm() > 1e-12 * d1.norm() * d2.norm())) {
    centre = n.P.rowwise().mean();  // LSQ plane: the least principal direction
    const Eigen::Matrix3Xd X = n.P.colwise() - centre;
    normal =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(X * X.transpose()).eigenvectors().col(0);
  }
  return ((n.P.colwise() - centre).transpose() * normal.normalized()).cwiseAbs().maxCoeff();
}

// Max distance of the net from the bilinear patch B of its corners at the Greville parameters: B
// written on the sub-patch's basis has exactly those control points (linear precision), so for a
// non-rational surface |S − B| is at most this everywhere; it sees the in-plane deviation (curved
// edges, collapsed corners) that the mid-plane test cannot. For a rational surface it is an
// estimate.
double bilinear_deviation(const SubNet& n) {
  const Eigen::Vector3d p00 = n.at(0, 0), p10 = n.at(n.nu - 1, 0), p01 = n.at(0, n.nv - 1),
                        p11 = n.at(n.nu - 1, n.nv - 1);
  double worst = 0.0;
  for (int i = 0; i < n.nu; ++i)
    for (int j = 0; j < n.nv; ++j) {
      const double s = n.gu[i], t = n.gv[j];
      const Eigen::Vector3d b =
          (1 - s) * (1 - t) * p00 + s * (1 - t) * p10 + (1 - s) * t * p01 + s * t * p11;
      worst = std::max(worst, (n.at(i, j) - b).norm());
    }
  return worst;
}

// Distance of q from the line through a and b (from a when a = b).
double chord_distance(const Eigen::Vector3d& q, const Eigen::Vector3d& a,
                      const Eigen::Vector3d& b) {
  const Eigen::Vector3d d = b - a;
  const double len = d.norm();
  return len > 0.0 ? d.cross(q - a).norm() / len : (q - a).norm();
}

// The curvature rule (spec P4): true when the rows (polygons along u) deviate more from their
// chords than the columns (polygons along v).
bool rows_deviate_more(const SubNet& n) {
  double along_u = 0.0, along_v = 0.0;
  for (int j = 0; j < n.nv; ++j)
    for (int i = 1; i + 1 < n.nu; ++i)
      along_u = std::max(along_u, chord_distance(n.at(i, j), n.at(0, j), n.at(n.nu - 1, j)));
  for (int i = 0; i < n.nu; ++i)
    for (int j = 1; j + 1 < n.nv; ++j)
      along_v = std::max(along_v, chord_distance(n.at(i, j), n.at(i, 0), n.at(i, n.nv - 1)));
  return along_u >= along_v;
}

// The seed's rule: the larger of the mean corner-to-corner lengths along u and along v.
bool u_extent_larger(const SubNet& n) {
  const double lu = (n.at(n.nu - 1, 0) - n.at(0, 0)).norm() +
                    (n.at(n.nu - 1, n.nv - 1) - n.at(0, n.nv - 1)).norm();
  const double lv = (n.at(0, n.nv - 1) - n.at(0, 0)).norm() +
                    (n.at(n.nu - 1, n.nv - 1) - n.at(n.nu - 1, 0)).norm();
  return lu >= lv;
}

void insert_sorted(std::vector<double>& values, double x) {
  const auto it = std::lower_bound(values.begin(), values.end(), x);
  if (it == values.end() || *it != x) values.insert(it, x);
}

}  // namespace

// Piegl & Tiller 2001, §3.1: stack of rectangles, flatness against the mid-plane, midpoint splits,
// the blanket on the tensor grid of every split value.
SurfaceDecomposition decompose_surface(const NurbsSurface& s, const DecompositionOptions& options) {
  if (!(options.tolerance_rel > 0.0 && std::isfinite(options.tolerance_rel)))
    throw InputError("surface decomposition: tolerance_rel is " + to_text(options.tolerance_rel) +
                     ", expected a finite value > 0");
  const BSplineSurface& h = s.homogeneous();
  Eigen::Matrix3Xd net(3, h.coefs().cols());
  for (Eigen::Index k = 0; k < net.cols(); ++k)
    net.col(k) = h.coefs().col(k).head<3>() / h.coefs()(3, k);
  SurfaceDecomposition out;
  out.tolerance =
      options.tolerance_rel * (net.rowwise().maxCoeff() - net.rowwise().minCoeff()).norm();
  const double span_u = s.back_u() - s.front_u(), span_v = s.back_v() - s.front_v();
  std::vector<double>& U = out.blanket.u;
  std::vector<double>& V = out.blanket.v;
  U = {s.front_u(), s.back_u()};
  V = {s.front_v(), s.back_v()};
  std::vector<Rectangle> stack{{s.front_u(), s.back_u(), s.front_v(), s.back_v(), 0}};
  while (!stack.empty()) {
    const Rectangle r = stack.back();
    stack.pop_back();
    const SubNet n = sub_net(h, r);
    ++out.flatness_tests;
    if (plane_deviation(n) <= out.tolerance && bilinear_deviation(n) <= out.tolerance) continue;
    const bool split_u =
        options.split == SplitRule::extent ? u_extent_larger(n) : rows_deviate_more(n);
    const double lo = split_u ? r.u0 : r.v0, hi = split_u ? r.u1 : r.v1;
    if (r.depth >= 40 || (hi - lo) / 2 < 1e-12 * (split_u ? span_u : span_v))
      throw NumericalError("surface decomposition: [" + to_text(r.u0) + ", " + to_text(r.u1) +
                           "] × [" + to_text(r.v0) + ", " + to_text(r.v1) + "] is not within " +
                           to_text(out.tolerance) + " mm of a plane after " +
                           std::to_string(r.depth) + " splits (limit: depth 40, span 1e-12)");
    const double mid = 0.5 * (lo + hi);
    insert_sorted(split_u ? U : V, mid);
    if (split_u) {
      stack.push_back({r.u0, mid, r.v0, r.v1, r.depth + 1});
      stack.push_back({mid, r.u1, r.v0, r.v1, r.depth + 1});
    } else {
      stack.push_back({r.u0, r.u1, r.v0, mid, r.depth + 1});
      stack.push_back({r.u0, r.u1, mid, r.v1, r.depth + 1});
    }
  }
  out.blanket.points.resize(3, static_cast<Eigen::Index>(U.size() * V.size()));
  for (std::size_t a = 0; a < U.size(); ++a)
    for (std::size_t b = 0; b < V.size(); ++b)
      out.blanket.points.col(out.blanket.vertex(static_cast<int>(a), static_cast<int>(b))) =
          s.point(U[a], V[b]);
  return out;
}

}  // namespace polarform
