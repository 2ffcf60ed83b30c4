// knots site (DATASET.h5 | LEDGER | FOLDER) -o DIR [--overwrite] [--cut C] [--link-cut C] [--title T] [--json]
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/core/errors.hpp"
#include "ek/site/site.hpp"
#include "output.hpp"

namespace ek::cli {

int cmd_site(int argc, char** argv) {
  std::string file, out, title;
  SiteOptions options;
  bool overwrite = false, json = false;
  ArgParser args("site", "(DATASET.h5 | LEDGER | FOLDER) -o DIR [--overwrite] [--cut C] [--link-cut C] [--title T] [--json]");
  args.positional("DATASET", &file, "data-set file, ledger file, or folder of ledgers (*.ledger.h5)");
  args.option("-o,--output", &out, "folder of the site (new or empty; see --overwrite)");
  args.flag("--overwrite", &overwrite, "replace a folder that an earlier knots site wrote");
  args.option("--cut", &options.cut, "distance cut of the table's distinct states and the sliders' start, in [0, 1]");
  args.option("--link-cut", &options.link_cut,
              "the same for links, in the link state distance [mean component length] (default 0.002)");
  args.option("--title", &title, "title of the site (default: the file's or folder's name)");
  args.flag("--json", &json, "print one JSON object");
  if (!args.parse(argc, argv)) return 0;
  if (out.empty()) throw InputError("missing -o DIR");
  options.title = title;
  options.validate();
  check_site_folder(out, overwrite);
  const SiteFiles files = build_site(file, options);
  write_site(files, out, overwrite);
  size_t bytes = 0, data_bytes = 0, knots = 0;
  for (const auto& [path, content] : files) {
    bytes += content.size();
    if (path.rfind("data/", 0) == 0) data_bytes += content.size();
    if (path.rfind("data/knots/", 0) == 0 && path.size() > 5 && path.compare(path.size() - 5, 5, ".json") == 0) ++knots;
  }
  if (json) {
    Json j;
    j["output"] = out;
    j["knots"] = knots;
    j["files"] = files.size();
    j["bytes"] = bytes;
    j["data_bytes"] = data_bytes;
    print_json(j);
    return 0;
  }
  std::cout << "wrote " << out << "/index.html: " << knots << " knots, " << files.size() << " files, "
            << fmt(bytes / 1e6, 3) << " MB (data " << fmt(data_bytes / 1e6, 3) << " MB)\n";
  return 0;
}

}  // namespace ek::cli
