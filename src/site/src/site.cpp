// The data files of the explorer site (site.hpp).
#include "ek/site/site.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "assets.hpp"
#include "ek/analysis/clustering.hpp"
#include "ek/analysis/mds.hpp"
#include "ek/contact/broad_phase.hpp"
#include "ek/core/errors.hpp"
#include "ek/core/paths.hpp"
#include "ek/dataset/pipeline.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/knots/table.hpp"

#ifndef EK_THREE_JS_DIR
#define EK_THREE_JS_DIR "/usr/share/javascript/three"
#endif

namespace ek {
namespace {

using Json = nlohmann::ordered_json;
constexpr double kPi = 3.14159265358979323846;

bool little_endian() {
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

template <class T>
void append(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

/// Describes one array of a knot's binary file and checks its alignment.
Json buffer(const std::string& dtype, std::vector<int> shape, size_t offset) {
  return Json{{"dtype", dtype}, {"shape", shape}, {"offset", offset}};
}

Json number(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

Json optional_index(int x) { return x < 0 ? Json(nullptr) : Json(x); }

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read " + path + " (three.js: Debian package libjs-three)");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// MDS coordinates [m, 2] of 1 - similarity (1D for two equilibria, the
/// origin for one).
Json mds_json(const KnotEntry& e, bool& converged, double& explained) {
  const auto m = static_cast<int>(e.equilibria.size());
  converged = true;
  explained = 1.0;
  Eigen::MatrixXd X = Eigen::MatrixXd::Zero(m, 2);
  if (m >= 2) {
    const MdsResult r = classical_mds_from_similarity(e.similarity, std::min(2, m - 1));
    X.leftCols(r.coordinates.cols()) = r.coordinates;
    converged = r.status == MdsStatus::Converged;
    explained = r.explained;
  }
  Json out = Json::array();
  for (int i = 0; i < m; ++i) out.push_back({number(X(i, 0)), number(X(i, 1))});
  return out;
}

}  // namespace

SiteOptions::SiteOptions() : three_dir(EK_THREE_JS_DIR) {}

void SiteOptions::validate() const {
  if (!(cut >= 0.0 && cut <= 1.0)) throw InputError("--cut must be in [0, 1]");
  if (!(link_cut >= 0.0 && link_cut <= 1.0)) throw InputError("--link-cut must be in [0, 1]");
}

std::vector<double> vertex_curvature(const Points& P) {
  const VecX angle = turning_angles(P);
  const VecX len = edge_lengths(P);
  const auto n = P.rows();
  std::vector<double> out(static_cast<size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) {
    const double voronoi = 0.5 * (len((i + n - 1) % n) + len(i));
    out[static_cast<size_t>(i)] = voronoi > 0.0 ? angle(i) / voronoi : 0.0;
  }
  return out;
}

std::vector<unsigned char> contact_edges(const Points& P, const CurveTopology& topology, double dhat) {
  std::vector<unsigned char> out(static_cast<size_t>(P.rows()), 0);
  for (const EdgePair& p : edge_pairs_within(P, topology, 1, dhat)) {
    out[static_cast<size_t>(p.a)] = 1;
    out[static_cast<size_t>(p.b)] = 1;
  }
  return out;
}

std::string knot_file_name(const std::string& name) {
  static const char* hex = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : name) {
    if (std::isalnum(c) || c == '_' || c == '-' || (c == '.' && !out.empty())) {
      out += static_cast<char>(c);
    } else {
      out += '~';
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return out.empty() ? "~" : out;
}

KnotSiteData knot_site_data(const KnotEntry& e, const std::string& file, double dhat, double cut) {
  require(little_endian(), "knot_site_data: the site's binary files are little-endian; this machine is not");
  const int m = static_cast<int>(e.equilibria.size());
  const int n = m ? static_cast<int>(e.equilibria.front().rows()) : 0;
  KnotSiteData out;
  std::vector<int> rank;
  out.distinct = static_cast<int>(clusters_at_cut(e, cut, &rank).size());

  std::string& bin = out.binary;
  Json buffers;
  // the attributes first: a float64 array at offset 0 is 8-byte aligned
  const int columns = static_cast<int>(e.attributes.cols());
  buffers["attributes"] = buffer("float64", {m, columns}, bin.size());
  for (Eigen::Index i = 0; i < e.attributes.rows(); ++i)
    for (Eigen::Index c = 0; c < e.attributes.cols(); ++c) append(bin, e.attributes(i, c));
  buffers["positions"] = buffer("float32", {m, n, 3}, bin.size());
  for (const Points& P : e.equilibria)
    for (Eigen::Index i = 0; i < P.rows(); ++i)
      for (int k = 0; k < 3; ++k) append(bin, static_cast<float>(P(i, k)));
  buffers["curvature"] = buffer("float32", {m, n}, bin.size());
  for (int i = 0; i < m; ++i)
    for (const Points& P : e.equilibrium_link(i))
      for (double k : vertex_curvature(P)) append(bin, static_cast<float>(k));
  buffers["similarity"] = buffer("float32", {m, m}, bin.size());
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) append(bin, static_cast<float>(e.similarity(i, j)));
  buffers["contact"] = buffer("uint8", {m, n}, bin.size());
  if (m > 0) {
    const CurveTopology topology = e.is_link() ? CurveTopology::from_sizes(e.components) : CurveTopology::single(n);
    for (const Points& P : e.equilibria)
      for (unsigned char c : contact_edges(P, topology, dhat)) bin += static_cast<char>(c);
  }

  Json j;
  j["format"] = std::string(kSiteFormat) + "-knot";
  j["format_version"] = kSiteFormatVersion;
  j["name"] = e.name;
  j["equilibria"] = m;
  j["vertices"] = n;
  if (e.is_link()) {
    j["components"] = e.components;  // vertices per component, back to back
    j["attribute_names"] = e.attribute_names;  // a link's own columns (link_attribute_names())
  }
  bool converged = true;
  double explained = 1.0;
  j["mds"] = mds_json(e, converged, explained);
  j["mds_converged"] = converged;
  j["mds_explained"] = number(explained);
  Json linkage = Json::array();
  for (Eigen::Index r = 0; r < e.linkage.rows(); ++r)
    linkage.push_back({static_cast<int>(e.linkage(r, 0)), static_cast<int>(e.linkage(r, 1)), number(e.linkage(r, 2)),
                       static_cast<int>(e.linkage(r, 3))});
  j["linkage"] = linkage;
  std::vector<int> leaves;
  if (m >= 2) leaves = Dendrogram::from_linkage(e.linkage).leaf_order();
  else if (m == 1) leaves = {0};
  j["leaf_order"] = leaves;
  j["cut"] = cut;
  j["cluster_rank"] = rank;
  j["distinct"] = out.distinct;
  std::vector<int> samples(static_cast<size_t>(m), -1);
  for (const RunRecord& r : e.runs)
    if (r.equilibrium >= 0 && r.equilibrium < m) samples[static_cast<size_t>(r.equilibrium)] = r.sample;
  j["sample"] = samples;
  j["binary"] = file + ".bin";
  j["buffers"] = buffers;
  j["binary_bytes"] = bin.size();
  out.json = j.dump();
  return out;
}

namespace {

/// One row of the knot table in data/site.json.
Json knot_record(const KnotEntry& e, const KnotTable& table, const std::string& file, int distinct, size_t offset) {
  const int m = static_cast<int>(e.equilibria.size());
  double lowest = std::numeric_limits<double>::infinity(), most_3d = -1.0;
  double min_tc = std::numeric_limits<double>::infinity();
  if (m) {
    const int ec = e.attribute_column("energy"), tc = e.attribute_column("threedim");
    const int kc = e.attribute_column("total_curvature");
    for (int i = 0; i < m; ++i) {
      lowest = std::min(lowest, e.attributes(i, ec));
      most_3d = std::max(most_3d, e.attributes(i, tc));
      min_tc = std::min(min_tc, e.attributes(i, kc));
    }
  }
  const KnotRecord* rec = table.find(e.name);
  Json k;
  k["name"] = e.name;
  k["file"] = file;
  k["crossing_number"] = e.crossing_number;
  k["bridge_index"] = optional_index(e.bridge_index);
  k["braid_index"] = optional_index(e.braid_index);
  const bool known = e.bridge_index > 0 && e.braid_index > 0;
  k["bb"] = known ? Json(e.bridge_index == e.braid_index) : Json(nullptr);
  k["two_bridge"] = e.bridge_index > 0 ? Json(e.bridge_index == 2) : Json(nullptr);
  k["alternating"] = rec && rec->alternating ? Json(*rec->alternating) : Json(nullptr);
  k["samples"] = e.samples_used;
  k["runs"] = e.runs.size();
  k["equilibria"] = m;
  k["distinct"] = distinct;
  k["lowest_energy"] = m ? number(lowest) : Json(nullptr);
  k["largest_threedim"] = m ? number(most_3d) : Json(nullptr);
  k["min_total_curvature"] = m ? number(min_tc) : Json(nullptr);
  k["milnor_ratio"] = m && e.bridge_index > 0 ? number(min_tc / (2.0 * kPi * e.bridge_index)) : Json(nullptr);
  k["adaptive"] = e.adaptive;
  k["complete"] = e.complete;
  k["offset"] = offset;
  return k;
}

/// A data-set parameter, null when the file does not record it (metadata.hpp).
template <class T>
Json or_null(const std::optional<T>& v) {
  return v ? Json(*v) : Json(nullptr);
}

Json dataset_json(const DatasetMetadata& meta, const std::string& path, const std::string& title) {
  Json d;
  d["file"] = std::filesystem::path(path).filename().string();
  d["title"] = title.empty() ? std::filesystem::path(path).filename().string() : title;
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
  return d;
}

void add_three(SiteFiles& files, const std::string& dir) {
  for (const char* rel : {"build/three.module.js", "examples/jsm/controls/OrbitControls.js"})
    files[std::string("three/") + rel] = slurp(dir + "/" + rel);
  const std::string copyright = "/usr/share/doc/libjs-three/copyright";
  if (std::filesystem::exists(copyright)) files["three/COPYRIGHT"] = slurp(copyright);
}

}  // namespace

SiteFiles build_site(const std::string& dataset_path, const SiteOptions& options) {
  options.validate();
  if (!std::filesystem::exists(options.three_dir + "/build/three.module.js"))
    throw InputError("three.js not found in " + options.three_dir + " (install the Debian package libjs-three)");
  DatasetReader reader(dataset_path);
  const DatasetMetadata& meta = reader.metadata();
  const KnotTable& table = KnotTable::global();
  SiteFiles files;
  Json knots = Json::array();
  std::vector<std::string> columns;
  std::string attributes;
  size_t rows = 0;
  for (const std::string& name : reader.knot_names()) {
    const KnotEntry e = reader.read(name);
    if (columns.empty() && !e.attribute_names.empty()) columns = e.attribute_names;
    if (!e.equilibria.empty() && e.attribute_names != columns)
      throw InputError(dataset_path + ": " + name + " has other attribute columns than the first entry (a site shows knots or links, not both)");
    const std::string file = knot_file_name(name);
    KnotSiteData data = knot_site_data(e, file, meta.dhat.value(), e.is_link() ? options.link_cut : options.cut);  // dhat: required, always read
    knots.push_back(knot_record(e, table, file, data.distinct, rows));
    files["data/knots/" + file + ".json"] = std::move(data.json);
    files["data/knots/" + file + ".bin"] = std::move(data.binary);
    for (Eigen::Index i = 0; i < e.attributes.rows(); ++i)
      for (Eigen::Index c = 0; c < e.attributes.cols(); ++c) append(attributes, e.attributes(i, c));
    rows += static_cast<size_t>(e.attributes.rows());
  }
  Json site;
  site["format"] = kSiteFormat;
  site["format_version"] = kSiteFormatVersion;
  site["generated_by"] = "knots site " + project_version();
  site["dataset"] = dataset_json(meta, dataset_path, options.title);
  site["cut"] = options.cut;
  site["link_cut"] = options.link_cut;
  site["attribute_names"] = columns;
  site["attributes"] = {{"file", "attributes.bin"}, {"dtype", "float64"}, {"rows", rows}, {"columns", columns.size()}};
  site["knots"] = knots;
  files["data/site.json"] = site.dump();
  files["data/attributes.bin"] = std::move(attributes);
  for (const auto& [path, content] : site_assets()) files[path] = std::string(content);
  add_three(files, options.three_dir);
  return files;
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
