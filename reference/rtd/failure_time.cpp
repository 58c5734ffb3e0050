// failure_time.cpp — exact Orient^{d+1}(S_F, t) data and failure-time
// comparison (thesis §9.2.2). See failure_time.hpp for the math.
#include "reference/rtd/failure_time.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace flipflop::ref {

using pred::exact::Dyadic;

PerturbationOrder PerturbationOrder::identity(std::size_t n) {
  PerturbationOrder o;
  o.order.resize(n);
  std::iota(o.order.begin(), o.order.end(), Index{0});
  o.rank = o.order;
  return o;
}

PerturbationOrder PerturbationOrder::from_order(std::vector<Index> order) {
  PerturbationOrder o;
  const std::size_t n = order.size();
  o.rank.assign(n, static_cast<Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    if (order[i] >= n || o.rank[order[i]] != n)
      throw std::invalid_argument("perturbation order is not a permutation of the points");
    o.rank[order[i]] = static_cast<Index>(i);
  }
  o.order = std::move(order);
  return o;
}

MovingModel::MovingModel(const PointSet& ps, const std::vector<double>& w,
                         const std::vector<double>& u)
    : ps_(&ps), d_(ps.dim), n_(ps.size()), w_(w), u_(u) {
  if (d_ < 1 || d_ > 5)
    throw std::invalid_argument("moving model: dimension " + std::to_string(d_) +
                                " is not supported (1..5)");
  if (w.size() != n_ || u.size() != n_)
    throw std::invalid_argument("moving model: " + std::to_string(n_) + " points but " +
                                std::to_string(w.size()) + " weights W and " +
                                std::to_string(u.size()) + " weights U");
  for (std::size_t p = 0; p < n_; ++p)
    if (!std::isfinite(w[p]) || !std::isfinite(u[p]))
      throw std::invalid_argument("moving model: weight of point " + std::to_string(p) +
                                  " is not finite");
  made_.assign(n_, 0);
}

const MovingModel::Exact& MovingModel::exact(std::size_t p) const {
  if (made_[p] != 0) return exact_[made_[p] - 1];
  Exact& e = exact_.emplace_back();
  made_[p] = static_cast<std::uint32_t>(exact_.size());
  Dyadic sq;  // |p|^2, exactly
  for (int j = 0; j < d_; ++j) {
    Dyadic& x = e.x[static_cast<std::size_t>(j)];
    x = pred::exact::to_dyadic(ps_->point(p)[j]);
    sq = pred::exact::add(sq, pred::exact::mul(x, x));
  }
  e.h0 = pred::exact::sub(sq, pred::exact::to_dyadic(w_[p]));
  e.h1 = pred::exact::sub(sq, pred::exact::to_dyadic(u_[p]));
  return e;
}

namespace {

// Sets dst = x.m · 2^(x.e - emin) (x.e >= emin for non-zero x).
void scaled(mpz_class& dst, const Dyadic& x, long emin) {
  if (x.m == 0) {
    dst = 0;
    return;
  }
  mpz_mul_2exp(dst.get_mpz_t(), x.m.get_mpz_t(), static_cast<mp_bitcnt_t>(x.e - emin));
}

long min_exponent(const Dyadic* const* xs, int k) {
  long e = 0;
  bool any = false;
  for (int i = 0; i < k; ++i) {
    if (xs[i]->m == 0) continue;
    e = any ? std::min(e, xs[i]->e) : xs[i]->e;
    any = true;
  }
  return e;
}

// The subsets of {0..k-1} (bit masks) of each size, for the Laplace
// expansions below: subsets_by_size(k)[size].
const std::vector<std::vector<unsigned>>& subsets_by_size(int k) {
  static const auto tables = [] {
    std::vector<std::vector<std::vector<unsigned>>> t(kMaxRidgeRows + 1);
    for (int kk = 1; kk <= kMaxRidgeRows; ++kk) {
      t[static_cast<std::size_t>(kk)].resize(static_cast<std::size_t>(kk) + 1);
      for (unsigned s = 1; s < (1u << kk); ++s)
        t[static_cast<std::size_t>(kk)][static_cast<std::size_t>(__builtin_popcount(s))].push_back(s);
    }
    return t;
  }();
  return tables[static_cast<std::size_t>(k)];
}

// All k maximal minors of a k x (k-1) integer matrix X (row-major): minor[r]
// = det of X without row r, rows kept in order. Laplace expansion over row
// subsets: D[S] = det(rows S, columns 0..|S|-1), expanded along its last
// column, D[S] = Σ_{i in S} (-1)^(pos_S(i) + |S| - 1) X[i][|S|-1] D[S \ i].
void maximal_minors(int k, const mpz_class* X, mpz_class* minor) {
  thread_local std::vector<mpz_class> D(1u << kMaxRidgeRows);
  const unsigned full = (1u << k) - 1u;
  const int cols = k - 1;
  for (int i = 0; i < k; ++i) D[1u << i] = X[i * cols + 0];
  const auto& by_size = subsets_by_size(k);
  for (int size = 2; size <= k - 1; ++size) {
    for (unsigned s : by_size[static_cast<std::size_t>(size)]) {
      mpz_class& dst = D[s];
      dst = 0;
      int pos = 0;
      for (int i = 0; i < k; ++i) {
        if (!(s & (1u << i))) continue;
        const mpz_class& x = X[i * cols + (size - 1)];
        const mpz_class& sub = D[s & ~(1u << i)];
        if (((pos + size - 1) & 1) == 0)
          mpz_addmul(dst.get_mpz_t(), x.get_mpz_t(), sub.get_mpz_t());
        else
          mpz_submul(dst.get_mpz_t(), x.get_mpz_t(), sub.get_mpz_t());
        ++pos;
      }
    }
  }
  for (int r = 0; r < k; ++r) minor[r] = D[full & ~(1u << r)];
}

// ≈ num/den from exact integers (den != 0), relative error below 2^-50.
double ratio(const mpz_class& num, const mpz_class& den) {
  if (num == 0) return 0.0;
  long en = 0, ed = 0;
  const double mn = mpz_get_d_2exp(&en, num.get_mpz_t());  // |mn| in [0.5, 1)
  const double md = mpz_get_d_2exp(&ed, den.get_mpz_t());
  return std::ldexp(mn / md, static_cast<int>(std::clamp(en - ed, -100000L, 100000L)));
}

// The filtered stage: the same Laplace expansion in ErrDouble on coordinates
// translated to the last row (y_r = x_r - x_last; the minors of [x | 1] and
// the lifted determinant are translation invariant, and the lifted column
// may be replaced by |y_r|^2 - (v_r - v_last), which differs from |x_r|^2 - v_r
// by a linear function of the rows: lambda_filter.hpp). False when the sign of
// Orient^d(C1) is not certain.
bool filter_motion(const MovingModel& mm, RidgeMotion& m) {
  using pred::ErrDouble;
  const int d = m.d, k = d + 2, cols = k - 1;
  const PointSet& ps = mm.points();
  const Index last = m.pts[static_cast<std::size_t>(k - 1)];
  ErrDouble X[kMaxRidgeRows * (kMaxRidgeRows - 1)];
  ErrDouble h0[kMaxRidgeRows], h1[kMaxRidgeRows];
  for (int r = 0; r < k; ++r) {
    const Index p = m.pts[static_cast<std::size_t>(r)];
    ErrDouble sq;
    for (int j = 0; j < d; ++j) {
      const ErrDouble y = ErrDouble(ps.point(p)[j]) - ErrDouble(ps.point(last)[j]);
      X[r * cols + j] = y;
      sq = sq + y * y;
    }
    X[r * cols + d] = ErrDouble(1.0);
    h0[r] = sq - (ErrDouble(mm.w()[p]) - ErrDouble(mm.w()[last]));
    h1[r] = sq - (ErrDouble(mm.u()[p]) - ErrDouble(mm.u()[last]));
  }
  // maximal minors by the subset expansion of maximal_minors()
  ErrDouble D[1u << kMaxRidgeRows];
  const unsigned full = (1u << k) - 1u;
  for (int i = 0; i < k; ++i) D[1u << i] = X[i * cols + 0];
  const auto& by_size = subsets_by_size(k);
  for (int size = 2; size <= k - 1; ++size)
    for (unsigned s : by_size[static_cast<std::size_t>(size)]) {
      ErrDouble acc;
      int pos = 0;
      for (int i = 0; i < k; ++i) {
        if (!(s & (1u << i))) continue;
        const ErrDouble term = X[i * cols + (size - 1)] * D[s & ~(1u << i)];
        acc = ((pos + size - 1) & 1) == 0 ? acc + term : acc - term;
        ++pos;
      }
      D[s] = acc;
    }
  const int orient_c1 = pred::sign_if_certain(D[full & ~(1u << (k - 1))]);
  if (orient_c1 == 0 || (!m.point_event && pred::sign_if_certain(D[full & ~(1u << (k - 2))]) == 0))
    return false;
  ErrDouble a0, a1, dd;
  for (int r = 0; r < k; ++r) {
    const ErrDouble minor = D[full & ~(1u << r)];
    const bool negate = (orient_c1 > 0) == (((r + d) & 1) == 0);
    const ErrDouble c = negate ? -minor : minor;
    const Index p = m.pts[static_cast<std::size_t>(r)];
    a0 = a0 + c * h0[r];
    a1 = a1 + c * h1[r];
    dd = dd + c * (ErrDouble(mm.w()[p]) - ErrDouble(mm.u()[p]));  // h(1) - h(0) = w - u
  }
  m.fa0 = a0;
  m.fa1 = a1;
  m.fd = dd;
  m.t_rel = std::numeric_limits<double>::infinity();
  if (pred::sign_if_certain(dd) != 0) {
    m.t_approx = -a0.v / dd.v;
    if (a0.v != 0 && a0.e < 0.25 * std::fabs(a0.v) && dd.e < 0.25 * std::fabs(dd.v) &&
        std::isfinite(m.t_approx) && std::fabs(m.t_approx) > 1e-280)
      // |t~ - t| <= |t| (2 εA + 2 εD) + rounding, for relative errors εA, εD <= 1/4
      m.t_rel = 2.0 * (a0.e / std::fabs(a0.v) + dd.e / std::fabs(dd.v)) + 0x1p-50;
  }
  return true;
}

}  // namespace

int RidgeMotion::direction() const {
  if (dir != 2) return dir;
  if (filtered)
    if (int s = pred::sign_if_certain(fd)) return dir = s;
  ensure_exact();
  return dir = sgn(mpz_class(a1 - a0));
}

void RidgeMotion::ensure_exact() const {
  if (exact) return;
  const MovingModel& mm = *model;
  const int k = d + 2;
  // The integer matrix [X | 1] of S_F, each coordinate column scaled.
  thread_local std::vector<mpz_class> X(kMaxRidgeRows * (kMaxRidgeRows - 1));
  const int cols = k - 1;  // d coordinates and the 1-column
  const Dyadic* col[kMaxRidgeRows];
  for (int j = 0; j < d; ++j) {
    for (int r = 0; r < k; ++r) col[r] = &mm.coord(pts[static_cast<std::size_t>(r)], j);
    const long e = min_exponent(col, k);
    for (int r = 0; r < k; ++r) scaled(X[static_cast<std::size_t>(r * cols + j)], *col[r], e);
  }
  for (int r = 0; r < k; ++r) X[static_cast<std::size_t>(r * cols + d)] = 1;

  std::array<mpz_class, kMaxRidgeRows> minor;
  maximal_minors(k, X.data(), minor.data());
  const int orient_c1 = sgn(minor[static_cast<std::size_t>(d) + 1]);
  if (orient_c1 == 0 || (!point_event && sgn(minor[static_cast<std::size_t>(d)]) == 0))
    throw std::invalid_argument(
        "instant flip: a simplex has zero volume (points not in general position in R^" +
        std::to_string(d) + ", thesis §9.2)");
  // c(r) = -sign(M_{d+1}) (-1)^(r+d) M_r  (scaled by 2^-E)
  for (int r = 0; r < k; ++r) {
    const bool negate = (orient_c1 > 0) == (((r + d) & 1) == 0);
    c[static_cast<std::size_t>(r)] = negate ? mpz_class(-minor[static_cast<std::size_t>(r)])
                                            : minor[static_cast<std::size_t>(r)];
  }

  // Heights at t = 0 and 1, scaled together by 2^-H.
  const Dyadic* hs[2 * kMaxRidgeRows];
  for (int r = 0; r < k; ++r) {
    hs[r] = &mm.height(pts[static_cast<std::size_t>(r)], 0);
    hs[k + r] = &mm.height(pts[static_cast<std::size_t>(r)], 1);
  }
  hexp = min_exponent(hs, 2 * k);
  thread_local mpz_class eta;
  a0 = 0;
  a1 = 0;
  for (int r = 0; r < k; ++r) {
    const mpz_class& cr = c[static_cast<std::size_t>(r)];
    scaled(eta, *hs[r], hexp);
    mpz_addmul(a0.get_mpz_t(), cr.get_mpz_t(), eta.get_mpz_t());
    scaled(eta, *hs[k + r], hexp);
    mpz_addmul(a1.get_mpz_t(), cr.get_mpz_t(), eta.get_mpz_t());
  }
  exact = true;
}

namespace {
RidgeMotion make_motion(const MovingModel& mm, const Index* ridge, Index a, Index b, bool point_event);
}  // namespace

RidgeMotion ridge_motion(const MovingModel& mm, const Index* ridge, Index a, Index b) {
  return make_motion(mm, ridge, a, b, false);
}

RidgeMotion point_motion(const MovingModel& mm, const Index* simplex, Index p) {
  return make_motion(mm, simplex, simplex[mm.dim()], p, true);
}

namespace {
RidgeMotion make_motion(const MovingModel& mm, const Index* ridge, Index a, Index b, bool point_event) {
  const int d = mm.dim();
  const int k = d + 2;
  RidgeMotion m;
  m.d = d;
  m.point_event = point_event;
  m.model = &mm;
  for (int i = 0; i < d; ++i) m.pts[static_cast<std::size_t>(i)] = ridge[i];
  m.pts[static_cast<std::size_t>(d)] = a;
  m.pts[static_cast<std::size_t>(d) + 1] = b;
  for (int r = 0; r < k; ++r)
    if (m.pts[static_cast<std::size_t>(r)] >= mm.size())
      throw std::invalid_argument("ridge_motion: point index out of range");
  m.filtered = filter_motion(mm, m);
  if (!m.filtered) {
    m.ensure_exact();
    m.t_rel = std::numeric_limits<double>::infinity();
    if (m.direction() != 0) {
      // from exact integers: relative error below 2^-50 (ratio())
      m.t_approx = ratio(m.a0, mpz_class(m.a0 - m.a1));
      if (std::isfinite(m.t_approx) && std::fabs(m.t_approx) > 1e-280) m.t_rel = 0x1p-48;
    }
  }
  return m;
}
}  // namespace

int coefficient_sign(const RidgeMotion& m, int r) {
  m.ensure_exact();
  return sgn(m.c[static_cast<std::size_t>(r)]);
}

int exact_sign(const RidgeMotion& m, int t) {
  if (m.filtered)
    if (int s = pred::sign_if_certain(t == 0 ? m.fa0 : m.fa1)) return s;
  m.ensure_exact();
  return sgn(t == 0 ? m.a0 : m.a1);
}

namespace {
// The sign of Σ_p c_F(p) ε_p: the first non-zero coefficient in order.
int perturbation_sign(const RidgeMotion& m, const PerturbationOrder& order);
}  // namespace

int perturbed_sign(const RidgeMotion& m, int t, const PerturbationOrder& order) {
  if (int s = exact_sign(m, t)) return s;
  return perturbation_sign(m, order);
}

int perturbed_sign_at(const RidgeMotion& m, double t, const PerturbationOrder& order) {
  if (m.filtered)
    if (int s = pred::sign_if_certain(m.fa0 + pred::ErrDouble(t) * m.fd)) return s;
  m.ensure_exact();
  // A + t·D with t = tm·2^te, multiplied by a positive power of two.
  const pred::exact::Dyadic td = pred::exact::to_dyadic(t);
  mpz_class a = m.a0, dt = (m.a1 - m.a0) * td.m;
  if (td.e < 0)
    mpz_mul_2exp(a.get_mpz_t(), a.get_mpz_t(), static_cast<mp_bitcnt_t>(-td.e));
  else
    mpz_mul_2exp(dt.get_mpz_t(), dt.get_mpz_t(), static_cast<mp_bitcnt_t>(td.e));
  if (int s = sgn(mpz_class(a + dt))) return s;
  return perturbation_sign(m, order);
}

namespace {
int perturbation_sign(const RidgeMotion& m, const PerturbationOrder& order) {
  // the first non-zero coefficient in perturbation order decides (Eq. 9.4)
  m.ensure_exact();
  int best = -1;
  Index best_rank = 0;
  for (int r = 0; r < m.rows(); ++r) {
    if (sgn(m.c[static_cast<std::size_t>(r)]) == 0) continue;
    const Index rk = order.rank[m.pts[static_cast<std::size_t>(r)]];
    if (best < 0 || rk < best_rank) {
      best = r;
      best_rank = rk;
    }
  }
  return best < 0 ? 0 : sgn(m.c[static_cast<std::size_t>(best)]);
}
}  // namespace

bool fails_in_unit_interval(const RidgeMotion& m, const PerturbationOrder& order) {
  return m.direction() < 0 && perturbed_sign(m, 1, order) < 0 &&
         perturbed_sign(m, 0, order) > 0;
}

namespace {

// Coefficient sign of ε_p in A*_G B*_F - A*_F B*_G: c_G(p) D_F - c_F(p) D_G,
// with the 2^H factors restored (the common 2^(E_F + E_G) dropped).
int eps_coefficient(const mpz_class* cf, const mpz_class& df, long hf, const mpz_class* cg,
                    const mpz_class& dg, long hg) {
  mpz_class x = 0, y = 0;  // x = c_G D_F 2^H_F, y = c_F D_G 2^H_G
  if (cg) x = *cg * df;
  if (cf) y = *cf * dg;
  const long lo = std::min(hf, hg);
  if (hf > lo) mpz_mul_2exp(x.get_mpz_t(), x.get_mpz_t(), static_cast<mp_bitcnt_t>(hf - lo));
  if (hg > lo) mpz_mul_2exp(y.get_mpz_t(), y.get_mpz_t(), static_cast<mp_bitcnt_t>(hg - lo));
  return cmp(x, y) > 0 ? 1 : (cmp(x, y) < 0 ? -1 : 0);
}

}  // namespace

int compare_times(const RidgeMotion& f, const RidgeMotion& g, const PerturbationOrder& order) {
  const int df = f.direction(), dg = g.direction();
  if (df == 0 || dg == 0) throw std::logic_error("compare_times: a ridge has no changing time");
  const int orient = df * dg;  // sign of D_F D_G
  // Filter: t ∈ [t~ - |t~| r, t~ + |t~| r] for both (r = t_rel, proven).
  // First: disjoint intervals are different times, so the two sets below
  // cannot be the same (the heap's comparisons mostly end here, without the
  // two sorts).
  if (std::isfinite(f.t_rel) && std::isfinite(g.t_rel)) {
    const double tf = f.t_approx, tg = g.t_approx;
    const double rf = std::fabs(tf) * f.t_rel * (1 + 0x1p-40), rg = std::fabs(tg) * g.t_rel * (1 + 0x1p-40);
    if (tf + rf < tg - rg) return -1;
    if (tg + rg < tf - rf) return 1;
  }
  // The same d+2 points: the same (perturbed) determinant up to sign, the
  // same flip — equal times (§9.2.2), decided combinatorially.
  {
    std::array<Index, kMaxRidgeRows> sf = f.pts, sg = g.pts;
    for (int i = 1; i < f.rows(); ++i)  // insertion sorts of d+2 <= 7 entries
      for (int j = i; j > 0 && sf[static_cast<std::size_t>(j)] < sf[static_cast<std::size_t>(j) - 1]; --j)
        std::swap(sf[static_cast<std::size_t>(j)], sf[static_cast<std::size_t>(j) - 1]);
    for (int i = 1; i < g.rows(); ++i)
      for (int j = i; j > 0 && sg[static_cast<std::size_t>(j)] < sg[static_cast<std::size_t>(j) - 1]; --j)
        std::swap(sg[static_cast<std::size_t>(j)], sg[static_cast<std::size_t>(j) - 1]);
    if (sf == sg) return 0;
  }
  f.ensure_exact();
  g.ensure_exact();
  // Main term A_G B_F - A_F B_G (each ridge's positive scale factors out).
  const mpz_class main = g.a0 * f.a1 - f.a0 * g.a1;
  if (int s = sgn(main)) return s * orient;
  // Perturbing values in order of dominance over S_F ∪ S_G.
  const mpz_class dF = f.a1 - f.a0, dG = g.a1 - g.a0;
  struct Entry {
    Index rank;
    const mpz_class* cf;
    const mpz_class* cg;
  };
  Entry e[2 * kMaxRidgeRows];
  int ne = 0;
  for (int r = 0; r < f.rows(); ++r)
    e[ne++] = {order.rank[f.pts[static_cast<std::size_t>(r)]], &f.c[static_cast<std::size_t>(r)],
               nullptr};
  for (int r = 0; r < g.rows(); ++r) {
    const Index rk = order.rank[g.pts[static_cast<std::size_t>(r)]];
    int i = 0;
    while (i < ne && e[i].rank != rk) ++i;
    if (i < ne)
      e[i].cg = &g.c[static_cast<std::size_t>(r)];
    else
      e[ne++] = {rk, nullptr, &g.c[static_cast<std::size_t>(r)]};
  }
  for (int i = 1; i < ne; ++i)  // insertion sort by rank (at most 2(d+2) entries)
    for (int j = i; j > 0 && e[j].rank < e[j - 1].rank; --j) std::swap(e[j], e[j - 1]);
  for (int i = 0; i < ne; ++i)
    if (int s = eps_coefficient(e[i].cf, dF, f.hexp, e[i].cg, dG, g.hexp)) return s * orient;
  return 0;
}

std::vector<RidgeLink> interior_ridges(int d, std::size_t n,
                                       const std::vector<std::vector<Index>>& simplices,
                                       std::size_t* boundary) {
  if (d < 1 || d > 5) throw std::invalid_argument("interior_ridges: dimension must be 1..5");
  const auto k = static_cast<std::size_t>(d) + 1;
  struct Facet {
    std::array<Index, 5> v;
    Index opposite;
  };
  std::vector<Facet> facets;
  facets.reserve(simplices.size() * k);
  for (const std::vector<Index>& simplex : simplices) {
    if (simplex.size() != k)
      throw std::invalid_argument("simplex list: a simplex has " + std::to_string(simplex.size()) +
                                  " vertices, expected " + std::to_string(k));
    std::array<Index, 6> sv{};
    for (std::size_t i = 0; i < k; ++i) {
      if (simplex[i] >= n)
        throw std::invalid_argument("simplex list: index " + std::to_string(simplex[i]) +
                                    " out of range");
      sv[i] = simplex[i];
    }
    std::sort(sv.begin(), sv.begin() + static_cast<std::ptrdiff_t>(k));
    for (std::size_t i = 0; i + 1 < k; ++i)
      if (sv[i] == sv[i + 1]) throw std::invalid_argument("simplex list: a simplex repeats a vertex");
    for (std::size_t drop = 0; drop < k; ++drop) {
      Facet f{};
      std::size_t j = 0;
      for (std::size_t i = 0; i < k; ++i)
        if (i != drop) f.v[j++] = sv[i];
      f.opposite = sv[drop];
      facets.push_back(f);
    }
  }
  std::sort(facets.begin(), facets.end(),
            [](const Facet& x, const Facet& y) { return x.v < y.v || (x.v == y.v && x.opposite < y.opposite); });
  std::vector<RidgeLink> out;
  std::size_t nb = 0;
  for (std::size_t i = 0; i < facets.size();) {
    std::size_t j = i;
    while (j < facets.size() && facets[j].v == facets[i].v) ++j;
    if (j - i == 1) {
      ++nb;
    } else if (j - i == 2) {
      out.push_back({facets[i].v, facets[i].opposite, facets[i + 1].opposite});
    } else {
      throw std::invalid_argument("simplex list: a ridge belongs to more than two simplices");
    }
    i = j;
  }
  if (boundary) *boundary = nb;
  return out;
}

double approximate_time(const RidgeMotion& m) {
  if (m.direction() == 0) throw std::logic_error("approximate_time: parallel ridge");
  if (std::isfinite(m.t_rel)) return m.t_approx;
  m.ensure_exact();
  return ratio(m.a0, mpz_class(m.a0 - m.a1));
}

mpq_class exact_time(const RidgeMotion& m) {
  if (m.direction() == 0) throw std::logic_error("exact_time: parallel ridge");
  m.ensure_exact();
  mpq_class t(m.a0, mpz_class(m.a0 - m.a1));
  t.canonicalize();
  return t;
}

}  // namespace flipflop::ref
