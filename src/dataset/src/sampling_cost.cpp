#include "ek/dataset/sampling_cost.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace ek {

KnotCost knot_cost(const KnotEntry& entry) {
  KnotCost c;
  c.name = entry.name;
  c.crossing_number = entry.crossing_number;
  c.samples = static_cast<int>(entry.runs.size());
  for (const RunRecord& r : entry.runs) c.run_seconds += r.seconds;
  return c;
}

double median_of(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 == 1 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

namespace {

double median(const std::vector<int>& v) { return median_of(std::vector<double>(v.begin(), v.end())); }

CrossingCost crossing_cost(int c, const std::vector<const KnotCost*>& knots) {
  CrossingCost out;
  out.crossing_number = c;
  out.knots = static_cast<int>(knots.size());
  std::vector<int> samples;
  double seconds = 0.0;
  long runs = 0;
  for (const KnotCost* k : knots) {
    samples.push_back(k->samples);
    seconds += k->run_seconds;
    runs += k->samples;
  }
  out.median_samples = median(samples);
  out.mean_samples = static_cast<double>(runs) / out.knots;
  out.seconds_per_run = runs > 0 ? seconds / runs : 0.0;
  return out;
}

}  // namespace

SamplingCost sampling_cost(const std::vector<KnotCost>& knots, int budget) {
  if (knots.empty()) throw std::invalid_argument("sampling_cost: no knots");
  if (budget < 1) throw std::invalid_argument("sampling_cost: budget must be at least 1");
  SamplingCost s;
  s.knots = static_cast<int>(knots.size());
  s.budget = budget;
  std::vector<int> samples;
  std::map<int, std::vector<const KnotCost*>> by_c;
  for (const KnotCost& k : knots) {
    samples.push_back(k.samples);
    s.samples += k.samples;
    s.run_seconds += k.run_seconds;
    s.max_samples = std::max(s.max_samples, k.samples);
    s.knots_at_budget += k.samples >= budget;
    by_c[k.crossing_number].push_back(&k);
  }
  s.median_samples = median(samples);
  s.saving_vs_budget = 1.0 - static_cast<double>(s.samples) / (static_cast<double>(s.knots) * budget);
  for (const auto& [c, ks] : by_c) s.by_crossing_number.push_back(crossing_cost(c, ks));
  return s;
}

namespace {

/// Weighted least-squares line y = a + b·c through (c, y) with weights w.
struct Line {
  double a = 0.0, b = 0.0;
  double at(double c) const { return a + b * c; }
};

Line fit(const std::vector<CrossingCost>& rows, double CrossingCost::*y) {
  double sw = 0, sc = 0, sy = 0, scc = 0, scy = 0;
  for (const CrossingCost& r : rows) {
    const double w = r.knots, c = r.crossing_number, v = r.*y;
    sw += w, sc += w * c, sy += w * v, scc += w * c * c, scy += w * c * v;
  }
  Line l;
  const double det = sw * scc - sc * sc;
  l.b = det > 0 ? (sw * scy - sc * sy) / det : 0.0;
  l.a = (sy - l.b * sc) / sw;
  return l;
}

}  // namespace

RunEstimate estimate_run(const SamplingCost& cost, const std::vector<int>& crossing_numbers) {
  std::map<int, const CrossingCost*> measured;
  for (const CrossingCost& r : cost.by_crossing_number) measured[r.crossing_number] = &r;
  if (measured.empty()) throw std::invalid_argument("estimate_run: no measured crossing numbers");
  const CrossingCost& last = *measured.rbegin()->second;
  const Line samples = fit(cost.by_crossing_number, &CrossingCost::mean_samples);
  const Line seconds = fit(cost.by_crossing_number, &CrossingCost::seconds_per_run);
  RunEstimate e;
  for (int c : crossing_numbers) {
    double n = 0, s = 0;
    if (const auto it = measured.find(c); it != measured.end()) {
      n = it->second->mean_samples, s = it->second->seconds_per_run;
    } else {
      if (measured.size() < 2)
        throw std::invalid_argument("estimate_run: crossing number " + std::to_string(c) +
                                    " is not measured and one crossing number gives no line");
      n = std::max(samples.at(c), last.mean_samples);
      s = std::max(seconds.at(c), last.seconds_per_run);
    }
    ++e.knots;
    e.samples += n;
    e.core_seconds += n * s;
  }
  return e;
}

}  // namespace ek
