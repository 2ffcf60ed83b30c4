// The data files of one knot of the explorer site (site.hpp): knot_site_data
// and what it computes per vertex, and the shown states of a ledger entry.
#include <algorithm>
#include <cctype>
#include <cstdint>

#include "ek/analysis/clustering.hpp"
#include "ek/analysis/mds.hpp"
#include "ek/contact/broad_phase.hpp"
#include "ek/core/errors.hpp"
#include "ek/analysis/unseen.hpp"
#include "ek/dataset/json.hpp"
#include "ek/dataset/pipeline.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/site/site.hpp"
#include "site_internal.hpp"

namespace ek {
namespace {

using site_detail::append;
using site_detail::Json;
using site_detail::number;

bool little_endian() {
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

/// A knot's binary file, array after array, with the layout of each in `buffers`.
struct BinaryFile {
  std::string bytes;
  Json buffers;
  void start(const char* name, const std::string& dtype, std::vector<int> shape) {
    buffers[name] = Json{{"dtype", dtype}, {"shape", std::move(shape)}, {"offset", bytes.size()}};
  }
};

/// The arrays of data/knots/<file>.bin (site.hpp), the attributes first: a
/// float64 array at offset 0 is 8-byte aligned.
BinaryFile knot_binary(const KnotEntry& e, double dhat) {
  const int m = static_cast<int>(e.equilibria.size());
  const int n = m ? static_cast<int>(e.equilibria.front().rows()) : 0;
  BinaryFile f;
  f.start("attributes", "float64", {m, static_cast<int>(e.attributes.cols())});
  for (Eigen::Index i = 0; i < e.attributes.rows(); ++i)
    for (Eigen::Index c = 0; c < e.attributes.cols(); ++c) append(f.bytes, e.attributes(i, c));
  f.start("positions", "float32", {m, n, 3});
  for (const Points& P : e.equilibria)
    for (Eigen::Index i = 0; i < P.rows(); ++i)
      for (int k = 0; k < 3; ++k) append(f.bytes, static_cast<float>(P(i, k)));
  f.start("curvature", "float32", {m, n});
  for (int i = 0; i < m; ++i)
    for (const Points& P : e.equilibrium_link(i))
      for (double k : vertex_curvature(P)) append(f.bytes, static_cast<float>(k));
  f.start("similarity", "float32", {m, m});
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) append(f.bytes, static_cast<float>(e.similarity(i, j)));
  f.start("contact", "uint8", {m, n});
  if (m > 0) {
    const CurveTopology topology = e.is_link() ? CurveTopology::from_sizes(e.components) : CurveTopology::single(n);
    for (const Points& P : e.equilibria)
      for (unsigned char c : contact_edges(P, topology, dhat)) f.bytes += static_cast<char>(c);
  }
  return f;
}

/// MDS coordinates [m, 2] of 1 - similarity (1D for two equilibria, the
/// origin for one), into j["mds"], j["mds_converged"], j["mds_explained"].
void add_mds(Json& j, const KnotEntry& e) {
  const auto m = static_cast<int>(e.equilibria.size());
  bool converged = true;
  double explained = 1.0;
  Eigen::MatrixXd X = Eigen::MatrixXd::Zero(m, 2);
  if (m >= 2) {
    const MdsResult r = classical_mds_from_similarity(e.similarity, std::min(2, m - 1));
    X.leftCols(r.coordinates.cols()) = r.coordinates;
    converged = r.status == MdsStatus::Converged;
    explained = r.explained;
  }
  Json out = Json::array();
  for (int i = 0; i < m; ++i) out.push_back({number(X(i, 0)), number(X(i, 1))});
  j["mds"] = out;
  j["mds_converged"] = converged;
  j["mds_explained"] = number(explained);
}

/// The linkage, its leaf order and the clusters at `cut` into `j`; returns their count.
int add_clusters(Json& j, const KnotEntry& e, double cut) {
  const int m = static_cast<int>(e.equilibria.size());
  Json linkage = Json::array();
  for (Eigen::Index r = 0; r < e.linkage.rows(); ++r)
    linkage.push_back({static_cast<int>(e.linkage(r, 0)), static_cast<int>(e.linkage(r, 1)), number(e.linkage(r, 2)),
                       static_cast<int>(e.linkage(r, 3))});
  j["linkage"] = linkage;
  std::vector<int> leaves;
  if (m >= 2) leaves = Dendrogram::from_linkage(e.linkage).leaf_order();
  else if (m == 1) leaves = {0};
  j["leaf_order"] = leaves;
  std::vector<int> rank;
  const int distinct = static_cast<int>(clusters_at_cut(e, cut, &rank).size());
  j["cut"] = cut;
  j["cluster_rank"] = rank;
  j["distinct"] = distinct;
  return distinct;
}

/// The sample each equilibrium came from (-1: no run names it).
std::vector<int> equilibrium_samples(const KnotEntry& e) {
  const int m = static_cast<int>(e.equilibria.size());
  std::vector<int> samples(static_cast<size_t>(m), -1);
  for (const RunRecord& r : e.runs)
    if (r.equilibrium >= 0 && r.equilibrium < m) samples[static_cast<size_t>(r.equilibrium)] = r.sample;
  return samples;
}

}  // namespace

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

KnotSiteData knot_site_data(const KnotEntry& e, const std::string& file, double dhat, double cut,
                            const ShownStates* states) {
  require(little_endian(), "knot_site_data: the site's binary files are little-endian; this machine is not");
  const int m = static_cast<int>(e.equilibria.size());
  require(!states || states->members.size() == static_cast<size_t>(m),
          "knot_site_data: one member count per shown state");
  KnotSiteData out;
  BinaryFile bin = knot_binary(e, dhat);
  Json j;
  j["format"] = std::string(kSiteFormat) + "-knot";
  j["format_version"] = kSiteFormatVersion;
  j["name"] = e.name;
  j["equilibria"] = m;
  j["vertices"] = m ? static_cast<int>(e.equilibria.front().rows()) : 0;
  if (e.is_link()) {
    j["components"] = e.components;  // vertices per component, back to back
    j["attribute_names"] = e.attribute_names;  // a link's own columns (link_attribute_names())
  }
  add_mds(j, e);
  out.distinct = add_clusters(j, e, cut);
  j["sample"] = equilibrium_samples(e);
  if (states) {
    j["members"] = states->members;
    j["states"] = states->states;
  }
  j.update(states ? states->unseen : entry_unseen_json(e, cut));
  j["binary"] = file + ".bin";
  j["buffers"] = bin.buffers;
  j["binary_bytes"] = bin.bytes.size();
  out.json = j.dump();
  out.binary = std::move(bin.bytes);
  return out;
}

KnotEntry shown_states(const LedgerEntry& l, const SimilarityOptions& similarity, ShownStates* shown) {
  KnotEntry e;
  static_cast<KnotHeader&>(e) = l;
  e.attribute_names = l.attribute_names;
  ShownStates s;
  s.states = static_cast<int>(l.states.size());
  s.unseen = {{"unseen", unseen_json(ledger_unseen(l))},
              {"unseen_low_energy", unseen_json(ledger_unseen(l, kLowEnergyFactor))}};
  for (const LedgerState& st : l.states) {
    if (st.curve.rows() == 0) continue;
    s.rows.push_back(st.representative);
    s.members.push_back(st.members);
    e.equilibria.push_back(st.curve);
  }
  const auto m = static_cast<Eigen::Index>(s.rows.size());
  e.attributes.resize(m, l.attributes.cols());
  std::vector<int> index(static_cast<size_t>(l.equilibria()), -1);  // ledger row -> shown index
  for (Eigen::Index i = 0; i < m; ++i) {
    e.attributes.row(i) = l.attributes.row(s.rows[static_cast<size_t>(i)]);
    index[static_cast<size_t>(s.rows[static_cast<size_t>(i)])] = static_cast<int>(i);
  }
  for (const LedgerRun& r : l.runs) {
    RunRecord run;
    run.sample = r.sample;
    run.status = r.status;
    run.equilibrium = r.equilibrium >= 0 ? index[static_cast<size_t>(r.equilibrium)] : -1;
    run.iterations = r.iterations;
    run.seconds = r.seconds;
    run.topology_preserved = r.topology_kept;
    e.runs.push_back(run);
  }
  cluster_entry(e, similarity);
  if (shown) *shown = std::move(s);
  return e;
}

}  // namespace ek
