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
// first non-zero coefficient in that order. If every |c| < 2^50, there are
// fewer than 64 monomials and i < 17, then every later monomial is at most
// ε^(i+1) η^j (same j: i' >= i + 1; larger j: ε^i' η^j' <= η^(j+1) <= ε^(i+1) η^j
// because η = 2^-1074 <= 2^(-60 (i+1))), so the later terms sum to less than
// 64 · 2^50 · 2^-60 ε^i η^j = ε^i η^j / 16 <= |c_ij| ε^i η^j: the minor has the
// sign of c_ij. Degrees stay below 8 here (a minor with m <= 4 moved rows has
// degree at most m + 1: one lifted entry per Leibniz term), so an 8 x 8 array
// holds every monomial, and the check |c| < 2^50 runs on the result.
//
// ============================================================================
// A minor: Laplace along its moved rows
// ============================================================================
// Rows whose values all split with a = b = 0 are integer rows (constant
// polynomials); the others are moved. A minor of r kept rows, m of them
// moved (m <= 4, else 2: the caller's expansion stages decide), with the
// moved rows brought to the top (the permutation's sign), is by Laplace's
// expansion along those rows
//     Σ_S (-1)^(Σ S + m(m-1)/2) det(moved rows, columns S) · det(integer rows, columns not in S)
// over the m-subsets S of the kept columns (positions 0..r-1). The moved
// minors are expanded by Leibniz term by term into the accumulator; the
// integer minors of every column subset come from one pass of Laplace levels
// in int64 (the minor of the last t integer rows on a column set T, from the
// level t-1 minors of T minus one column), bottom row first. That pass cannot
// overflow when H = Π max(1, |row|_2) over the integer rows is below 2^62:
// every level-t minor and every partial sum of its expansion is at most the
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
#pragma once

#if !defined(__CUDA_ARCH__)

#include <cmath>
#include <cstdint>

namespace flipflop::pred::xp {

// v = n + a 2^-60 + b 2^-1074 exactly, within the bounds above; false otherwise
inline bool nl_split(double v, long long& n, long long& a, long long& b) {
  if (!(std::fabs(v) <= 0x1p26)) return false;  // (NaN too)
  const double nd = std::rint(v);
  const double r = v - nd;  // exact (Sterbenz; r = v where nd = 0)
  n = static_cast<long long>(nd);
  a = b = 0;
  if (r == 0.0) return true;
  const double s = r * 0x1p60;  // exact: a power of two, no overflow (|r| <= 1/2)
  if (std::fabs(s) <= 0x1p40 && s == std::trunc(s)) {
    a = static_cast<long long>(s);
    return true;
  }
  if (std::fabs(r) < 0x1p-1000) {
    const double t = r * 0x1p600 * 0x1p474;  // r 2^1074, exact: below 2^74
    if (std::fabs(t) <= 0x1p40 && t == std::trunc(t)) {
      b = static_cast<long long>(t);
      return true;
    }
  }
  return false;
}

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
  NlEntry a[K][K];
  long long n[K][K];  // the constant coefficients (integer rows: the whole entry)
  double norm2[K];    // Σ_j n_ij^2 over all K columns, binary64
  bool moved[K];
};

// Λ (w non-null: lifted, column K-2 the heights, K-1 the 1-column) of K
// points as polynomials; false where a value does not split, a lifted
// coefficient overflows, or more than four rows are moved.
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
    for (int j = 0; j < ncoord; ++j) {
      NlEntry& e = L.a[i][j];
      e.n = 0;
      e.add(0, n[j]);
      e.add(8, a[j]);
      e.add(1, b[j]);
    }
    if (w) {
      long long nw, aw, bw;
      if (!nl_split(w[i], nw, aw, bw)) return false;
      mv = mv || aw != 0 || bw != 0;
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
    }
    NlEntry& one = L.a[i][K - 1];
    one.n = 0;
    one.add(0, 1);
    L.moved[i] = mv;
    moved += mv;
    double s = 0.0;
    for (int j = 0; j < K; ++j) {
      const NlEntry& e = L.a[i][j];
      L.n[i][j] = (e.n > 0 && e.e[0] == 0) ? e.c[0] : 0;
      const double v = static_cast<double>(L.n[i][j]);
      s += v * v;
    }
    L.norm2[i] = s;
  }
  return moved <= 4;
}

// The permutations of 0..m-1 (m <= 4) with their signs, for Leibniz.
struct NlPerms {
  int count;
  int p[24][4];
  int sign[24];
};
struct NlPermTable {
  NlPerms t[5];
};
inline const NlPerms& nl_perms(int m) {
  static const NlPermTable table = [] {
    NlPermTable all;
    NlPerms* t = all.t;
    for (int m = 0; m <= 4; ++m) {
      int v[4] = {0, 1, 2, 3};
      t[m].count = 0;
      // every arrangement of 0..m-1 in lexicographic order, parity by inversions
      auto rec = [&](auto&& self, int k, unsigned used) -> void {
        if (k == m) {
          int inv = 0;
          for (int x = 0; x < m; ++x)
            for (int y = x + 1; y < m; ++y) inv += v[x] > v[y];
          NlPerms& P = t[m];
          for (int x = 0; x < 4; ++x) P.p[P.count][x] = x < m ? v[x] : 0;
          P.sign[P.count] = (inv & 1) ? -1 : 1;
          ++P.count;
          return;
        }
        for (int c = 0; c < m; ++c)
          if (!(used & (1u << c))) {
            v[k] = c;
            self(self, k + 1, used | (1u << c));
          }
      };
      rec(rec, 0, 0u);
    }
    return all;
  }();
  return table.t[m];
}

inline int nl_popcount(unsigned x) {  // x < 256 (no popcnt instruction assumed)
  static constexpr unsigned char kBits[16] = {0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};
  return kBits[x & 15u] + kBits[(x >> 4) & 15u];
}

// The minors of one call: L, and the integer rows' Laplace levels for the
// last few row sets asked (the perturbation's search asks for many minors on
// the same rows: first every column dropped with row 0).
template <int K>
class NlMinors {
 public:
  NearLattice<K> L;

  // The sign of the minor on rows kr and columns kc (bit masks, equal
  // popcounts), or 2 where this stage cannot decide it (more than four
  // moved rows kept, an overflow, a coefficient of 2^50 or more).
  int sign(unsigned kr, unsigned kc) {
    int mv[4], m = 0, rowpar = 0, r = 0;
    unsigned ints = 0;
    for (int i = 0; i < K; ++i) {
      if (!(kr & (1u << i))) continue;
      if (L.moved[i]) {
        if (m == 4) return 2;
        rowpar += r - m;  // moved to the top past the integer rows above it
        mv[m++] = i;
      } else {
        ints |= 1u << i;
      }
      ++r;
    }
    if (r == 0) return 1;
    const long long* M = levels(ints);
    if (!M) return 2;
    if (m == 0) return (M[kc] > 0) - (M[kc] < 0);
    // the accumulator: monomial e = 8 i + j, `used` its touched slots
    long long acc[64];
    std::uint64_t used = 0;
    bool over = false;
    auto add = [&](int e, long long v) {
      if (!(used >> e & 1u)) {
        used |= std::uint64_t{1} << e;
        acc[e] = v;
      } else {
        over |= __builtin_add_overflow(acc[e], v, &acc[e]);
      }
    };
    if (m == 1) {
      // one moved row: Σ_c (-1)^(pos c) L[mv][c] M(kc \ c)
      const NlEntry* row = L.a[mv[0]];
      long long sg = (rowpar & 1) ? -1 : 1;
      for (unsigned U = kc; U; U &= U - 1, sg = -sg) {
        const unsigned bit = U & (0u - U);
        const long long D = M[kc & ~bit];
        if (D == 0) continue;
        const NlEntry& e = row[__builtin_ctz(bit)];
        const long long d = sg * D;
        for (int t = 0; t < e.n; ++t) {
          long long v;
          over |= __builtin_mul_overflow(d, e.c[t], &v);
          add(e.e[t], v);
        }
      }
    } else if (m == 2) {
      // two moved rows: Σ_{c0 < c1} (-1)^(pos c0 + pos c1 + 1) M(kc \ {c0, c1})
      // (L[mv0][c0] L[mv1][c1] - L[mv0][c1] L[mv1][c0])
      const NlEntry* r0 = L.a[mv[0]];
      const NlEntry* r1 = L.a[mv[1]];
      int p0 = 0;
      for (unsigned U0 = kc; U0; U0 &= U0 - 1, ++p0) {
        const unsigned b0 = U0 & (0u - U0);
        const int c0 = __builtin_ctz(b0);
        int p1 = p0 + 1;
        for (unsigned U1 = U0 & (U0 - 1); U1; U1 &= U1 - 1, ++p1) {
          const unsigned b1 = U1 & (0u - U1);
          const int c1 = __builtin_ctz(b1);
          const long long D = M[kc & ~(b0 | b1)];
          if (D == 0) continue;
          const long long d = ((p0 + p1 + 1 + rowpar) & 1) ? -D : D;
          for (int flip = 0; flip < 2; ++flip) {
            const NlEntry& x = flip ? r0[c1] : r0[c0];
            const NlEntry& y = flip ? r1[c0] : r1[c1];
            const long long dd = flip ? -d : d;
            for (int s = 0; s < x.n; ++s) {
              long long u;
              over |= __builtin_mul_overflow(dd, x.c[s], &u);
              for (int t = 0; t < y.n; ++t) {
                long long v;
                over |= __builtin_mul_overflow(u, y.c[t], &v);
                add(x.e[s] + y.e[t], v);
              }
            }
          }
        }
      }
    } else {
      const NlPerms& P = nl_perms(m);
      // every m-subset S of kc, Laplace along the moved rows
      for (unsigned S = kc; S; S = (S - 1) & kc) {
        if (nl_popcount(S) != m) continue;
        const long long D = M[kc & ~S];
        if (D == 0) continue;
        int sc[4], k = 0, possum = 0;
        for (unsigned U = S; U; U &= U - 1) {
          const unsigned bit = U & (0u - U);
          possum += nl_popcount(kc & (bit - 1u));
          sc[k++] = __builtin_ctz(bit);
        }
        const long long base = ((possum + m * (m - 1) / 2 + rowpar) & 1) ? -D : D;
        for (int x = 0; x < P.count; ++x) {
          const NlEntry* ent[4];
          bool zero = false;
          for (int y = 0; y < m; ++y) {
            ent[y] = &L.a[mv[y]][sc[P.p[x][y]]];
            zero = zero || ent[y]->n == 0;
          }
          if (zero) continue;
          // every choice of one monomial per entry (at most 2 · 2 · 2 · 6)
          int idx[4] = {0, 0, 0, 0};
          while (true) {
            long long v = P.sign[x] < 0 ? -base : base;
            int e = 0;
            for (int y = 0; y < m; ++y) {
              over |= __builtin_mul_overflow(v, ent[y]->c[idx[y]], &v);
              e += ent[y]->e[idx[y]];
            }
            add(e, v);
            int y = m - 1;
            while (y >= 0 && ++idx[y] == ent[y]->n) idx[y--] = 0;
            if (y < 0) break;
          }
        }
      }
    }
    if (over) return 2;
    // the leading coefficient: η's degree first (e mod 8), then ε's
    int lead = -1;
    for (std::uint64_t u = used; u; u &= u - 1) {
      const int e = __builtin_ctzll(u);
      const long long v = acc[e];
      if (!(v > -0x1p50 && v < 0x1p50)) return 2;
      if (v != 0 && (lead < 0 || (e & 7) < (lead & 7) || ((e & 7) == (lead & 7) && e < lead))) lead = e;
    }
    if (lead >= 0) return acc[lead] > 0 ? 1 : -1;
    return 0;
  }

 private:
  static constexpr int kSlots = 4;
  unsigned key_[kSlots] = {~0u, ~0u, ~0u, ~0u};
  int next_ = 0;
  long long M_[kSlots][1u << K];

  // The minors of the integer rows `ints` (increasing) on every column set
  // of at most that many columns: M[T], T a mask of Λ's columns, the rows'
  // Laplace levels from the bottom row up; null where H >= 2^62 (above).
  const long long* levels(unsigned ints) {
    // A cached set whose bottom rows are `ints` serves too: the levels of
    // the last t rows are the same (the search drops rows from the top:
    // row 0 first).
    const unsigned low = ints & (0u - ints);
    for (int s = 0; s < kSlots; ++s)
      if (key_[s] != ~0u && !(ints & ~key_[s]) && (key_[s] & ~ints) < (low ? low : ~0u)) return M_[s];
    int ir[K], q = 0;
    double h = 1.0;
    for (int i = 0; i < K; ++i)
      if (ints & (1u << i)) {
        ir[q++] = i;
        h *= L.norm2[i] > 1.0 ? L.norm2[i] : 1.0;
      }
    if (!(h * (1.0 + 0x1p-30) < 0x1p124)) return nullptr;
    const int slot = next_;
    next_ = (next_ + 1) % kSlots;
    key_[slot] = ints;
    long long* M = M_[slot];
    M[0] = 1;
    for (unsigned T = 1; T < (1u << K); ++T) {
      const int t = nl_popcount(T);
      if (t > q) continue;
      const long long* row = L.n[ir[q - t]];
      long long sum = 0, sg = 1;
      for (unsigned U = T; U; U &= U - 1, sg = -sg) {
        const unsigned bit = U & (0u - U);
        sum += sg * row[__builtin_ctz(bit)] * M[T & ~bit];
      }
      M[T] = sum;
    }
    return M;
  }
};

}  // namespace flipflop::pred::xp

#endif  // !__CUDA_ARCH__
