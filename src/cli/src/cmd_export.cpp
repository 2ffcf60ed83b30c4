// knots export DATASET NAME INDEX -o FILE.obj
#include <iostream>

#include "args.hpp"
#include "commands.hpp"
#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "ek/geometry/curve_io.hpp"

namespace ek::cli {

int cmd_export(int argc, char** argv) {
  std::string file, name, index_text, out;
  ArgParser args("export", "DATASET NAME INDEX -o FILE.obj");
  args.positional("DATASET", &file, "data-set file");
  args.positional("NAME", &name, "knot name");
  args.positional("INDEX", &index_text, "equilibrium index (0-based, as listed by knots query)");
  args.option("-o,--output", &out, "curve file (.obj or .txt), written atomically");
  if (!args.parse(argc, argv)) return 0;
  if (out.empty()) throw InputError("missing -o FILE");
  check_writable(out);
  const long long index = parse_integer(index_text, "INDEX");
  DatasetReader reader(file);
  const KnotEntry e = reader.read(name);
  if (index < 0 || index >= static_cast<long long>(e.equilibria.size()))
    throw InputError("INDEX " + index_text + " out of range: " + name + " has " + std::to_string(e.equilibria.size()) +
                     " equilibria");
  if (e.is_link())
    write_link(out, e.equilibrium_link(static_cast<int>(index)));
  else
    write_curve(out, e.equilibria[static_cast<size_t>(index)]);
  std::cout << "wrote " << out << ": " << name << " equilibrium " << index << "\n";
  return 0;
}

}  // namespace ek::cli
