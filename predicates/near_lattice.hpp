// near_lattice.hpp — the exact stage for lattices with a few points moved by
// some ulp: det Λ and every minor the perturbation asks for, as polynomials
// in two infinitesimal units with small integer coefficients. Host only
// (xp::lambda_exact calls it outside __CUDA_ARCH__); no heap, no GMP.
//
// ============================================================================
// The split and why the leading coefficient decides
// ============================================================================
// Every value v of the call (coordinate or weight) is split exactly as
//     v = n + a ε + b η,   ε = 2^-60,  η = 2^-1074,
// n = rint(v) an integer with |n| <= 2^26, and the remainder r = v - n (exact:
// Sterbenz, |r| <= 1/2) either a multiple a of ε with |a| <= 2^40 (a point of
// a lattice moved by some ulp: ulp(v) >= 2^-53 for |v| >= 1/2) or, below
// 2^-1000, a multiple b of η with |b| <= 2^40 (a moved 0 is a subnormal).
// A value that does not split sends the call to the expansion stages.
//
// Λ's entries are then polynomials in (ε, η) with integer coefficients: a
// coordinate n + a ε + b η; the 1-column 1; a lifted entry |x|^2 - w =
//   Σ n_j^2 - n_w + ε (2 Σ n_j a_j - a_w) + η (2 Σ n_j b_j - b_w)
//   + ε^2 Σ a_j^2 + ε η 2 Σ a_j b_j + η^2 Σ b_j^2,
// and any minor is the polynomial Σ c_ij ε^i η^j evaluated at those units:
// an identity, no approximation. Lemma (the leading coefficient decides):
// order the monomials by η's degree j, then by ε's degree i; let c_ij be the
// first non-zero coefficient in that order. If i < 17 and the other
// coefficients' absolute values sum to S < 2^60, then every later monomial
// is at most ε^(i+1) η^j (same j: i' >= i + 1; larger j: ε^i' η^j' <=
// η^(j+1) <= ε^(i+1) η^j because η = 2^-1074 <= 2^(-60 (i+1))), so the later
// terms sum to at most S 2^-60 ε^i η^j < ε^i η^j <= |c_ij| ε^i η^j: the minor
// has the sign of c_ij. Degrees stay below 8 here (a minor with m <= 6 moved
// rows has degree at most m + 1: one lifted entry per term), so the
// exponents e = 8 i + j fit a 64-slot accumulator, and the check (S below
// 2^58 in binary64, a margin for its rounding) runs on the result (NlAcc).
//
// ============================================================================
// A minor: Laplace along its moved rows
// ============================================================================
// Rows whose values all split with a = b = 0 are integer rows (constant
// polynomials); the others are moved. A minor of r kept rows, m of them
// moved (m <= 6, else 2: the caller's expansion stages decide), with the
// moved rows brought to the top (the permutation's sign), is by Laplace's
// expansion along those rows
//     Σ_S (-1)^(Σ S + m(m-1)/2) det(moved rows, columns S) · det(integer rows, columns not in S)
// over the m-subsets S of the kept columns (positions 0..r-1). Both kinds of
// minors come from Laplace levels: the minor of the last t rows on a column
// set T from the minors of the last t - 1 rows on T less one column, bottom
// row first, so that the minors of a row set also serve the row sets the
// perturbation's search reaches by dropping top rows. The integer rows'
// levels are computed whole when a row set is first asked (int64, a few
// hundred products); the moved rows' minors (polynomials) on demand and
// memoised per column set, and only where the integer cofactor is not 0
// (most of them are 0 on a lattice). The integer minors are int64 and cannot
// overflow when H = Π max(1, |row|_2) over the integer rows is below 2^62:
// every level-t minor and the sum of any of its expansion's terms is at most the
// product of its rows' norms (|Σ_c a_c M(T\c)| <= |a|_2 (Σ_U M(U)^2)^(1/2) =
// |a|_2 det(B B^T)^(1/2) <= |a|_2 Π |b|_2 by Cauchy-Binet and Hadamard, B the
// lower rows). The check runs in binary64 on the rows' squared norms with a
// relative margin of 2^-30. The products and sums of the moved part are
// checked (__builtin_*_overflow): on overflow, 2.
//
// Measured (callgrind, `flipflop rtd --dim 5 --threads 1`, the 3^5 grid with
// 20 % of its points moved by 2 ulp, a moved 0 a subnormal): the XDbl
// expansion stages took 71,012 det_translated calls at 43,000 instructions
// and 33,092 sos_expansions calls at 121,000, 65 % of the run's 10.9 G.
// This stage's first form (stop 81) expanded three or four moved rows by
// Leibniz, monomial choice by choice, for every minor, and refused five
// moved rows and any coefficient of 2^50: the 112,873 seven-row calls of
// that run, replayed alone (near_lattice_sign, best of 3), took 5.13 us a
// call with 2,567 refusals; with the moved rows' memoised levels, the
// integer levels on tables and the bound on the later coefficients' sum,
// 3.70 us with 438 refusals (docs/performance/predicates.md, stop 82).
#pragma once

#if !defined(__CUDA_ARCH__)

#include <cmath>
#include <cstdint>

namespace flipflop::pred::xp {

// v = n + a 2^-60 + b 2^-1074 exactly, within the bounds above; false otherwise
// (rint and trunc without a library call: adding and subtracting 1.5 2^52
// rounds a binary64 of magnitude below 2^51 to the nearest integer, exactly,
// in the default rounding mode that the predicates assume throughout)
inline bool nl_split(double v, long long& n, long long& a, long long& b) {
  if (!(std::fabs(v) <= 0x1p26)) return false;  // (NaN too)
  constexpr double kRound = 0x1.8p52;
  const double nd = (v + kRound) - kRound;  // rint(v)
  const double r = v - nd;  // exact (Sterbenz; r = v where nd = 0)
  n = static_cast<long long>(nd);
  a = b = 0;
  if (r == 0.0) return true;
  const double s = r * 0x1p60;  // exact: a power of two, no overflow (|r| <= 1/2)
  if (std::fabs(s) <= 0x1p40 && (s + kRound) - kRound == s) {
    a = static_cast<long long>(s);
    return true;
  }
  if (std::fabs(r) < 0x1p-1000) {
    const double t = r * 0x1p600 * 0x1p474;  // r 2^1074, exact: below 2^74
    if (std::fabs(t) <= 0x1p40 && (t + kRound) - kRound == t) {
      b = static_cast<long long>(t);
      return true;
    }
  }
  return false;
}

// At most this many moved rows in a minor (degree m + 1 <= 7 below).
inline constexpr int kNlMaxMoved = 6;

// A polynomial entry: up to six monomials ε^i η^j, e = 8 i + j, non-zero c.
struct NlEntry {
  int n = 0;
  int e[6];
  long long c[6];
  void add(int ei, long long ci) {
    if (ci != 0) {
      e[n] = ei;
      c[n] = ci;
      ++n;
    }
  }
};

template <int K>
struct NearLattice {
  NlEntry a[K][K];    // the moved rows' entries (integer rows: not filled)
  long long n[K][K];  // the constant coefficients (integer rows: the whole entry)
  double norm2[K];    // Σ_j n_ij^2 over all K columns, binary64
  bool moved[K];
};

// Λ (w non-null: lifted, column K-2 the heights, K-1 the 1-column) of K
// points as polynomials; false where a value does not split, a lifted
// coefficient overflows, or more than kNlMaxMoved rows are moved. Only the
// moved rows' polynomial entries (a) are filled: the minors read an integer
// row through its constants (n) alone, so its entries are not built (on the
// moved 3^5 grid most rows of a call are integer rows).
template <int K>
inline bool nl_build(const double* const* p, const double* w, NearLattice<K>& L) {
  const int ncoord = w ? K - 2 : K - 1;
  int moved = 0;
  for (int i = 0; i < K; ++i) {
    long long n[K], a[K], b[K];
    bool mv = false;
    for (int j = 0; j < ncoord; ++j) {
      if (!nl_split(p[i][j], n[j], a[j], b[j])) return false;
      mv = mv || a[j] != 0 || b[j] != 0;
    }
    long long nw = 0, aw = 0, bw = 0;
    if (w) {
      if (!nl_split(w[i], nw, aw, bw)) return false;
      mv = mv || aw != 0 || bw != 0;
    }
    if (mv && ++moved > kNlMaxMoved) return false;
    long long* ni = L.n[i];
    for (int j = 0; j < ncoord; ++j) ni[j] = n[j];
    ni[K - 1] = 1;
    if (!mv) {
      // an integer row: the lifted entry is c0 alone, below 8 2^52 + 2^26
      // (no overflow)
      if (w) {
        long long c0 = -nw;
        for (int j = 0; j < ncoord; ++j) c0 += n[j] * n[j];
        ni[K - 2] = c0;
      }
    } else {
      for (int j = 0; j < ncoord; ++j) {
        NlEntry& e = L.a[i][j];
        e.n = 0;
        e.add(0, n[j]);
        e.add(8, a[j]);
        e.add(1, b[j]);
      }
      if (w) {
        // c0 = Σ n^2 - n_w, cε = 2 Σ n a - a_w, cη = 2 Σ n b - b_w, cεε = Σ a^2,
        // cεη = 2 Σ a b, cηη = Σ b^2 (checked: |n| <= 2^26, |a|, |b| <= 2^40)
        long long c0 = -nw, ce = -aw, ch = -bw, cee = 0, ceh = 0, chh = 0;
        bool over = false;
        for (int j = 0; j < ncoord; ++j) {
          long long t;
          over |= __builtin_mul_overflow(n[j], n[j], &t) || __builtin_add_overflow(c0, t, &c0);
          over |= __builtin_mul_overflow(2 * n[j], a[j], &t) || __builtin_add_overflow(ce, t, &ce);
          over |= __builtin_mul_overflow(2 * n[j], b[j], &t) || __builtin_add_overflow(ch, t, &ch);
          over |= __builtin_mul_overflow(a[j], a[j], &t) || __builtin_add_overflow(cee, t, &cee);
          over |= __builtin_mul_overflow(a[j], b[j], &t) || __builtin_mul_overflow(t, 2LL, &t) ||
                  __builtin_add_overflow(ceh, t, &ceh);
          over |= __builtin_mul_overflow(b[j], b[j], &t) || __builtin_add_overflow(chh, t, &chh);
        }
        if (over) return false;
        NlEntry& e = L.a[i][K - 2];
        e.n = 0;
        e.add(0, c0);
        e.add(8, ce);
        e.add(1, ch);
        e.add(16, cee);
        e.add(9, ceh);
        e.add(2, chh);
        ni[K - 2] = c0;
      }
      NlEntry& one = L.a[i][K - 1];
      one.n = 0;
      one.add(0, 1);
    }
    L.moved[i] = mv;
    double s = 0.0;
    for (int j = 0; j < K; ++j) {
      const double v = static_cast<double>(ni[j]);
      s += v * v;
    }
    L.norm2[i] = s;
  }
  return true;
}

inline int nl_popcount(unsigned x) {  // x < 256 (no popcnt instruction assumed)
  static constexpr unsigned char kBits[16] = {0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};
  return kBits[x & 15u] + kBits[(x >> 4) & 15u];
}

// The column masks of K columns ordered by popcount: mask[start[t] ..
// start[t + 1] - 1] are those of t columns, increasing.
template <int K>
struct NlMasks {
  unsigned mask[1u << K];
  int start[K + 2];
  // mask k's columns, increasing, and the mask less each of them
  unsigned char col[1u << K][K];
  unsigned char sub[1u << K][K];
  constexpr NlMasks() : mask{}, start{}, col{}, sub{} {
    int k = 0;
    for (int t = 0; t <= K; ++t) {
      start[t] = k;
      for (unsigned T = 0; T < (1u << K); ++T) {
        int c = 0;
        for (unsigned U = T; U; U &= U - 1) ++c;
        if (c != t) continue;
        int u = 0;
        for (int j = 0; j < K; ++j)
          if (T & (1u << j)) {
            col[k][u] = static_cast<unsigned char>(j);
            sub[k][u++] = static_cast<unsigned char>(T & ~(1u << j));
          }
        mask[k++] = T;
      }
    }
    start[K + 1] = k;
  }
};
template <int K>
inline constexpr NlMasks<K> kNlMasks{};

// A minor of moved rows as a sparse polynomial: at most 36 monomials, since a
// minor of t <= 6 rows has total degree at most t + 1 <= 7 (one lifted
// entry per term) and there are 36 monomials ε^i η^j with i + j <= 7; the
// exponent e = 8 i + j then stays below 64.
struct NlPoly {
  int n;
  unsigned char e[36];
  long long c[36];
};

// A dense accumulator over the exponents e = 8 i + j < 64, `used` its
// touched slots, `over` set on any int64 overflow.
struct NlAcc {
  std::uint64_t used = 0;
  bool over = false;
  long long c[64];
  void add(int e, long long v) {
    if (!(used >> e & 1u)) {
      used |= std::uint64_t{1} << e;
      c[e] = v;
    } else {
      over |= __builtin_add_overflow(c[e], v, &c[e]);
    }
  }
  // += d x
  template <class Poly>
  void add_scaled(const Poly& x, long long d) {
    for (int t = 0; t < x.n; ++t) {
      long long v;
      over |= __builtin_mul_overflow(d, x.c[t], &v);
      add(x.e[t], v);
    }
  }
  // += ± x p
  void add_product(const NlEntry& x, const NlPoly& p, bool negate) {
    for (int s = 0; s < x.n; ++s) {
      long long xs = x.c[s];
      if (negate) over |= __builtin_sub_overflow(0LL, xs, &xs);  // (-x) p = -(x p): negated once per monomial
      const int es = x.e[s];
      for (int t = 0; t < p.n; ++t) {
        long long v;
        over |= __builtin_mul_overflow(xs, p.c[t], &v);
        add(es + p.e[t], v);
      }
    }
  }
  // the non-zero monomials, in increasing e; false on overflow
  bool to_poly(NlPoly& p) const {
    p.n = 0;
    if (over) return false;
    for (std::uint64_t u = used; u; u &= u - 1) {
      const int e = __builtin_ctzll(u);
      if (c[e] == 0) continue;
      if (p.n == 36) return false;  // (cannot happen: the degree bound above)
      p.e[p.n] = static_cast<unsigned char>(e);
      p.c[p.n++] = c[e];
    }
    return true;
  }
  // The sign of the polynomial at the units (the lemma above, with the
  // bound on the later monomials' sum: below 2^58 in binary64, a margin
  // over the 2^60 it needs for 36 terms of int64), 0 for the zero
  // polynomial, 2 on overflow or beyond that bound.
  int lead_sign() const {
    if (over) return 2;
    // the leading monomial: η's degree first (e mod 8), then ε's
    int lead = -1;
    for (std::uint64_t u = used; u; u &= u - 1) {
      const int e = __builtin_ctzll(u);
      if (c[e] != 0 && (lead < 0 || (e & 7) < (lead & 7) || ((e & 7) == (lead & 7) && e < lead))) lead = e;
    }
    if (lead < 0) return 0;
    double later = 0.0;
    for (std::uint64_t u = used & ~(std::uint64_t{1} << lead); u; u &= u - 1)
      later += std::fabs(static_cast<double>(c[__builtin_ctzll(u)]));
    if (!(later < 0x1p58)) return 2;
    return c[lead] > 0 ? 1 : -1;
  }
};

// The minors of one call: L, the integer rows' Laplace levels for the last
// few row sets asked, and the moved rows' Laplace levels as polynomials,
// both computed on demand and kept (the perturbation's search asks for many
// minors on the same rows: first every column dropped with row 0).
template <int K>
class NlMinors {
 public:
  NearLattice<K> L;

  // The sign of the minor on rows kr and columns kc (bit masks, equal
  // popcounts), or 2 where this stage cannot decide it (more than six
  // moved rows kept, an overflow, the lemma's bound).
  //
  // With the moved rows brought to the top (rowpar: the permutation's
  // parity), Laplace's expansion along them is
  //     Σ_S (-1)^(Σ pos S + m(m-1)/2) P(S) M(kc \ S)
  // over the m-subsets S of kc (pos: a column's position in kc), with P(S)
  // the moved rows' minor on S (a polynomial, moved_minor) and M the
  // integer rows' minor (int64, int_slot). Terms with M = 0 cost nothing:
  // their P is not computed (on lattices most of the integer minors are 0).
  int sign(unsigned kr, unsigned kc) {
    NlAcc acc;
    if (!poly(kr, kc, acc)) return 2;
    return acc.lead_sign();
  }

  // The same minor as a polynomial, added into acc (empty on entry); false
  // where this stage cannot compute it (more than six moved rows kept, an
  // overflow, an integer minor out of int64's reach). acc.over may still be
  // set (an overflow while summing): its reader checks it.
  bool poly(unsigned kr, unsigned kc, NlAcc& acc) {
    int mv[kNlMaxMoved], m = 0, rowpar = 0, r = 0;
    unsigned ints = 0, mset = 0;
    for (int i = 0; i < K; ++i) {
      if (!(kr & (1u << i))) continue;
      if (L.moved[i]) {
        if (m == kNlMaxMoved) return false;
        rowpar += r - m;  // moved to the top past the integer rows above it
        mv[m++] = i;
        mset |= 1u << i;
      } else {
        ints |= 1u << i;
      }
      ++r;
    }
    if (r == 0) {
      acc.add(0, 1);
      return true;
    }
    const int slot = int_slot(ints);
    if (slot < 0) return false;
    const long long* M = M_[slot];
    if (m == 0) {
      if (M[kc] != 0) acc.add(0, M[kc]);
      return true;
    }
    if (m == 1) {
      // one moved row: Σ_c (-1)^(pos c) L[mv][c] M(kc \ c)
      const NlEntry* row = L.a[mv[0]];
      long long sg = (rowpar & 1) ? -1 : 1;
      for (unsigned U = kc; U; U &= U - 1, sg = -sg) {
        const unsigned bit = U & (0u - U);
        const long long D = M[kc & ~bit];
        if (D != 0) acc.add_scaled(row[__builtin_ctz(bit)], sg * D);
      }
    } else {
      moved_rows(mv, m, mset);
      const NlMasks<K>& T = kNlMasks<K>;
      const int base = rowpar + m * (m - 1) / 2;
      for (int k = T.start[m]; k < T.start[m + 1]; ++k) {
        const unsigned S = T.mask[k];
        if (S & ~kc) continue;
        const long long D = M[kc & ~S];
        if (D == 0) continue;
        const NlPoly* p = moved_minor(S);
        if (!p) return false;
        int possum = base;
        for (unsigned U = S; U; U &= U - 1) possum += nl_popcount(kc & ((U & (0u - U)) - 1u));
        acc.add_scaled(*p, (possum & 1) ? -D : D);
      }
    }
    return true;
  }

 private:
  // the integer rows' minors: slots of row sets (key_), M_[s][T] for every
  // column set T of at most as many columns as the set has rows
  static constexpr int kSlots = 4;
  unsigned key_[kSlots] = {~0u, ~0u, ~0u, ~0u};
  int next_ = 0;
  long long M_[kSlots][1u << K];
  // the moved rows' minors: P_[T] of the last |T| rows pmv_[..pm_ - 1]
  // (pkey_ their mask, ~0u: none), phave_[T] 0 not computed, 1 computed,
  // 2 out of reach (an overflow)
  unsigned pkey_ = ~0u;
  int pmv_[kNlMaxMoved];
  int pm_ = 0;
  unsigned char phave_[1u << K];
  NlPoly P_[1u << K];

  // Is the set `sub` the last rows of the cached set `key` (the cached set
  // less some of its top rows)? Laplace levels built from the bottom row up
  // then serve: the minors of the last t rows are the same.
  static bool suffix_of(unsigned sub, unsigned key) {
    const unsigned low = sub & (0u - sub);
    return key != ~0u && !(sub & ~key) && (key & ~sub) < (low ? low : ~0u);
  }

  // The slot for the integer rows `ints`; -1 where H >= 2^62 (above). The
  // levels run on tables of each column set's columns and subsets (NlMasks),
  // even positions first: any subset of an expansion's terms is bounded like
  // the whole (the row with the other entries zeroed).
  int int_slot(unsigned ints) {
    for (int s = 0; s < kSlots; ++s)
      if (suffix_of(ints, key_[s])) return s;
    int ir[K], q = 0;
    double h = 1.0;
    for (int i = 0; i < K; ++i)
      if (ints & (1u << i)) {
        ir[q++] = i;
        h *= L.norm2[i] > 1.0 ? L.norm2[i] : 1.0;
      }
    if (!(h * (1.0 + 0x1p-30) < 0x1p124)) return -1;
    const int slot = next_;
    next_ = (next_ + 1) % kSlots;
    key_[slot] = ints;
    long long* M = M_[slot];
    M[0] = 1;
    for (int t = 1; t <= q; ++t) {
      const long long* row = L.n[ir[q - t]];
      switch (t) {  // the level's loops unrolled for its size (t <= K <= 8)
        case 1: int_level<1>(row, M); break;
        case 2: int_level<2>(row, M); break;
        case 3: int_level<3>(row, M); break;
        case 4: int_level<4>(row, M); break;
        case 5: int_level<5>(row, M); break;
        case 6: int_level<6>(row, M); break;
        case 7: int_level<7>(row, M); break;
        default: int_level<8>(row, M); break;
      }
    }
    return slot;
  }

  // One Laplace level: the minors of the last t rows on every t-column set,
  // from the level below (row: the new top row).
  template <int t>
  static void int_level(const long long* row, long long* M) {
    if constexpr (t <= K) {
      const NlMasks<K>& T = kNlMasks<K>;
      for (int k = T.start[t]; k < T.start[t + 1]; ++k) {
        const unsigned char* col = T.col[k];
        const unsigned char* sub = T.sub[k];
        long long sum = 0;
        for (int u = 0; u < t; u += 2) sum += row[col[u]] * M[sub[u]];
        for (int u = 1; u < t; u += 2) sum -= row[col[u]] * M[sub[u]];
        M[T.mask[k]] = sum;
      }
    }
  }

  // The moved rows of the next minors (increasing; mset their mask).
  void moved_rows(const int* mv, int m, unsigned mset) {
    if (suffix_of(mset, pkey_)) return;
    pkey_ = mset;
    pm_ = m;
    for (int i = 0; i < m; ++i) pmv_[i] = mv[i];
    for (unsigned T = 0; T < (1u << K); ++T) phave_[T] = 0;
  }

  // The polynomial minor of the last |C| moved rows on the columns C (null
  // on an overflow), by Laplace along the top one of them:
  //     P(C) = Σ_{c in C} (-1)^(pos c) L[row][c] P(C \ c).
  const NlPoly* moved_minor(unsigned C) {
    if (phave_[C] == 1) return &P_[C];
    if (phave_[C] == 2) return nullptr;
    const int t = nl_popcount(C);
    const NlEntry* row = L.a[pmv_[pm_ - t]];
    NlPoly& p = P_[C];
    bool ok = true;
    if (t == 1) {
      const NlEntry& x = row[__builtin_ctz(C)];
      p.n = x.n;
      for (int i = 0; i < x.n; ++i) {
        p.e[i] = static_cast<unsigned char>(x.e[i]);
        p.c[i] = x.c[i];
      }
    } else {
      NlAcc acc;
      bool negate = false;
      for (unsigned U = C; U && ok; U &= U - 1, negate = !negate) {
        const unsigned bit = U & (0u - U);
        const NlEntry& x = row[__builtin_ctz(bit)];
        if (x.n == 0) continue;
        const NlPoly* q = moved_minor(C & ~bit);
        if (!q) ok = false;
        else if (q->n != 0) acc.add_product(x, *q, negate);
      }
      ok = ok && acc.to_poly(p);
    }
    phave_[C] = ok ? 1 : 2;
    return ok ? &p : nullptr;
  }
};

}  // namespace flipflop::pred::xp

#endif  // !__CUDA_ARCH__
