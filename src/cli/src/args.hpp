#pragma once
// Minimal, strict command-line parsing for the `knots` subcommands: every
// unknown option, missing value or malformed number is an InputError (exit 2).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "ek/core/parse.hpp"
#include <Eigen/Core>

namespace ek::cli {

class ArgParser {
 public:
  ArgParser(std::string command, std::string synopsis);

  /// Required positional argument.
  void positional(const std::string& name, std::string* value, const std::string& help);
  /// Optional positional arguments collected in order (after the required ones).
  void rest(const std::string& name, std::vector<std::string>* values, const std::string& help);
  /// Option with a value; `names` like "-o,--output".
  void option(const std::string& names, std::string* value, const std::string& help);
  void option(const std::string& names, double* value, const std::string& help);
  void option(const std::string& names, int* value, const std::string& help);
  void option(const std::string& names, long long* value, const std::string& help);
  void option(const std::string& names, std::optional<double>* value, const std::string& help);
  void option(const std::string& names, std::optional<int>* value, const std::string& help);
  void option(const std::string& names, std::optional<std::string>* value, const std::string& help);
  /// Repeatable option (each occurrence appended).
  void option(const std::string& names, std::vector<std::string>* values, const std::string& help);
  /// Boolean flag.
  void flag(const std::string& names, bool* value, const std::string& help);

  /// Parses argv[first..argc). Returns false if --help was given (usage printed).
  bool parse(int argc, char** argv, int first = 2);
  std::string usage() const;
  /// Whether the option (by any of its names) was given on the command line.
  bool given(const std::string& name) const;

 private:
  struct Opt {
    std::vector<std::string> names;
    std::string help;
    bool takes_value;
    std::function<void(const std::string&, const std::string&)> set;
    bool seen = false;
  };
  struct Pos {
    std::string name, help;
    std::string* value;
  };
  std::string command_, synopsis_;
  std::vector<Opt> opts_;
  std::vector<Pos> pos_;
  std::vector<std::string>* rest_ = nullptr;
  std::string rest_name_, rest_help_;
  Opt* find(const std::string& name);
};

/// The strict number parsers of ek/core/parse.hpp.
using ek::parse_integer;
using ek::parse_number;
/// Parses comma-separated numbers ("1e-3" or "1e-2,1e-1"); an empty item is
/// not a number. The empty text gives an empty list.
std::vector<double> parse_number_list(const std::string& text, const std::string& what);
/// Parses "X,Y,Z" (three finite numbers) given to `option`; InputError
/// "OPTION expects X,Y,Z, not 'TEXT'" otherwise.
Eigen::Vector3d parse_vec3(const std::string& text, const std::string& option);

}  // namespace ek::cli
