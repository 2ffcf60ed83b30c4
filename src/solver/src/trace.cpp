#include "ek/solver/trace.hpp"

#include <algorithm>
#include <iomanip>

namespace ek {
namespace {

std::vector<std::string> part_names(const std::vector<IterationRecord>& trace) {
  std::vector<std::string> names;
  for (const IterationRecord& r : trace)
    for (const EnergyPart& p : r.parts)
      if (std::find(names.begin(), names.end(), p.name) == names.end()) names.push_back(p.name);
  return names;
}

double part_value(const IterationRecord& r, const std::string& name) {
  for (const EnergyPart& p : r.parts)
    if (p.name == name) return p.value;
  return 0.0;
}

}  // namespace

void write_trace_csv(std::ostream& out, const std::vector<IterationRecord>& trace,
                     const std::vector<std::string>& phase_names) {
  const std::vector<std::string> parts = part_names(trace);
  out << "phase,phase_name,iteration,kind,energy";
  for (const std::string& p : parts) out << ",energy_" << p;
  out << ",gradient_norm,hessian,shift,factorizations,failed_factorizations,pattern_changed,max_step,step,"
         "line_search_trials,active_pairs,seconds\n";
  out << std::setprecision(17);
  for (const IterationRecord& r : trace) {
    const bool named = r.phase >= 0 && r.phase < static_cast<int>(phase_names.size());
    out << r.phase << ',' << (named ? phase_names[static_cast<size_t>(r.phase)] : std::string()) << ','
        << r.iteration << ',' << to_string(r.kind) << ',' << r.energy;
    for (const std::string& p : parts) out << ',' << part_value(r, p);
    out << ',' << r.gradient_norm << ',' << (r.exact ? "exact" : "projected") << ',' << r.shift << ','
        << r.factorizations << ',' << r.failed_factorizations << ',' << (r.pattern_changed ? 1 : 0) << ','
        << r.max_step << ',' << r.step << ',' << r.line_search_trials << ',' << r.active_pairs << ','
        << r.seconds << '\n';
  }
}

}  // namespace ek

namespace ek {

void TraceSummary::add(const TraceSummary& o) {
  iterations += o.iterations;
  for (size_t k = 0; k < by_excess.size(); ++k) by_excess[k] += o.by_excess[k];
  full_steps += o.full_steps;
  short_steps += o.short_steps;
  collision_limited += o.collision_limited;
  exact_iterations += o.exact_iterations;
  factorizations += o.factorizations;
  failed_factorizations += o.failed_factorizations;
  pattern_changes += o.pattern_changes;
  seconds += o.seconds;
  seconds_exact += o.seconds_exact;
}

TraceSummary summarize_trace(const std::vector<IterationRecord>& trace) {
  TraceSummary s;
  std::vector<double> end_energy;  // per phase: the energy of its last record
  for (const IterationRecord& r : trace) {
    if (r.phase >= static_cast<int>(end_energy.size())) end_energy.resize(static_cast<size_t>(r.phase) + 1, 0.0);
    end_energy[static_cast<size_t>(r.phase)] = r.energy;
  }
  for (const IterationRecord& r : trace) {
    s.factorizations += r.factorizations;
    s.failed_factorizations += r.failed_factorizations;
    s.pattern_changes += r.pattern_changed ? 1 : 0;
    s.seconds += r.seconds;
    if (r.exact) s.seconds_exact += r.seconds;
    if (r.kind == IterationKind::Final) continue;
    ++s.iterations;
    const double excess = r.energy - end_energy[static_cast<size_t>(r.phase)];
    const size_t band = excess > 1e-1 ? 0 : excess > 1e-2 ? 1 : excess > 1e-3 ? 2 : excess > 1e-4 ? 3 : 4;
    ++s.by_excess[band];
    if (r.step >= 1.0) ++s.full_steps;
    if (r.step > 0.0 && r.step < 1.0 / 64.0) ++s.short_steps;
    if (r.max_step < 1.0) ++s.collision_limited;
    if (r.exact) ++s.exact_iterations;
  }
  return s;
}

}  // namespace ek
