// Parameters of points from the nearest quad of a surface blanket (Piegl & Tiller 2001, §3.2,
// §3.4; spec P6): quads binned by their bounding boxes in a uniform grid (3D, or 2D in the
// maximum-area plane), searched in rings around each point's cell; bilinear inversion in the
// quad's mid-plane; optional Newton polish on the base surface.
#include "src/fit/quad_projection.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "src/error.h"
#include "src/fit/max_area_plane.h"
#include "src/fit/parallel.h"
#include "src/nurbs/point_inversion.h"

namespace polarform {

namespace {

// One blanket quad prepared for projection: its corners and its mid-plane frame, in which the
// bilinear map is A + s·e + t·f + s·t·g (2D).
struct Quad {
  Eigen::Vector3d p00, p10, p11, p01, e1, e2;
  Eigen::Vector2d e, f, g;
  bool planar_frame = false;  // false for a quad collapsed to a segment or point
};

Quad prepare(const Eigen::Vector3d& p00, const Eigen::Vector3d& p10, const Eigen::Vector3d& p11,
             const Eigen::Vector3d& p01) {
  Quad q{p00, p10, p11, p01, {}, {}, {}, {}, {}};
  const Eigen::Vector3d n = (p11 - p00).cross(p01 - p10);  // spec P4/P6: normal d1 × d2
  const double scale = std::max({(p11 - p00).norm(), (p01 - p10).norm(), (p10 - p00).norm()});
  if (!(n.norm() > 1e-12 * scale * scale)) return q;
  const Eigen::Vector3d N = n.normalized();
  q.e1 = N.unitOrthogonal();
  q.e2 = N.cross(q.e1);
  const auto flat = [&](const Eigen::Vector3d& x) {
    return Eigen::Vector2d((x - p00).dot(q.e1), (x - p00).dot(q.e2));
  };
  q.e = flat(p10);
  q.f = flat(p01);
  q.g = flat(p11) - q.e - q.f;
  q.planar_frame = true;
  return q;
}

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

struct QuadHit {
  double s = 0.0, t = 0.0, distance = std::numeric_limits<double>::infinity();
  bool clamped = false;
};

Eigen::Vector3d bilinear(const Quad& q, double s, double t) {
  return (1 - s) * (1 - t) * q.p00 + s * (1 - t) * q.p10 + s * t * q.p11 + (1 - s) * t * q.p01;
}

// The nearest point of the quad's four edges (straight segments), for points outside the quad.
QuadHit nearest_on_edges(const Quad& q, const Eigen::Vector3d& x) {
  QuadHit best;
  best.clamped = true;
  const std::array<std::array<double, 4>, 4> edges{
      {{0, 0, 1, 0}, {1, 0, 1, 1}, {0, 1, 1, 1}, {0, 0, 0, 1}}};
  for (const auto& e : edges) {
    const Eigen::Vector3d a = bilinear(q, e[0], e[1]), b = bilinear(q, e[2], e[3]);
    const double len2 = (b - a).squaredNorm();
    const double w = len2 > 0.0 ? std::clamp((x - a).dot(b - a) / len2, 0.0, 1.0) : 0.0;
    const double d = (x - (a + w * (b - a))).norm();
    if (d < best.distance) best = {e[0] + w * (e[2] - e[0]), e[1] + w * (e[3] - e[1]), d, true};
  }
  return best;
}

// Piegl & Tiller 2001, §3.4: the point and the quad projected into the quad's mid-plane, the
// bilinear map inverted there (closed-form quadratic in t, then s by least squares; the seed's
// pencil of rulings is this inverse for parallelograms and keeps the corners' parameters
// consistent otherwise). Outside the quad: the nearest edge point (spec P6, fix 1).
QuadHit project_on_quad(const Quad& q, const Eigen::Vector3d& x) {
  if (!q.planar_frame) return nearest_on_edges(q, x);
  const Eigen::Vector2d h((x - q.p00).dot(q.e1), (x - q.p00).dot(q.e2));
  const double k2 = cross2(q.g, q.f), k1 = cross2(q.e, q.f) + cross2(h, q.g), k0 = cross2(h, q.e);
  std::array<double, 2> roots{};
  int count = 0;
  if (std::abs(k2) <= 1e-12 * std::abs(k1)) {
    if (k1 != 0.0) roots[count++] = -k0 / k1;
  } else {
    const double disc = k1 * k1 - 4.0 * k0 * k2;
    if (disc >= 0.0) {
      const double w = std::sqrt(disc);
      const double r = -0.5 * (k1 + std::copysign(w, k1));  // stable quadratic roots
      roots[count++] = r / k2;
      if (r != 0.0) roots[count++] = k0 / r;
    }
  }
  constexpr double eps = 1e-12;
  for (int k = 0; k < count; ++k) {
    const double t = roots[k];
    const Eigen::Vector2d d = q.e + t * q.g;
    if (!(d.squaredNorm() > 0.0)) continue;
    const double s = (h - t * q.f).dot(d) / d.squaredNorm();
    if (s >= -eps && s <= 1 + eps && t >= -eps && t <= 1 + eps) {
      const double sc = std::clamp(s, 0.0, 1.0), tc = std::clamp(t, 0.0, 1.0);
      return {sc, tc, (x - bilinear(q, sc, tc)).norm(), false};
    }
  }
  return nearest_on_edges(q, x);
}

// Quads binned by their bounding boxes (in Dim coordinates) in compressed rows, and the ring
// search: ring L holds the cells at Chebyshev distance L; a quad in no searched cell is at least
// the wall distance + L·size away (projection to the plane shortens distances, so in 2D too).
template <int Dim>
class QuadGrid {
 public:
  using Vec = Eigen::Matrix<double, Dim, 1>;

  QuadGrid(const std::vector<Vec>& lo, const std::vector<Vec>& hi, double size) : size_(size) {
    const int n = static_cast<int>(lo.size());
    low_ = lo[0];
    Vec high = hi[0];
    for (int k = 1; k < n; ++k) {
      low_ = low_.cwiseMin(lo[k]);
      high = high.cwiseMax(hi[k]);
    }
    if (!(size_ > 0.0)) size_ = std::max(1e-300, (high - low_).maxCoeff());
    auto counts = [&] {
      double total = 1.0;
      for (int d = 0; d < Dim; ++d) {
        cells_[d] = std::max(1, static_cast<int>(std::ceil((high[d] - low_[d]) / size_)));
        total *= cells_[d];
      }
      return total;
    };
    while (counts() > 8.0 * n + 64.0) size_ *= 1.25;
    int total = 1;
    for (int d = 0; d < Dim; ++d) total *= cells_[d];
    start_.assign(static_cast<std::size_t>(total) + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<int> fill(start_.begin(), start_.end() - 1);
      if (pass == 1) index_.resize(static_cast<std::size_t>(start_.back()));
      for (int k = 0; k < n; ++k) {
        const auto a = cell_of(lo[k]), b = cell_of(hi[k]);
        auto c = a;
        for (;;) {
          const int l = linear(c);
          if (pass == 0)
            ++start_[l + 1];
          else
            index_[fill[l]++] = k;
          int d = Dim - 1;
          while (d >= 0 && ++c[d] > b[d]) c[d] = a[d], --d;
          if (d < 0) break;
        }
      }
      if (pass == 0)
        for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    }
  }

  int cell_count() const { return static_cast<int>(start_.size()) - 1; }

  // visit(quad) returns the current best distance; the search stops once it is within the bound.
  template <class Visit>
  void search(const Vec& x, std::vector<int>& stamp, int mark, Visit&& visit) const {
    const auto c0 = cell_of(x);
    double wall = std::numeric_limits<double>::infinity();
    int last_ring = 0;
    for (int d = 0; d < Dim; ++d) {
      const double lo = low_[d] + c0[d] * size_;
      if (c0[d] > 0) wall = std::min(wall, std::max(0.0, x[d] - lo));
      if (c0[d] + 1 < cells_[d]) wall = std::min(wall, std::max(0.0, lo + size_ - x[d]));
      last_ring = std::max({last_ring, c0[d], cells_[d] - 1 - c0[d]});
    }
    double best = std::numeric_limits<double>::infinity();
    for (int ring = 0; ring <= last_ring; ++ring) {
      std::array<int, Dim> lo{}, hi{};
      for (int d = 0; d < Dim; ++d) {
        lo[d] = std::max(0, c0[d] - ring);
        hi[d] = std::min(cells_[d] - 1, c0[d] + ring);
      }
      auto c = lo;
      for (;;) {
        int cheb = 0;
        for (int d = 0; d < Dim; ++d) cheb = std::max(cheb, std::abs(c[d] - c0[d]));
        if (cheb == ring) {
          const int l = linear(c);
          for (int k = start_[l]; k < start_[l + 1]; ++k) {
            const int quad = index_[k];
            if (stamp[quad] == mark) continue;
            stamp[quad] = mark;
            best = visit(quad);
          }
        }
        int d = Dim - 1;
        while (d >= 0 && ++c[d] > hi[d]) c[d] = lo[d], --d;
        if (d < 0) break;
      }
      if (best <= wall + ring * size_) break;
    }
  }

 private:
  std::array<int, Dim> cell_of(const Vec& p) const {
    std::array<int, Dim> c{};
    for (int d = 0; d < Dim; ++d) {
      const double f = std::floor((p[d] - low_[d]) / size_);
      c[d] = f < 0.0 ? 0 : (f >= cells_[d] - 1 ? cells_[d] - 1 : static_cast<int>(f));
    }
    return c;
  }
  int linear(const std::array<int, Dim>& c) const {
    int l = c[0];
    for (int d = 1; d < Dim; ++d) l = l * cells_[d] + c[d];
    return l;
  }

  Vec low_;
  double size_;
  std::array<int, Dim> cells_{};
  std::vector<int> start_, index_;
};

void check_blanket(const SurfaceBlanket& b) {
  if (b.u.size() < 2 || b.v.size() < 2 ||
      b.points.cols() != static_cast<Eigen::Index>(b.u.size() * b.v.size()))
    throw InputError("quad projection: the blanket needs at least 2 × 2 vertices and " +
                     std::to_string(b.u.size()) + " × " + std::to_string(b.v.size()) +
                     " points, it has " + std::to_string(b.points.cols()));
}

// Nearest quad of every point through the grid over coordinates `to_dim` (3D or plane).
template <int Dim, class ToDim>
void search_quads(const Eigen::Matrix3Xd& points, const SurfaceBlanket& blanket,
                  const std::vector<Quad>& quads, double size, ToDim to_dim, int threads,
                  PatchParameters& out) {
  using Vec = Eigen::Matrix<double, Dim, 1>;
  const int nq = static_cast<int>(quads.size());
  std::vector<Vec> lo(nq), hi(nq);
  for (int k = 0; k < nq; ++k) {
    const Quad& q = quads[k];
    lo[k] = hi[k] = to_dim(q.p00);
    for (const Eigen::Vector3d* c : {&q.p10, &q.p11, &q.p01}) {
      lo[k] = lo[k].cwiseMin(to_dim(*c));
      hi[k] = hi[k].cwiseMax(to_dim(*c));
    }
  }
  const QuadGrid<Dim> grid(lo, hi, size);
  out.stats.cells = grid.cell_count();
  const std::size_t n = static_cast<std::size_t>(points.cols());
  const int chunks = worker_count(threads, n, 1000);
  std::vector<long long> tests(chunks, 0);
  const int qv = blanket.quads_v();
  parallel_chunks(n, chunks, [&](std::size_t begin, std::size_t end, int chunk) {
    std::vector<int> stamp(nq, -1);
    for (std::size_t k = begin; k < end; ++k) {
      const Eigen::Vector3d x = points.col(static_cast<Eigen::Index>(k));
      QuadHit best;
      int best_quad = 0;
      grid.search(to_dim(x), stamp, static_cast<int>(k), [&](int quad) {
        ++tests[chunk];
        const QuadHit hit = project_on_quad(quads[quad], x);
        if (hit.distance < best.distance) best = hit, best_quad = quad;
        return best.distance;
      });
      const int a = best_quad / qv, b = best_quad % qv;
      out.u[k] = blanket.u[a] + best.s * (blanket.u[a + 1] - blanket.u[a]);
      out.v[k] = blanket.v[b] + best.t * (blanket.v[b + 1] - blanket.v[b]);
      out.distance[k] = best.distance;
      out.clamped[k] = best.clamped ? 1 : 0;
    }
  });
  for (long long t : tests) out.stats.point_quad_tests += t;
}

double median_diagonal(const std::vector<Quad>& quads) {
  std::vector<double> d(quads.size());
  for (std::size_t k = 0; k < quads.size(); ++k)
    d[k] = std::max((quads[k].p11 - quads[k].p00).norm(), (quads[k].p01 - quads[k].p10).norm());
  std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
  return d[d.size() / 2];
}

}  // namespace

// Piegl & Tiller 2001, §3.2 and §3.4 (grid search, projection onto quads); spec P6.
PatchParameters parametrize_on_blanket(const Eigen::Matrix3Xd& points, const NurbsSurface& base,
                                       const SurfaceBlanket& blanket,
                                       const PatchSearchOptions& options) {
  check_blanket(blanket);
  if (!points.allFinite()) throw InputError("quad projection: a point has a non-finite coordinate");
  const std::size_t n = static_cast<std::size_t>(points.cols());
  PatchParameters out{
      Eigen::VectorXd(n), Eigen::VectorXd(n), Eigen::VectorXd(n), std::vector<char>(n, 0), {}};
  std::vector<Quad> quads;
  quads.reserve(static_cast<std::size_t>(blanket.quads()));
  const auto P = [&](int a, int b) {
    return Eigen::Vector3d(blanket.points.col(blanket.vertex(a, b)));
  };
  for (int a = 0; a < blanket.quads_u(); ++a)
    for (int b = 0; b < blanket.quads_v(); ++b)
      quads.push_back(prepare(P(a, b), P(a + 1, b), P(a + 1, b + 1), P(a, b + 1)));
  out.stats.brute_force_tests = static_cast<long long>(quads.size()) * static_cast<long long>(n);

  if (options.search == PatchSearch::grid3d) {
    search_quads<3>(
        points, blanket, quads, median_diagonal(quads), [](const Eigen::Vector3d& x) { return x; },
        options.threads, out);
  } else {
    // The seed's plane: rotate the max-area plane to z = 0 (P&T §3.2); folds make it ambiguous.
    const MaxAreaPlane plane = max_area_plane(blanket);
    out.stats.folded_triangles = plane.folded_triangles;
    if (plane.folded_triangles > 0)
      throw InputError("plane search: " + std::to_string(plane.folded_triangles) +
                       " blanket triangles face away from the maximum-area plane (the patch turns "
                       "by more than 180°); use --search grid3d");
    const Eigen::Vector3d e1 = plane.normal.unitOrthogonal(), e2 = plane.normal.cross(e1);
    const auto to_plane = [&](const Eigen::Vector3d& x) {
      return Eigen::Vector2d(x.dot(e1), x.dot(e2));
    };
    Eigen::Vector2d lo = to_plane(blanket.points.col(0)), hi = lo;
    for (Eigen::Index k = 1; k < blanket.points.cols(); ++k) {
      lo = lo.cwiseMin(to_plane(blanket.points.col(k)));
      hi = hi.cwiseMax(to_plane(blanket.points.col(k)));
    }
    // P&T §3.2: size = sqrt(x_L·y_L / number of blanket vertices).
    const double size = std::sqrt((hi - lo).prod() / static_cast<double>(blanket.points.cols()));
    search_quads<2>(points, blanket, quads, size, to_plane, options.threads, out);
  }
  for (char c : out.clamped) out.stats.clamped_points += c;

  // Spec P6, fix 2: Newton from the quad parameters to the foot point on the base surface.
  std::optional<SurfaceProjector> projector;
  if (options.polish) projector.emplace(base);
  out.stats.polished = options.polish;
  parallel_chunks(n, worker_count(options.threads, n, 1000),
                  [&](std::size_t b, std::size_t e, int) {
                    for (std::size_t k = b; k < e; ++k) {
                      const Eigen::Vector3d x = points.col(static_cast<Eigen::Index>(k));
                      const double u = std::clamp(out.u[k], base.front_u(), base.back_u());
                      const double v = std::clamp(out.v[k], base.front_v(), base.back_v());
                      if (projector) {
                        const SurfaceProjection f = projector->project(x, u, v);
                        out.u[k] = f.u;
                        out.v[k] = f.v;
                        out.distance[k] = f.distance;
                      } else {
                        out.distance[k] = (x - base.point(u, v)).norm();
                      }
                    }
                  });
  return out;
}

}  // namespace polarform
