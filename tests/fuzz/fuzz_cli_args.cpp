// The command line's parsing of numbers, lists and options (src/cli/src/args.cpp).
// The input is split at NUL bytes into arguments; each is also parsed as a
// number, an integer and a number list.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <vector>

#include "args.hpp"
#include "fuzz_common.hpp"

namespace {

std::vector<std::string> split_args(const std::string& text) {
  std::vector<std::string> out;
  size_t start = 0;
  for (size_t i = 0; i <= text.size(); ++i)
    if (i == text.size() || text[i] == '\0') {
      out.push_back(text.substr(start, i - start));
      start = i + 1;
    }
  return out;
}

void parse_values(const std::string& arg) {
  using namespace ek::cli;
  ek::fuzz::expect_result_or_input_error([&] {
    const double v = parse_number(arg, "--x");
    EK_FUZZ_CHECK(std::isfinite(v));
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    EK_FUZZ_CHECK(parse_number(buf, "--x") == v);
  });
  ek::fuzz::expect_result_or_input_error([&] {
    const long long v = parse_integer(arg, "--n");
    EK_FUZZ_CHECK(parse_integer(std::to_string(v), "--n") == v);
  });
  ek::fuzz::expect_result_or_input_error([&] {
    const auto list = parse_number_list(arg, "--list");
    const size_t commas = static_cast<size_t>(std::count(arg.begin(), arg.end(), ','));
    EK_FUZZ_CHECK(arg.empty() ? list.empty() : list.size() == commas + 1);
    for (double v : list) EK_FUZZ_CHECK(std::isfinite(v));
  });
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  std::cout.setstate(std::ios::badbit);  // --help prints the usage
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::vector<std::string> args = split_args(ek::fuzz::text(data, size));
  for (const auto& a : args) parse_values(a);
  std::vector<char*> argv{const_cast<char*>("knots"), const_cast<char*>("fuzz")};
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  ek::fuzz::expect_result_or_input_error([&] {
    std::string input, name;
    double radius = 0.2;
    int n = 400;
    long long seed = 1;
    std::optional<double> tol;
    std::optional<int> jobs;
    std::optional<std::string> knot;
    std::vector<std::string> where, rest;
    bool json = false;
    ek::cli::ArgParser p("fuzz", "INPUT [NAMES...] [options]");
    p.positional("INPUT", &input, "input");
    p.rest("NAMES", &rest, "names");
    p.option("-o,--output", &name, "output");
    p.option("-r,--radius", &radius, "radius");
    p.option("-n,--vertices", &n, "vertices");
    p.option("--seed", &seed, "seed");
    p.option("--tol", &tol, "tolerance");
    p.option("--jobs", &jobs, "jobs");
    p.option("--knot", &knot, "knot");
    p.option("--where", &where, "conditions");
    p.flag("--json", &json, "json");
    if (!p.parse(static_cast<int>(argv.size()), argv.data())) return;
    EK_FUZZ_CHECK(std::isfinite(radius) && (!tol || std::isfinite(*tol)));
    EK_FUZZ_CHECK(p.given("--json") == json);
  });
  return 0;
}
