// knots dataset (--max-crossings C [--min-crossings C0] [--stratified F] | --names A,B,...) -o DATASET.h5
//               [--jobs J] [--shard I/N] [--adaptive] ...
#include <sys/resource.h>

#include <iostream>
#include <thread>
#include <algorithm>
#include <sstream>

#include "commands.hpp"
#include "ek/core/commit.hpp"
#include "ek/core/paths.hpp"
#include "ek/dataset/ledger.hpp"
#include "ek/dataset/run.hpp"
#include "ek/knots/link_table.hpp"
#include "ek/knots/selection.hpp"
#include "explore_options.hpp"
#include "output.hpp"

namespace ek::cli {

namespace {

/// [s] user + system CPU time of this process (every thread).
double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  const auto s = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
  return s(u.ru_utime) + s(u.ru_stime);
}

/// The ledger of the finished data set, with this run's provenance: its
/// commit, command line, machine, wall and CPU time (of this invocation: a
/// resumed run's earlier parts are not in them, which `source` says).
void write_run_ledger(const DatasetRunOptions& ro, const DatasetRunSummary& s, int argc, char** argv,
                      const std::string& path, int curves) {
  LedgerProvenance p;
  p.cut = ro.explore.novelty_distance;
  p.curves_per_knot = curves;
  p.commit = source_commit();
  p.created = now_iso8601();
  p.source = "knots";
  for (int k = 1; k < argc; ++k) p.source += std::string(" ") + argv[k];
  if (s.knots_skipped + s.knots_resumed > 0)
    p.source += " (resumed: " + std::to_string(s.knots_skipped + s.knots_resumed) + " knots from an earlier invocation)";
  p.cores = static_cast<int>(std::thread::hardware_concurrency());
  p.jobs = ro.explore.jobs;
  p.wall_seconds = s.seconds;
  p.cpu_seconds = cpu_seconds();
  write_ledger(path, ledger_of_dataset(ro.output, p));
}

}  // namespace

int cmd_dataset(int argc, char** argv) {
  std::string out, names, shard = "1/1", ledger;
  int ledger_curves = LedgerProvenance{}.curves_per_knot;
  std::optional<int> max_crossings, min_crossings;
  std::optional<double> stratified;
  bool json = false;
  ExploreArgs a;
  ArgParser args("dataset",
                 "(--max-crossings C [--min-crossings C0] [--stratified F] | --names A,B,...) -o DATASET.h5 [--jobs J] "
                 "[--shard I/N] [--adaptive] [--json]");
  args.option("--max-crossings", &max_crossings, "every table knot with 3 .. C crossings");
  args.option("--min-crossings", &min_crossings, "with --max-crossings: only knots with at least C0 crossings (default 3)");
  args.option("--stratified", &stratified,
              "with --max-crossings: a deterministic stratified sample, the share F of every stratum "
              "(crossing number, alternating, bridge index) and every BB knot");
  args.option("--names", &names, "comma-separated knot names, or links of the link table (hopf, borromean, ...)");
  args.option("-o,--output", &out, "data-set file (HDF5); an existing one with the same parameters is resumed/extended");
  args.option("--shard", &shard, "I/N: only the knots k with k mod N = I - 1 (table order), for clusters");
  args.option("--ledger", &ledger,
              "also write the data set's ledger (its states at the novelty distance, runs, attributes, provenance) "
              "to this file once the data set is complete");
  args.option("--ledger-curves", &ledger_curves,
              "curves the ledger keeps per knot: those of its lowest-energy states (default 16)");
  add_explore_options(args, a);
  args.flag("--json", &json, "print a JSON summary");
  if (!args.parse(argc, argv)) return 0;
  if (out.empty()) throw InputError("missing -o DATASET.h5");
  if (ledger_curves < 0) throw InputError("--ledger-curves must be 0 or more");
  if (max_crossings.has_value() == !names.empty()) throw InputError("give exactly one of --max-crossings and --names");
  DatasetRunOptions ro;
  ro.output = out;
  std::tie(ro.shard_index, ro.shard_count) = parse_shard(shard);
  const auto& table = KnotTable::global();
  if ((min_crossings || stratified) && !max_crossings)
    throw InputError("--min-crossings and --stratified need --max-crossings");
  if (max_crossings) {
    if (*max_crossings < 3 || *max_crossings > 12) throw InputError("--max-crossings must be between 3 and 12");
    const int low = min_crossings.value_or(3);
    if (low < 3 || low > *max_crossings) throw InputError("--min-crossings must be between 3 and --max-crossings");
    if (stratified) {
      StratifiedSampleOptions so;
      so.min_crossings = low;
      so.max_crossings = *max_crossings;
      so.fraction = *stratified;
      ro.knots = stratified_sample(table, so);
    } else {
      for (const KnotRecord* k : table.up_to_crossings(*max_crossings))
        if (k->crossing_number >= low) ro.knots.push_back(k);
    }
  } else {
    std::stringstream ss(names);
    std::string n;
    std::vector<const KnotRecord*> list;
    std::vector<const LinkRecord*> links;
    while (std::getline(ss, n, ',')) {
      if (n.empty()) continue;
      if (!table.find(n) && find_link(n))
        links.push_back(find_link(n));
      else
        list.push_back(&table.at(n));
    }
    std::sort(list.begin(), list.end(), [](const KnotRecord* x, const KnotRecord* y) { return x->row < y->row; });
    list.erase(std::unique(list.begin(), list.end()), list.end());
    const auto link_row = [](const LinkRecord* l) { return l - link_table().data(); };
    std::sort(links.begin(), links.end(), [&](const LinkRecord* x, const LinkRecord* y) { return link_row(x) < link_row(y); });
    links.erase(std::unique(links.begin(), links.end()), links.end());
    ro.knots = list;
    ro.links = links;
    if (!links.empty()) prepare_for_links(a, !list.empty());
  }
  finish_explore_options(a);
  ro.explore = a.options;
  ro.progress = !a.quiet && !json;
  const DatasetRunSummary s = run_dataset(ro);
  if (!ledger.empty()) write_run_ledger(ro, s, argc, argv, ledger, ledger_curves);
  if (json) {
    Json j;
    j["output"] = out;
    j["knots"] = s.knots;
    j["knots_skipped"] = s.knots_skipped;
    j["knots_resumed"] = s.knots_resumed;
    j["runs"] = s.runs;
    j["equilibria"] = s.equilibria;
    j["seconds"] = number(s.seconds);
    j["equilibria_per_second"] = number(s.seconds > 0 ? s.equilibria / s.seconds : 0.0);
    print_json(j);
  } else {
    std::cout << "data set " << out << ": " << s.knots << " knots (" << s.knots_skipped << " already there, "
              << s.knots_resumed << " resumed), " << s.runs << " runs, " << s.equilibria << " stable equilibria in "
              << fmt(s.seconds, 4) << " s\n";
  }
  return 0;
}

}  // namespace ek::cli
