#include "src/fit/normal_equations.h"

#include <algorithm>
#include <string>
#include <vector>

#include "src/error.h"
#include "src/nurbs/basis.h"

namespace polarform {

namespace {

// Upper half of the banded A (entry (r, r') with r' >= r at offset (du, dv) of r' from r) and b, in
// full (unfolded) coefficient indices.
struct BandAccumulator {
  int nu, nv, pu, pv, width;
  std::vector<double> band, rhs;
  double gg = 0.0, wsum = 0.0;

  BandAccumulator(int nu_, int nv_, int pu_, int pv_)
      : nu(nu_), nv(nv_), pu(pu_), pv(pv_), width((2 * pu_ + 1) * (2 * pv_ + 1)),
        band(static_cast<std::size_t>(nu_) * nv_ * width, 0.0),
        rhs(static_cast<std::size_t>(nu_) * nv_, 0.0) {}

  void add(const BandAccumulator& o) {
    for (std::size_t i = 0; i < band.size(); ++i) band[i] += o.band[i];
    for (std::size_t i = 0; i < rhs.size(); ++i) rhs[i] += o.rhs[i];
    gg += o.gg;
    wsum += o.wsum;
  }
};

// Bae 2002, eq. (C.8a) (unconstrained part), one sample at a time.
void accumulate(const SplineAxis& U, const SplineAxis& V, const Samples& s, std::size_t begin,
                std::size_t end, BandAccumulator& acc, ProgressRange* progress) {
  const int pu = U.degree, pv = V.degree, nu = U.size(), nv = V.size();
  const int lu = pu + 1, lv = pv + 1, nloc = lu * lv, bw = 2 * pv + 1;
  const double u0 = U.front(), u1 = U.back(), v0 = V.front(), v1 = V.back();
  double Nu[kMaxDegree + 1], Nv[kMaxDegree + 1];
  std::vector<double> B(static_cast<std::size_t>(nloc));
  std::vector<int> row(static_cast<std::size_t>(nloc));
  for (std::size_t k = begin; k < end; ++k) {
    const Eigen::Index e = static_cast<Eigen::Index>(k);
    const double u = std::clamp(s.u[e], u0, u1), v = std::clamp(s.v[e], v0, v1);
    const int su = find_span(pu, U.knots, nu, u), sv = find_span(pv, V.knots, nv, v);
    basis_funs(su, u, pu, U.knots, Nu);
    basis_funs(sv, v, pv, V.knots, Nv);
    const double w = s.w(k), g = s.value[e];
    for (int iu = 0, a = 0; iu < lu; ++iu)
      for (int iv = 0; iv < lv; ++iv, ++a) {
        B[a] = Nu[iu] * Nv[iv];
        row[a] = (su - pu + iu) * nv + (sv - pv + iv);
        acc.rhs[row[a]] += w * g * B[a];
      }
    for (int iu = 0, a = 0; iu < lu; ++iu)
      for (int iv = 0; iv < lv; ++iv, ++a) {
        const double wb = w * B[a];
        double* base = acc.band.data() + static_cast<std::size_t>(row[a]) * acc.width + pu * bw + pv;
        for (int ju = iu; ju < lu; ++ju) {
          double* out = base + (ju - iu) * bw - iv;
          const double* Bj = B.data() + ju * lv;
          for (int jv = ju == iu ? iv : 0; jv < lv; ++jv) out[jv] += wb * Bj[jv];
        }
      }
    acc.gg += w * g * g;
    acc.wsum += w;
    if (progress && ((k - begin) & 0xFFFF) == 0) (*progress)(double(k - begin) / double(end - begin));
  }
}

}  // namespace

NormalEquations assemble_normal_equations(const SplineAxis& U, const SplineAxis& V,
                                          const CoefficientMap& map, const Samples& samples,
                                          int threads, ProgressRange progress) {
  const int nu = U.size(), nv = V.size(), pu = U.degree, pv = V.degree;
  if (map.size_u() != nu || map.size_v() != nv)
    throw InputError("normal equations: coefficient map " + std::to_string(map.size_u()) + " x " +
                     std::to_string(map.size_v()) + " for a " + std::to_string(nu) + " x " +
                     std::to_string(nv) + " net");
  const std::size_t n = samples.size();
  const int chunks = worker_count(threads, n);
  std::vector<BandAccumulator> acc(static_cast<std::size_t>(chunks), BandAccumulator(nu, nv, pu, pv));
  parallel_chunks(n, chunks, [&](std::size_t b, std::size_t e, int c) {
    accumulate(U, V, samples, b, e, acc[static_cast<std::size_t>(c)], c == 0 ? &progress : nullptr);
  });
  for (int c = 1; c < chunks; ++c) acc[0].add(acc[static_cast<std::size_t>(c)]);
  const BandAccumulator& A = acc[0];

  NormalEquations out;
  out.count = n;
  out.gg = A.gg;
  out.weight_sum = A.wsum;
  out.b = Eigen::VectorXd::Zero(map.unknowns());
  for (int r = 0; r < nu * nv; ++r) out.b[map[r]] += A.rhs[static_cast<std::size_t>(r)];
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(A.band.size());
  const int bw = 2 * pv + 1;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const int r = i * nv + j;
      const double* base = A.band.data() + static_cast<std::size_t>(r) * A.width;
      for (int du = 0; du <= pu && i + du < nu; ++du)
        for (int dv = -pv; dv <= pv; ++dv) {
          if ((du == 0 && dv < 0) || j + dv < 0 || j + dv >= nv) continue;
          const double x = base[(du + pu) * bw + dv + pv];
          if (x == 0.0) continue;
          const int ma = map[r], mb = map[(i + du) * nv + j + dv];
          t.emplace_back(ma, mb, x);
          if (du != 0 || dv != 0) t.emplace_back(mb, ma, x);
        }
    }
  out.A.resize(map.unknowns(), map.unknowns());
  out.A.setFromTriplets(t.begin(), t.end());
  progress(1.0);
  return out;
}

}  // namespace polarform
