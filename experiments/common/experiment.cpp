#include "experiment.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "ek/core/atomic_file.hpp"
#include "ek/core/errors.hpp"
#include "ek/solver/relax.hpp"

namespace ek::exp {

namespace fs = std::filesystem;

double elapsed_seconds() {
  static const auto t0 = std::chrono::steady_clock::now();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

fs::path previous_folder(const std::string& out) {
  fs::path p(out);
  if (!p.has_filename()) p = p.parent_path();  // "dir/" names the same folder as "dir"
  return p.string() + ".previous";
}

Args parse_args(int argc, char** argv, const std::string& name, const std::string& description,
                const std::vector<ExtraOption>& extra) {
  elapsed_seconds();
  Args a;
  auto fail = [&](const std::string& why) {
    std::cerr << name << ": error: " << why << std::endl;
    std::exit(2);
  };
  for (int i = 1; i < argc; ++i) {
    const std::string s = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) fail("option " + s + " needs a value");
      return argv[++i];
    };
    const auto own = std::find_if(extra.begin(), extra.end(), [&](const ExtraOption& o) { return o.name == s; });
    if (own != extra.end()) {
      try {
        if (own->value) own->value(value());
        else own->flag();
      } catch (const InputError& e) {
        fail(s + ": " + e.what());
      }
      continue;
    }
    if (s == "--help" || s == "-h") {
      std::cout << "usage: " << name
                << " --scale ci|default|paper|paper10|sample12 --out DIR [--jobs J] [--method M] [--seed S]";
      for (const ExtraOption& o : extra) std::cout << " " << o.usage;
      std::cout << "\n" << description << "\n";
      std::exit(0);
    } else if (s == "--scale") {
      a.scale_name = value();
      if (a.scale_name == "ci") a.scale = Scale::CI;
      else if (a.scale_name == "default") a.scale = Scale::Default;
      else if (a.scale_name == "paper") a.scale = Scale::Paper;
      else if (a.scale_name == "paper10") a.scale = Scale::Paper10;
      else if (a.scale_name == "sample12") a.scale = Scale::Sample12;
      else fail("--scale '" + a.scale_name + "': expected ci, default, paper, paper10 or sample12");
    } else if (s == "--out") {
      a.out = value();
    } else if (s == "--jobs") {
      const std::string v = value();
      char* end = nullptr;
      const long j = std::strtol(v.c_str(), &end, 10);
      if (*end != '\0' || j < 1 || j > 256) fail("--jobs '" + v + "': expected an integer in 1..256");
      a.jobs = static_cast<int>(j);
    } else if (s == "--method") {
      a.method = value();
      try {
        with_method(RelaxOptions{}, a.method);  // checks the name
      } catch (const InputError& e) {
        fail(std::string("--method: ") + e.what());
      }
    } else if (s == "--seed") {
      const std::string v = value();
      char* end = nullptr;
      errno = 0;
      const unsigned long long seed = std::strtoull(v.c_str(), &end, 10);
      if (v.empty() || v[0] == '-' || *end != '\0' || errno == ERANGE) fail("--seed '" + v + "': expected a non-negative integer");
      a.seed = seed;
    } else {
      fail("unknown argument '" + s + "' (see --help)");
    }
  }
  if (a.out.empty()) fail("missing --out DIR");
  std::error_code ec;
  if (fs::exists(fs::path(a.out) / "summary.json", ec)) {
    // A finished run: this one recomputes everything (its data sets would
    // otherwise keep the old equilibria of every knot they hold). The old
    // folder is kept as DIR.previous until this run finishes.
    const fs::path previous = previous_folder(a.out);
    fs::remove_all(previous, ec);
    if (ec) fail("cannot remove '" + previous.string() + "': " + ec.message());
    fs::rename(a.out, previous, ec);
    if (ec) fail("cannot move the finished run '" + a.out + "' to '" + previous.string() + "': " + ec.message());
  }
  fs::create_directories(a.out, ec);
  if (ec) fail("cannot create '" + a.out + "': " + ec.message());
  a.results = fs::path(a.out).parent_path().string();
  if (a.results.empty()) a.results = ".";
  return a;
}

int run_experiment(int argc, char** argv, const std::string& name, const std::string& description,
                   const std::function<void(const Args&)>& body, const std::vector<ExtraOption>& extra) {
  const Args a = parse_args(argc, argv, name, description, extra);
  try {
    body(a);
  } catch (const InputError& e) {
    std::cerr << name << ": error: " << e.what() << std::endl;
    return 2;
  }
  std::error_code ec;
  fs::remove_all(previous_folder(a.out), ec);  // the run finished: its predecessor is replaced
  return 0;
}

std::vector<std::string> split_list(const std::string& text, char separator) {
  std::vector<std::string> out;
  std::string item;
  for (std::istringstream in(text); std::getline(in, item, separator);)
    if (!item.empty()) out.push_back(item);
  return out;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

void announce(const Args& a, const std::string& name, const std::string& what, double expected) {
  std::string t;
  if (expected < 120) t = std::to_string(static_cast<int>(std::ceil(expected))) + " s";
  else if (expected < 7200) t = std::to_string(static_cast<int>(std::ceil(expected / 60))) + " min";
  else {
    char hours[32];
    std::snprintf(hours, sizeof hours, "%.1f h", std::ceil(expected / 360) / 10);  // tenths, rounded up
    t = hours;
  }
  std::cout << "experiment " << name << " at scale " << a.scale_name << ": " << what << "; expected run time about "
            << t << " on " << a.jobs << " jobs" << std::endl;
}

void write_text(const std::string& path, const std::string& text) {
  AtomicFile f(path);
  f.stream() << text;
  f.commit();
}

void write_json(const std::string& path, const nlohmann::ordered_json& j) { write_text(path, j.dump(2) + "\n"); }

Csv::Csv(std::string path, std::vector<std::string> header) : path_(std::move(path)), columns_(header.size()) {
  row(header);
}

Csv& Csv::row(const std::vector<std::string>& cells) {
  require(cells.size() == columns_, "Csv::row: wrong number of cells");
  for (size_t k = 0; k < cells.size(); ++k) text_ += (k ? "," : "") + cells[k];
  text_ += "\n";
  return *this;
}

void Csv::commit() { write_text(path_, text_); }

std::string Csv::num(double x, int digits) {
  if (!std::isfinite(x)) return "nan";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

std::vector<CsvRow> read_csv_rows(const std::string& path, const std::string& who,
                                  const std::vector<std::string>& required) {
  std::ifstream in(path);
  require_input(static_cast<bool>(in), who + ": cannot read " + path + " (run its experiment first)");
  const auto split = [](const std::string& line) {
    std::vector<std::string> out;
    std::stringstream s(line);
    for (std::string item; std::getline(s, item, ',');) out.push_back(item);
    if (!line.empty() && line.back() == ',') out.emplace_back();  // getline drops a trailing empty cell
    return out;
  };
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = split(line);
  for (const std::string& name : required)
    require_input(std::find(header.begin(), header.end(), name) != header.end(),
                  who + ": " + path + " has no column '" + name + "'");
  std::vector<CsvRow> rows;
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = split(line);
    require_input(cells.size() == header.size(), who + ": " + path + ": a row has the wrong number of cells");
    CsvRow r;
    for (size_t k = 0; k < header.size(); ++k) r[header[k]] = cells[k];
    rows.push_back(std::move(r));
  }
  return rows;
}

}  // namespace ek::exp
