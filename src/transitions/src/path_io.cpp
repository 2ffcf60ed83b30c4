#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "ek/transitions/saddles.hpp"

namespace ek {

void write_path_obj(const std::string& path, const std::vector<Points>& images, const std::vector<double>& energies) {
  require(images.size() == energies.size(), "write_path_obj: one energy per image");
  AtomicFile f(path);
  std::ostream& out = f.stream();
  char buf[128];
  long long base = 1;
  for (size_t k = 0; k < images.size(); ++k) {
    std::snprintf(buf, sizeof buf, "o image_%zu E=%.17g\n", k, energies[k]);
    out << buf;
    const Points& P = images[k];
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
      std::snprintf(buf, sizeof buf, "v %.17g %.17g %.17g\n", P(i, 0), P(i, 1), P(i, 2));
      out << buf;
    }
    out << "l";
    for (Eigen::Index i = 0; i < P.rows(); ++i) out << ' ' << base + i;
    out << ' ' << base << "\n";
    base += P.rows();
  }
  f.commit();
}

namespace {

Points to_points(const std::vector<double>& xyz) {
  Points P(static_cast<Eigen::Index>(xyz.size() / 3), 3);
  for (Eigen::Index i = 0; i < P.rows(); ++i) P.row(i) << xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2];
  return P;
}

}  // namespace

std::vector<Points> read_path_obj(const std::string& path, std::vector<double>& energies) {
  std::ifstream in(path);
  require_input(static_cast<bool>(in), path + ": cannot open");
  std::vector<Points> images;
  std::vector<double> xyz;
  energies.clear();
  std::string line;
  int row = 0;
  while (std::getline(in, line)) {
    ++row;
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "o") {
      if (!energies.empty()) images.push_back(to_points(xyz));
      xyz.clear();
      std::string name, e;
      s >> name >> e;
      char* end = nullptr;
      const double energy = e.size() > 2 ? std::strtod(e.c_str() + 2, &end) : 0.0;
      require_input(e.rfind("E=", 0) == 0 && end && *end == '\0',
                    path + ":" + std::to_string(row) + ": expected 'o image_<k> E=<energy>'");
      energies.push_back(energy);
    } else if (tag == "v") {
      double x = 0, y = 0, z = 0;
      require_input(!energies.empty() && static_cast<bool>(s >> x >> y >> z),
                    path + ":" + std::to_string(row) + ": a vertex needs an image ('o') and three numbers");
      xyz.insert(xyz.end(), {x, y, z});
    }
  }
  if (!energies.empty()) images.push_back(to_points(xyz));
  require_input(!images.empty(), path + ": no image");
  return images;
}

}  // namespace ek
