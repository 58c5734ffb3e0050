// predicate_batch.hpp — batches of predicate calls for the device predicate
// path (kernels_cuda/predicates_device.hpp), built inside a RapidCheck property
// from the instance families of predicate_inputs.hpp, and their oracle: a
// sequential loop over stage::gmp / stage::gmp_sos (GMP only). Shared by
// proptests/predicates_device_test.cpp (thrust's OpenMP backend) and
// kernels_cuda/predicates_cuda_test.cpp (the CUDA backend).
//
// A batch: `instances` instances of one family (their points appended to one
// point array, one call each: its points in order), then `extra` calls whose
// points are drawn from the whole array (mixing instances), and a few calls that
// repeat a point (0 under SoS and exactly). Point ids are distinct over the
// whole array: small, strided, or near 2^64 - 1, in a random order.
#pragma once

#include <rapidcheck.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "kernels_cuda/predicates_device.hpp"
#include "predicates/predicates.hpp"
#include "proptests/support/predicate_inputs.hpp"

namespace flipflop::test {

// The shapes of predicates_device.hpp: k points, weighted (lifted) or not.
struct BatchShape {
  int k;
  bool lifted;
};

inline std::vector<BatchShape> device_shapes() {
  return {{3, false}, {4, false}, {4, true}, {5, true}, {5, false}, {3, true}};
}

// The named predicate of the shape (for the generators and the messages).
inline Spec batch_spec(BatchShape s) {
  if (!s.lifted) return s.k == 3 ? Spec{Kind::orient2d, 2} : s.k == 4 ? Spec{Kind::orient3d, 3}
                                                                      : Spec{Kind::orient_d, s.k - 1};
  return s.k == 4 ? Spec{Kind::power2d, 2} : s.k == 5 ? Spec{Kind::power3d, 3}
                                                      : Spec{Kind::power_d, s.k - 2};
}

inline std::string batch_name(BatchShape s) {
  return batch_spec(s).name() + " (k=" + std::to_string(s.k) + (s.lifted ? ", lifted)" : ")");
}

struct BatchInput {
  BatchShape shape{3, false};
  int dim = 0;
  std::vector<double> coords;   // point-major
  std::vector<double> weights;  // one per point (lifted shapes)
  std::vector<PointId> ids;     // one per point, distinct
  std::vector<std::uint32_t> calls;

  std::size_t n_points() const { return ids.size(); }
  std::size_t n_calls() const { return calls.size() / static_cast<std::size_t>(shape.k); }
  const double* point(std::uint32_t i) const { return coords.data() + static_cast<std::size_t>(i) * dim; }

  kernels::PredicateBatch view(bool sos, bool static_filter) const {
    kernels::PredicateBatch b;
    b.k = shape.k;
    b.dim = dim;
    b.coords = coords.data();
    b.weights = shape.lifted ? weights.data() : nullptr;
    b.ids = sos ? ids.data() : nullptr;
    b.n_points = n_points();
    b.calls = calls.data();
    b.n_calls = n_calls();
    b.static_filter = static_filter;
    return b;
  }
};

inline BatchInput gen_batch(BatchShape shape, Family fam, int max_instances, std::size_t min_extra,
                            std::size_t max_extra) {
  const Spec spec = batch_spec(shape);
  const int k = shape.k;
  BatchInput b;
  b.shape = shape;
  b.dim = spec.d;
  const int m = *rc::gen::inRange(1, max_instances + 1);
  for (int t = 0; t < m; ++t) {
    const Instance in = gen_instance(spec, fam);
    const auto base = static_cast<std::uint32_t>(b.n_points());
    b.coords.insert(b.coords.end(), in.x.begin(), in.x.end());
    b.weights.insert(b.weights.end(), in.w.begin(), in.w.end());
    b.ids.resize(b.ids.size() + static_cast<std::size_t>(k));
    for (int i = 0; i < k; ++i) b.calls.push_back(base + static_cast<std::uint32_t>(i));
  }
  std::mt19937_64 rng(*rc::gen::arbitrary<std::uint64_t>());
  // distinct ids in a random order
  const std::size_t n = b.n_points();
  std::vector<PointId> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  for (std::size_t i = n; i > 1; --i) std::swap(order[i - 1], order[rng() % i]);
  const IdStretch stretch = gen_id_stretch(n);
  for (std::size_t i = 0; i < n; ++i) b.ids[i] = stretch(order[i]);
  // calls mixing instances: k distinct points (a repeated point comes below)
  const std::size_t extra = min_extra + (max_extra > min_extra ? rng() % (max_extra - min_extra + 1) : 0);
  for (std::size_t c = 0; c < extra; ++c) {
    const std::size_t first = b.calls.size();
    for (int i = 0; i < k; ++i) {
      std::uint32_t q = 0;
      bool repeated = true;
      while (repeated) {
        q = static_cast<std::uint32_t>(rng() % n);
        repeated = false;
        for (std::size_t j = first; j < b.calls.size(); ++j) repeated = repeated || b.calls[j] == q;
      }
      b.calls.push_back(q);
    }
  }
  // a few calls repeating one of their points
  const std::size_t calls = b.n_calls();
  const std::size_t repeats = *rc::gen::inRange<std::size_t>(0, 4);
  for (std::size_t r = 0; r < repeats; ++r) {
    const std::size_t c = rng() % calls;
    const int i = static_cast<int>(rng() % static_cast<unsigned>(k));
    const int j = (i + 1 + static_cast<int>(rng() % static_cast<unsigned>(k - 1))) % k;
    b.calls[c * k + static_cast<std::size_t>(j)] = b.calls[c * k + static_cast<std::size_t>(i)];
  }
  return b;
}

// The oracle: one GMP predicate per call, sequentially.
inline std::vector<int> reference_signs(const BatchInput& b, bool sos) {
  const int k = b.shape.k;
  std::vector<int> out(b.n_calls());
  for (std::size_t c = 0; c < out.size(); ++c) {
    const double* p[8];
    double w[8];
    PointId id[8];
    for (int i = 0; i < k; ++i) {
      const std::uint32_t q = b.calls[c * static_cast<std::size_t>(k) + static_cast<std::size_t>(i)];
      p[i] = b.point(q);
      w[i] = b.shape.lifted ? b.weights[q] : 0.0;
      id[i] = b.ids[q];
    }
    const double* wp = b.shape.lifted ? w : nullptr;
    out[c] = sos ? pred::stage::gmp_sos(k, id, p, wp) : pred::stage::gmp(k, p, wp);
  }
  return out;
}

// Exact hexadecimal listing of the calls whose signs differ (at most `limit`).
inline std::string describe_differences(const BatchInput& b, const std::vector<int>& got,
                                        const std::vector<int>& expected, int limit = 3) {
  std::string out;
  char buf[96];
  for (std::size_t c = 0; c < expected.size() && limit > 0; ++c) {
    if (c < got.size() && got[c] == expected[c]) continue;
    --limit;
    std::snprintf(buf, sizeof buf, "call %zu: got %d, expected %d\n", c,
                  c < got.size() ? got[c] : 99, expected[c]);
    out += buf;
    for (int i = 0; i < b.shape.k; ++i) {
      const std::uint32_t q = b.calls[c * static_cast<std::size_t>(b.shape.k) + static_cast<std::size_t>(i)];
      out += "  id " + std::to_string(b.ids[q]) + " (";
      for (int j = 0; j < b.dim; ++j) {
        std::snprintf(buf, sizeof buf, "%a%s", b.point(q)[j], j + 1 < b.dim ? ", " : "");
        out += buf;
      }
      std::snprintf(buf, sizeof buf, ") w %a\n", b.shape.lifted ? b.weights[q] : 0.0);
      out += buf;
    }
  }
  return out;
}

// Totals over a property (both runs of check_batch; zeros: of the exact run).
struct BatchTally {
  std::size_t calls = 0, exact_stage = 0, zeros = 0;
};

// One batch through `backend` (a callable (const PredicateBatch&, PredicateStats*)
// -> std::vector<int>), exact and SoS, with or without the static filter: equal
// to the oracle entry for entry.
template <class Backend>
void check_batch(const BatchInput& b, Backend&& backend, BatchTally* tally) {
  for (bool sos : {false, true}) {
    const bool with_filter = *rc::gen::arbitrary<bool>();
    const std::vector<int> expected = reference_signs(b, sos);
    kernels::PredicateStats stats;
    const std::vector<int> got = backend(b.view(sos, with_filter), &stats);
    RC_LOG() << batch_name(b.shape) << (sos ? ", SoS" : ", exact") << (with_filter ? ", static filter" : "")
             << ", " << b.n_calls() << " calls over " << b.n_points() << " points\n"
             << describe_differences(b, got, expected);
    RC_ASSERT(got == expected);
    RC_ASSERT(stats.calls == b.n_calls());
    RC_ASSERT(stats.exact_stage <= stats.calls);
    if (tally) {
      tally->calls += stats.calls;
      tally->exact_stage += stats.exact_stage;
      if (!sos)
        for (int s : expected) tally->zeros += s == 0;
    }
  }
}

}  // namespace flipflop::test
