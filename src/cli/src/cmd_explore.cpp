// knots explore NAME [--samples K | --adaptive] -o DATASET.h5 [--jobs J] [--seed S] ...
// NAME is a knot of the table or a link of the link table.
#include <iostream>

#include "commands.hpp"
#include "ek/dataset/json.hpp"
#include "ek/dataset/run.hpp"
#include "ek/knots/link_table.hpp"
#include "explore_options.hpp"
#include "output.hpp"

namespace ek::cli {

int cmd_explore(int argc, char** argv) {
  std::string name, out;
  bool json = false;
  ExploreArgs a;
  ArgParser args("explore", "NAME [--samples K | --adaptive] -o DATASET.h5 [--jobs J] [--seed S] [--json]");
  args.positional("NAME", &name, "knot name as in the table, or a link of the link table (hopf, borromean, ...: docs/models.md)");
  args.option("-o,--output", &out, "data-set file (HDF5); created, or extended when it exists with the same parameters");
  add_explore_options(args, a);
  args.flag("--json", &json, "print a JSON summary");
  if (!args.parse(argc, argv)) return 0;
  if (out.empty()) throw InputError("missing -o DATASET.h5");
  const LinkRecord* link = KnotTable::global().find(name) ? nullptr : find_link(name);
  if (link) prepare_for_links(a, false);
  finish_explore_options(a);
  DatasetRunOptions ro;
  ro.explore = a.options;
  if (link)
    ro.links = {link};
  else
    ro.knots = {&KnotTable::global().at(name)};
  ro.output = out;
  ro.progress = !a.quiet && !json;
  const DatasetRunSummary s = run_dataset(ro);
  // what the knot's states leave unseen, at the cut of adaptive sampling (its δ)
  const auto entry = [&] { return DatasetReader(out).read(name); };
  if (json) {
    Json j;
    j["name"] = link ? link->name : ro.knots.front()->name;
    j["output"] = out;
    j["skipped"] = s.knots_skipped > 0;
    j["runs"] = s.runs;
    j["equilibria"] = s.equilibria;
    j["seconds"] = number(s.seconds);
    if (s.knots_skipped == 0 && s.equilibria > 0) j.update(entry_unseen_json(entry(), a.options.novelty_distance));
    print_json(j);
  } else if (s.knots_skipped > 0) {
    std::cout << name << " is already in " << out << "; nothing to do\n";
  } else {
    std::cout << "explored " << name << ": " << s.runs << " runs, " << s.equilibria << " stable equilibria in "
              << fmt(s.seconds, 4) << " s; wrote " << out << "\n";
    if (s.equilibria > 0) std::cout << entry_unseen_text(entry(), a.options.novelty_distance) << "\n";
  }
  return 0;
}

}  // namespace ek::cli
