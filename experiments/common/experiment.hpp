#pragma once
// Shared plumbing of the paper experiments: the SCALE knob, output folders,
// crash-safe CSV/JSON results, and the run-time estimate printed before a run.
// Experiments are thin programs over the library; figure scripts read only
// what they write.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ek/core/errors.hpp"

namespace ek::exp {

/// How much of the paper's computation an experiment repeats.
///  - ci:      fits the CI budget together with every other test (minutes)
///  - default: what `make figures` runs (all experiments together <= 2 h on 2 cores)
///  - paper:   the paper's scale (all 2,977 knots, adaptive sampling up to 500)
///  - paper10: the paper's data set up to 10 crossings (249 knots, adaptive
///             sampling up to 500); every other experiment at its default
///             parameters (by_scale() gives the default value)
///  - sample12: the paper's data set on a deterministic stratified sample of
///             the 11- and 12-crossing knots (10% of every stratum and every
///             BB knot, ek::stratified_sample; adaptive sampling up to 500);
///             every other experiment at its default parameters
enum class Scale { CI, Default, Paper, Paper10, Sample12 };

struct Args {
  Scale scale = Scale::Default;
  std::string scale_name = "default";
  std::string out;        ///< output folder of this experiment
  std::string results;    ///< results root (parent of the experiments' folders)
  int jobs = 2;           ///< parallel relaxations
  /// The relaxation method of the twist-free data-set runs (`--method`, as
  /// `knots relax --method`: default, gauss-newton, eigen-projected, hybrid, exact, paper;
  /// with_method()).
  std::string method = "default";
  /// The run seed of the data-set runs (`--seed`; every knot's walk and every
  /// sample derive from it, docs/models.md); 1 unless given.
  std::uint64_t seed = 1;
};

/// An option an experiment adds to the common ones (`--name VALUE` when
/// `value` is set, a flag `--name` otherwise). It takes precedence over a
/// common option of the same name. A handler throws InputError for a bad
/// value: one line on stderr, exit status 2.
struct ExtraOption {
  std::string name;   ///< "--count"
  std::string usage;  ///< "[--count K]", shown by --help
  std::function<void(const std::string&)> value;
  std::function<void()> flag;
};

/// Parses `--scale ci|default|paper|paper10|sample12 --out DIR [--jobs J] [--method M] [--seed S]`, the
/// experiment's `extra` options (and --help);
/// creates DIR. Bad arguments: one line on stderr, exit status 2.
///
/// Reruns: a DIR holding a finished run (DIR/summary.json, written last by
/// every experiment) is renamed DIR.previous (replacing an older one) and the
/// experiment starts afresh, so a rerun after a code change never keeps the
/// old results (a data set would otherwise skip every knot it already holds).
/// DIR.previous is removed when the new run finishes (run_experiment); a
/// failed or interrupted run leaves it, and its own unfinished DIR, which the
/// next run resumes (data-set journals, docs/dataset-format.md).
Args parse_args(int argc, char** argv, const std::string& name, const std::string& description,
                const std::vector<ExtraOption>& extra = {});

/// DIR.previous for an output folder DIR ("dir/" and "dir" give the same).
std::filesystem::path previous_folder(const std::string& out);

/// Pick a value by scale (paper10 and sample12 take the default value: only
/// the data set has its own parameters at those scales).
template <class T>
T by_scale(const Args& a, T ci, T def, T paper) {
  return a.scale == Scale::CI ? ci : a.scale == Scale::Paper ? paper : def;
}

/// Prints "experiment NAME at scale S: WHAT; expected run time about T on J jobs".
void announce(const Args& a, const std::string& name, const std::string& what, double expected_seconds);

/// Writes text atomically (temporary file + rename).
void write_text(const std::string& path, const std::string& text);
/// Writes a JSON document (pretty) atomically.
void write_json(const std::string& path, const nlohmann::ordered_json& j);

/// Writes an experiment's summary struct (experiments/schema/*_summary.hpp)
/// as DIR/summary.json, atomically; the summary is written last, so its
/// presence marks a finished run (parse_args).
template <class Summary>
void write_summary(const Args& a, const Summary& s) {
  write_json(a.out + "/summary.json", nlohmann::ordered_json(s));
}

/// A CSV table written atomically on commit().
class Csv {
 public:
  Csv(std::string path, std::vector<std::string> header);
  Csv& row(const std::vector<std::string>& cells);
  void commit();
  static std::string num(double x, int digits = 12);
  /// A flag cell: "true" or "false" (docs/results.md, "CSV files").
  static std::string flag(bool x) { return x ? "true" : "false"; }

 private:
  std::string path_, text_;
  size_t columns_;
};

/// One column of a results table: its name and the text of its cell in a
/// row (Csv::num, Csv::flag, ...), so that a table is described once.
template <class Row>
struct CsvColumn {
  std::string name;                              ///< the header's cell
  std::function<std::string(const Row&)> cell;  ///< a row's cell
};

/// Writes `rows` as the table of `columns` to `path` (a header line of the
/// columns' names, one line per row) atomically, as Csv does.
template <class Row>
void write_csv(const std::string& path, const std::vector<CsvColumn<Row>>& columns, const std::vector<Row>& rows) {
  std::vector<std::string> header;
  for (const CsvColumn<Row>& c : columns) header.push_back(c.name);
  Csv csv(path, header);
  for (const Row& r : rows) {
    std::vector<std::string> cells;
    for (const CsvColumn<Row>& c : columns) cells.push_back(c.cell(r));
    csv.row(cells);
  }
  csv.commit();
}

/// A row of a results table read back: column → cell.
using CsvRow = std::map<std::string, std::string>;

/// The rows of a results table written by Csv (no quoted cells; a trailing
/// empty cell kept). InputError "<who>: ..." when the file cannot be read
/// (its experiment has not run), lacks a column of `required`, or a row has
/// the wrong number of cells.
std::vector<CsvRow> read_csv_rows(const std::string& path, const std::string& who,
                                  const std::vector<std::string>& required = {});

/// Wall-clock seconds since the first call.
double elapsed_seconds();

/// The main of an experiment: parses the arguments, runs `body`, and turns
/// bad input (InputError) into one line on stderr and exit status 2.
int run_experiment(int argc, char** argv, const std::string& name, const std::string& description,
                   const std::function<void(const Args&)>& body, const std::vector<ExtraOption>& extra = {});

/// The items of a separated list, empty items dropped ("a,,b" gives a, b).
std::vector<std::string> split_list(const std::string& text, char separator = ',');
/// The median (the mean of the two middle values for an even count; 0 for none).
double median(std::vector<double> values);

}  // namespace ek::exp
