// knots describe DATASET [--json]
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "ek/dataset/json.hpp"
#include "output.hpp"

namespace ek::cli {

int cmd_describe(int argc, char** argv) {
  std::string file;
  bool json = false;
  ArgParser args("describe", "DATASET [--json]");
  args.positional("DATASET", &file, "data-set file");
  args.flag("--json", &json, "print one JSON object");
  if (!args.parse(argc, argv)) return 0;
  DatasetReader reader(file);
  if (json) {
    Json j;
    j["file"] = file;
    j.update(describe_json(reader));
    print_json(j);
    return 0;
  }
  std::cout << reader.metadata().text() << "knots (" << reader.knot_names().size() << "):";
  for (const auto& name : reader.knot_names()) std::cout << " " << name;
  std::cout << "\n";
  return 0;
}

}  // namespace ek::cli
