#include "ek/solver/relax_request.hpp"

#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "ek/solver/trace.hpp"

namespace ek {

RelaxOptions RelaxRequest::options() const {
  RelaxOptions opt;
  opt.tolerance = tol;
  opt.max_iterations = max_iter;
  opt.material.radius = radius;
  opt.material.young = young;
  opt.material.poisson = poisson;
  opt.contact_stiffness = contact_stiffness;
  opt.newton.verbose = verbose;
  opt.newton.record_trace = trace;
  opt = with_method(opt, method);
  if (coarse_levels) opt.coarse_levels = *coarse_levels;
  if (factorization == "cholmod") opt.newton.cholesky.mode = CholeskyMode::Simplicial;
  else if (factorization != "block")
    throw InputError("--factorization must be block or cholmod, not '" + factorization + "'");
  opt.contact_continuation = continuation;
  if (release && !planar) throw InputError("--release needs --planar H");
  opt.link = link;
  opt.full_model = full_model;
  opt.smallest_eigenvalue = eigen;
  opt.stop_at_critical_point = stop_at_saddle;
  if (planar) {
    SlabOptions s;
    s.half_thickness = *planar;
    opt.slab = s;
    opt.release_slab = release;
  }
  opt.validate();
  return opt;
}

std::string topology_change(const RelaxResult& r) {
  if (r.topology_preserved()) return "";
  if (!r.link_type)
    return "the Alexander polynomial changed from " + r.alexander.to_string() + " to " + r.result_alexander.to_string();
  std::string changed;  // "a, b and c"
  const std::pair<bool, const char*> parts[] = {{!r.alexander_preserved, "a component's Alexander polynomial"},
                                                {!r.linking_preserved, "a linking number"},
                                                {!r.conway_preserved, "the Conway polynomial"}};
  int count = 0;
  for (const auto& [differs, what] : parts) count += differs;
  for (const auto& [differs, what] : parts) {
    if (!differs) continue;
    changed += changed.empty() ? "" : --count == 1 ? " and " : ", ";
    changed += what;
  }
  return changed + " of the link changed";
}

void write_trace_file(const std::string& path, const RelaxResult& r) {
  AtomicFile f(path);
  write_trace_csv(f.stream(), r.trace, r.phases);
  f.commit();
}

}  // namespace ek
