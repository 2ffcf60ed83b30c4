// The explorer site of a data set or of ledgers (site.hpp): the knot table,
// the attribute table and the site's files.
#include "ek/site/site.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

#include "assets.hpp"
#include "ek/analysis/clustering.hpp"
#include "ek/core/errors.hpp"
#include "ek/core/paths.hpp"
#include "ek/dataset/pipeline.hpp"
#include "ek/knots/table.hpp"
#include "site_internal.hpp"

#ifndef EK_THREE_JS_DIR
#define EK_THREE_JS_DIR "/usr/share/javascript/three"
#endif

namespace ek {
namespace {

using site_detail::append;
using site_detail::Json;
using site_detail::number;
constexpr double kPi = 3.14159265358979323846;

/// What the site was built from (site.json: dataset.source).
enum class SiteSource { Dataset, Ledger };

const char* to_string(SiteSource s) { return s == SiteSource::Ledger ? "ledger" : "dataset"; }

Json optional_index(int x) { return x < 0 ? Json(nullptr) : Json(x); }

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read " + path + " (three.js: Debian package libjs-three)");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// Every stored equilibrium of a knot, as the knot table summarises it: a
/// data set's entry, or a ledger's (which has every row without the curves).
struct KnotRows {
  const KnotHeader& header;
  const std::vector<std::string>& names;  ///< k attribute names
  const Eigen::MatrixXd& attributes;      ///< m by k
  const Eigen::MatrixXd& linkage;         ///< (m − 1) by 4, over all m
  size_t runs;
};

/// The rows of a KnotEntry or a LedgerEntry (the same member names).
template <class Entry>
KnotRows rows_of(const Entry& e) {
  return {e, e.attribute_names, e.attributes, e.linkage, e.runs.size()};
}

/// Clusters of all m equilibria at `cut` (clusters_at_cut's count).
int distinct_at(const KnotRows& k, double cut) {
  const auto m = k.attributes.rows();
  if (m <= 1) return static_cast<int>(m);
  return cluster_count(Dendrogram::from_linkage(k.linkage), cut);
}

/// Column `name` of the rows; -1 when absent.
int column(const KnotRows& k, const std::string& name) {
  const auto it = std::find(k.names.begin(), k.names.end(), name);
  return it == k.names.end() ? -1 : static_cast<int>(it - k.names.begin());
}

/// The smallest (or, with `largest`, the largest) value of column `name`; null without rows.
Json extreme(const KnotRows& k, const std::string& name, bool largest = false) {
  const int c = column(k, name);
  if (k.attributes.rows() == 0 || c < 0) return nullptr;
  double x = largest ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < k.attributes.rows(); ++i)  // NaN rows are skipped
    x = largest ? std::max(x, k.attributes(i, c)) : std::min(x, k.attributes(i, c));
  return number(x);
}

/// One row of the knot table in data/site.json.
Json knot_record(const KnotRows& k, const std::string& file, int distinct, size_t offset, const ShownStates* shown) {
  const KnotHeader& h = k.header;
  const KnotRecord* rec = KnotTable::global().find(h.name);
  Json r;
  r["name"] = h.name;
  r["file"] = file;
  r["crossing_number"] = h.crossing_number;
  r["bridge_index"] = optional_index(h.bridge_index);
  r["braid_index"] = optional_index(h.braid_index);
  const bool known = h.bridge_index > 0 && h.braid_index > 0;
  r["bb"] = known ? Json(h.bridge_index == h.braid_index) : Json(nullptr);
  r["two_bridge"] = h.bridge_index > 0 ? Json(h.bridge_index == 2) : Json(nullptr);
  r["alternating"] = rec && rec->alternating ? Json(*rec->alternating) : Json(nullptr);
  r["samples"] = h.samples_used;
  r["runs"] = k.runs;
  r["equilibria"] = k.attributes.rows();
  r["distinct"] = distinct;
  r["lowest_energy"] = extreme(k, "energy");
  r["largest_threedim"] = extreme(k, "threedim", true);
  r["min_total_curvature"] = extreme(k, "total_curvature");
  const Json tc = r["min_total_curvature"];
  r["milnor_ratio"] = tc.is_null() || h.bridge_index <= 0 ? Json(nullptr)
                                                            : number(tc.get<double>() / (2.0 * kPi * h.bridge_index));
  r["adaptive"] = h.adaptive;
  r["complete"] = h.complete;
  r["offset"] = offset;
  if (shown) r["shown_rows"] = shown->rows;
  return r;
}

/// A data-set parameter, null when the file does not record it (metadata.hpp).
template <class T>
Json or_null(const std::optional<T>& v) {
  return v ? Json(*v) : Json(nullptr);
}

/// The name of a file or folder ("dir/" -> "dir"); a folder with its parent's name ("sample12/ledgers").
std::string source_name(const std::string& path) {
  std::filesystem::path p = std::filesystem::path(path).lexically_normal();
  if (!p.has_filename() && p.has_parent_path()) p = p.parent_path();
  if (!std::filesystem::is_directory(p)) return p.filename().string();
  const std::filesystem::path parent = std::filesystem::absolute(p).parent_path().filename();
  return (parent.empty() ? p.filename() : parent / p.filename()).string();
}

Json dataset_json(const DatasetMetadata& meta, const std::string& path, const std::string& title, SiteSource source) {
  Json d;
  d["file"] = source_name(path);
  d["title"] = title.empty() ? source_name(path) : title;
  d["created"] = or_null(meta.created);
  d["project_version"] = or_null(meta.project_version);
  d["sampling"] = or_null(meta.sampling);
  d["seed"] = or_null(meta.seed);
  d["vertices"] = or_null(meta.vertices);
  d["edge_length"] = or_null(meta.edge_length);
  d["radius"] = or_null(meta.radius);
  d["dhat"] = or_null(meta.dhat);
  d["young"] = or_null(meta.young);
  d["poisson"] = or_null(meta.poisson);
  d["tolerance"] = or_null(meta.tolerance);
  d["twist_model"] = or_null(meta.twist_model);
  d["source"] = to_string(source);
  return d;
}

void add_three(SiteFiles& files, const std::string& dir) {
  for (const char* rel : {"build/three.module.js", "examples/jsm/controls/OrbitControls.js"})
    files[std::string("three/") + rel] = slurp(dir + "/" + rel);
  const std::string copyright = "/usr/share/doc/libjs-three/copyright";
  if (std::filesystem::exists(copyright)) files["three/COPYRIGHT"] = slurp(copyright);
}

/// [length] the contact distance of the site's contact flags (every data set and ledger records it).
double contact_distance(const DatasetMetadata& meta, const std::string& path) {
  if (!meta.dhat) throw InputError(path + ": records no contact distance dhat");
  return *meta.dhat;
}

/// The site's files, knot after knot: a data set's and a ledger's site share it.
class SiteBuilder {
 public:
  SiteBuilder(const std::string& path, const SiteOptions& options, double dhat)
      : path_(path), options_(options), dhat_(dhat) {}

  /// Adds a knot: `k` its stored equilibria (the table's record and
  /// attributes.bin), `shown` those its pages show (curves, their attributes,
  /// similarity, linkage, runs), `states` what a ledger's shown states add.
  void add(const KnotRows& k, const KnotEntry& shown, const ShownStates* states = nullptr) {
    if (columns_.empty()) columns_ = k.names;
    if (k.attributes.rows() > 0 && k.names != columns_)
      throw InputError(path_ + ": " + k.header.name +
                       " has other attribute columns than the first entry (a site shows knots or links, not both)");
    const std::string file = knot_file_name(k.header.name);
    const double cut = k.header.is_link() ? options_.link_cut : options_.cut;
    KnotSiteData data = knot_site_data(shown, file, dhat_, cut, states);
    knots_.push_back(knot_record(k, file, distinct_at(k, cut), rows_, states));
    files_["data/knots/" + file + ".json"] = std::move(data.json);
    files_["data/knots/" + file + ".bin"] = std::move(data.binary);
    for (Eigen::Index i = 0; i < k.attributes.rows(); ++i)
      for (Eigen::Index c = 0; c < k.attributes.cols(); ++c) append(attributes_, k.attributes(i, c));
    rows_ += static_cast<size_t>(k.attributes.rows());
  }

  /// Every file of the site, with `dataset` as site.json's dataset object.
  SiteFiles finish(Json dataset) {
    Json site;
    site["format"] = kSiteFormat;
    site["format_version"] = kSiteFormatVersion;
    site["generated_by"] = "knots site " + project_version();
    site["dataset"] = std::move(dataset);
    site["cut"] = options_.cut;
    site["link_cut"] = options_.link_cut;
    site["attribute_names"] = columns_;
    site["attributes"] = {{"file", "attributes.bin"}, {"dtype", "float64"}, {"rows", rows_}, {"columns", columns_.size()}};
    site["knots"] = std::move(knots_);
    files_["data/site.json"] = site.dump();
    files_["data/attributes.bin"] = std::move(attributes_);
    for (const auto& [path, content] : site_assets()) files_[path] = std::string(content);
    add_three(files_, options_.three_dir);
    return std::move(files_);
  }

 private:
  const std::string& path_;
  const SiteOptions& options_;
  double dhat_;
  SiteFiles files_;
  Json knots_ = Json::array();
  std::vector<std::string> columns_;
  std::string attributes_;
  size_t rows_ = 0;
};

SiteFiles dataset_site(const std::string& path, const SiteOptions& options) {
  DatasetReader reader(path);
  SiteBuilder site(path, options, contact_distance(reader.metadata(), path));
  for (const std::string& name : reader.knot_names()) {
    const KnotEntry e = reader.read(name);
    site.add(rows_of(e), e);
  }
  return site.finish(dataset_json(reader.metadata(), path, options.title, SiteSource::Dataset));
}

/// The comparison the data-set pipeline used for a knot (options_for_knot of the default options).
SimilarityOptions knot_similarity(const std::string& name) {
  const ExploreOptions defaults;
  const KnotRecord* knot = KnotTable::global().find(name);
  return knot ? options_for_knot(defaults, *knot).similarity : defaults.similarity;
}

SiteFiles ledger_site(const std::string& path, const SiteOptions& options) {
  const Ledger ledger = read_ledger_source(path);
  SiteBuilder site(path, options, contact_distance(ledger.parameters, path));
  for (const LedgerEntry& e : ledger.entries) {
    ShownStates states;
    const KnotEntry shown = shown_states(e, knot_similarity(e.name), &states);
    site.add(rows_of(e), shown, &states);
  }
  Json d = dataset_json(ledger.parameters, path, options.title, SiteSource::Ledger);
  d["ledger_cut"] = ledger.provenance.cut;
  d["curves_per_knot"] = ledger.provenance.curves_per_knot;
  return site.finish(std::move(d));
}

}  // namespace

SiteOptions::SiteOptions() : three_dir(EK_THREE_JS_DIR) {}

void SiteOptions::validate() const {
  if (!(cut >= 0.0 && cut <= 1.0)) throw InputError("--cut must be in [0, 1]");
  if (!(link_cut >= 0.0 && link_cut <= 1.0)) throw InputError("--link-cut must be in [0, 1]");
}

SiteFiles build_site(const std::string& path, const SiteOptions& options) {
  options.validate();
  if (!std::filesystem::exists(options.three_dir + "/build/three.module.js"))
    throw InputError("three.js not found in " + options.three_dir + " (install the Debian package libjs-three)");
  return is_ledger_source(path) ? ledger_site(path, options) : dataset_site(path, options);
}

std::string content_type(const std::string& path) {
  const auto ext = std::filesystem::path(path).extension().string();
  if (ext == ".html") return "text/html; charset=utf-8";
  if (ext == ".js") return "text/javascript; charset=utf-8";
  if (ext == ".css") return "text/css; charset=utf-8";
  if (ext == ".json") return "application/json";
  if (ext == ".svg") return "image/svg+xml";
  if (ext == ".png") return "image/png";
  if (ext == ".bin") return "application/octet-stream";
  return "text/plain; charset=utf-8";
}

}  // namespace ek
