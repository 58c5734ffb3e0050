// hull2.cpp — the multithreaded 2D hull: throw-away, then parallel Graham-
// sorting with chunked flip-pop (hull2.hpp).
#include "kernels_cpu/hull2/hull2.hpp"

#include <stdexcept>
#include <string>

#include "kernels_cpu/hull2/graham_insertion.hpp"
#include "kernels_cpu/hull2/graham_sorting.hpp"
#include "kernels_cpu/hull2/throw_away.hpp"
#include "kernels_cpu/parallel.hpp"
#include "predicates/predicates.hpp"

namespace flipflop::cpu {

namespace {

// the reference's names of the algorithms computed (ref::hull2_graham_sort,
// ref::hull2_graham_insert), so that rejected input gets the reference's message
constexpr const char* kSort = "hull2 graham-sort";
constexpr const char* kInsert = "hull2 graham-insert";

std::vector<Index> compute(const PointSet& ps, const Hull2Options& opt, ref::Hull2Stats& st, const char* who) {
  StageClock clock(opt.times);
  const hull2::ThrowAwayResult kept = hull2::throw_away(ps, opt.throw_away_from, opt.sample);  // 1.
  const std::vector<Index>& idx = kept.survivors;
  std::vector<hull2::Pt2> pts(idx.size());
  par_for(idx.size(), kChunk, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t k = lo; k < hi; ++k) pts[k] = {ps.point(idx[k])[0], ps.point(idx[k])[1], idx[k]};
  });
  hull2::ScanCounts counts;
  const pred::StaticFilter f = hull2::static_filter_of(pts);
  clock.mark("throw-away");
  hull2::InsertionCounts ins;
  std::vector<Index> cycle =
      who == kInsert ? hull2::graham_insertion(std::move(pts), f, opt.scan_chunk, counts, ins, &clock)
                     : hull2::graham_sorting(std::move(pts), f, opt.scan_chunk, counts, &clock);  // 2.
  // a strictly interior point exists only when the input spans the plane
  if (idx.size() == ps.size() && !ref::cycle_spans_plane(ps, cycle)) {
    ref::require_planar_input(ps, who);  // throws the reference's message
    throw std::logic_error(std::string(who) + ": collinear hull of an input that spans the plane");
  }
  st.input_vertices = ps.size();
  st.discarded_early = ps.size() - idx.size() + ins.dropped;
  st.insertions = ins.insertions;
  st.insertion_rounds = ins.rounds;
  st.polygon_vertices = who == kInsert ? ins.insertions + 2 : idx.size();  // what flip-pop starts from
  st.flips_2_1 = counts.flips_2_1;
  st.rounds = counts.passes;
  st.hull_vertices = cycle.size();
  std::vector<Index> out = ref::rotate_to_smallest(std::move(cycle));
  clock.mark("output");
  return out;
}

std::vector<Index> run(const PointSet& ps, const Hull2Options& opt, ref::Hull2Stats* stats, const char* who) {
  if (opt.threads < 0) throw std::invalid_argument("hull2 (cpu): the number of threads must be positive");
  if (ps.dim != 2 || ps.size() < 3) {
    ref::require_planar_input(ps, who);  // throws the reference's message
    throw std::invalid_argument(std::string(who) + ": at least 3 points in 2D are needed");
  }
  if (ps.size() >= kNone / 2) throw std::invalid_argument(std::string(who) + ": too many points for 32-bit indices");
  ref::Hull2Stats st;
  std::vector<Index> out;
  with_threads(opt.threads, [&] { out = compute(ps, opt, st, who); });
  if (stats) *stats = st;
  return out;
}

}  // namespace

std::vector<Index> hull2_graham_sort(const PointSet& ps, const Hull2Options& opt, ref::Hull2Stats* stats) {
  return run(ps, opt, stats, kSort);
}

std::vector<Index> hull2_graham_insert(const PointSet& ps, const Hull2Options& opt, ref::Hull2Stats* stats) {
  return run(ps, opt, stats, kInsert);
}

}  // namespace flipflop::cpu
