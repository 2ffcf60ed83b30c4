#pragma once
/// \file
/// The data-set explorer (paper Section 7: similarity, clustering, MDS,
/// filters, cross-knot queries): a static web site written from a data-set
/// file or from ledgers (ledger.hpp: a ledger file, or a folder of them
/// merged). This module extracts everything the pages show; the pages
/// (src/site/web/, plain ES modules, no build step) only display it and
/// recluster a dendrogram at a cut the user picks.
///
/// A ledger keeps every equilibrium's attributes and the dendrogram of all
/// of them, but the curves of its lowest-energy states only and no
/// similarity matrix. A ledger's site therefore has the same knot table and
/// attribute table as its data set's (every stored equilibrium), while each
/// knot's files hold its *shown states*: the states with a kept curve, each
/// as its representative (lowest-energy member), in energy order, with the
/// similarity and dendrogram of those curves recomputed as the data-set
/// pipeline computes them (shown_states).
///
/// Site layout (docs/explorer.md documents it for users):
///
/// ~~~{.unparsed}
///   index.html, style.css, js/*.js      the pages (embedded in the program at build time)
///   three/build/three.module.js         three.js and its OrbitControls, copied from
///   three/examples/jsm/controls/...     Debian's libjs-three at run time
///   data/site.json                      format "elastic-knots-site", format_version 2:
///                                       the data set's parameters and `source`
///                                       ("dataset" or "ledger"; a ledger adds
///                                       `ledger_cut`, `curves_per_knot`), the attribute
///                                       names, one record per knot (table fields over
///                                       every stored equilibrium, Milnor ratio, distinct
///                                       states at the cut, row offset; a ledger's knot
///                                       adds `shown_rows`, the row of each shown state)
///   data/attributes.bin                 float64 little-endian [M, k]: every equilibrium's
///                                       attributes, knots in file order (M = Σ m)
///   data/knots/<file>.json              per knot, of its m shown equilibria (a ledger's:
///                                       its shown states): MDS coordinates [m, 2], linkage
///                                       [m-1, 4] (SciPy layout), dendrogram leaf order,
///                                       clusters at the cut (a ledger's knot adds
///                                       `members` [m] and `states`, its state count), and
///                                       the layout of:
///   data/knots/<file>.bin               little-endian arrays, back to back:
///                                       positions float32 [m, n, 3], curvature float32
///                                       [m, n] (turning angle / Voronoi length, 1/length),
///                                       similarity float32 [m, m], contact uint8 [m, n]
///                                       (edge i = vertex i to i+1 closer than d̂ to an
///                                       edge sharing no vertex with it)
/// ~~~
///
/// Numbers in JSON are written with 17 significant digits (exact round trip),
/// so a cut compared with the linkage heights in the page gives the same
/// clusters as `knots cluster` at that cut.
#include <map>
#include <string>
#include <vector>

#include "ek/analysis/similarity.hpp"
#include "ek/core/json.hpp"
#include "ek/contact/topology.hpp"
#include "ek/dataset/dataset_file.hpp"
#include "ek/dataset/ledger.hpp"

namespace ek {

/// Format of data/site.json and data/knots/*.json (conventions: data files carry a schema version).
inline constexpr const char* kSiteFormat = "elastic-knots-site";
inline constexpr int kSiteFormatVersion = 2;  ///< format_version of data/site.json

/// The cuts, the three.js folder and the title of build_site().
struct SiteOptions {
  /// [1] distance cut (1 - similarity) for the knot table's "distinct states"
  /// column and the initial position of each knot's cut slider (the paper
  /// experiments' cluster cut)
  double cut = 0.05;
  /// [mean component length] the same for the links of the data set, in the
  /// link state distance d (ek/analysis/link_states.hpp)
  double link_cut = 0.002;
  /// folder of Debian's libjs-three (holds build/three.module.js and
  /// examples/jsm/controls/OrbitControls.js); default: found when the program was configured
  std::string three_dir;
  /// name shown as the data set's title (default: the data-set file's name)
  std::string title;

  SiteOptions();  ///< The defaults; three_dir as found when the program was configured.
  /// Throws InputError for a cut or link cut outside [0, 1].
  void validate() const;
};

/// The site's files: path relative to the site's folder -> contents.
using SiteFiles = std::map<std::string, std::string>;

/// The data files of one knot (`data/knots/<file>.json` and `.bin`).
struct KnotSiteData {
  std::string json;    ///< `data/knots/<file>.json`
  std::string binary;  ///< `data/knots/<file>.bin`
  int distinct = 0;    ///< [1] clusters at the cut
};

/// What a ledger's site adds to a knot: which of its states the pages show
/// (those whose curve the ledger keeps).
struct ShownStates {
  std::vector<int> rows;     ///< [1] each shown state's representative: its row among the knot's equilibria
  std::vector<int> members;  ///< [1] each shown state's member count
  int states = 0;            ///< [1] the knot's states at the ledger's cut, shown or not
  /// What all its states leave unseen: unseen and unseen_low_energy of
  /// ledger_unseen() (ek/dataset/json.hpp, entry_unseen_json()'s keys).
  Json unseen;
};

/// Extracts one knot's data files from the equilibria its pages show
/// (`file` is the base name of both files, `dhat` [length] the contact
/// distance of the contact flags, `cut` the clusters' cut). `states`: a
/// ledger's shown states (one member count per equilibrium of `entry`,
/// written as `members` and `states`); null for a data set. Both write
/// `unseen` and `unseen_low_energy`: the ledger's, or the entry's at `cut`.
KnotSiteData knot_site_data(const KnotEntry& entry, const std::string& file, double dhat, double cut,
                            const ShownStates* states = nullptr);

/// The shown states of a ledger entry as a knot entry: the states with a
/// kept curve, in the ledger's (energy) order, each its representative's
/// curve and attribute row; the runs with `equilibrium` renumbered to them
/// (-1 for the other rows); similarity and linkage recomputed by
/// cluster_entry (pipeline.hpp) with `similarity` (the data set's
/// comparison: options_for_knot). `shown` (optional) receives their rows and
/// member counts.
KnotEntry shown_states(const LedgerEntry& entry, const SimilarityOptions& similarity, ShownStates* shown = nullptr);

/// Per-vertex curvature of a closed polygon: turning angle at vertex i over
/// its Voronoi length (half the two edges), [1/length]; length n.
std::vector<double> vertex_curvature(const Points& P);

/// Per-edge contact flags of closed polygons (one, or a link's components
/// back to back as `topology` says): edge i (vertex i to the next vertex of
/// its component) is closer than dhat to an edge sharing no vertex with it,
/// on any component; length n.
std::vector<unsigned char> contact_edges(const Points& P, const CurveTopology& topology, double dhat);
/// The one-polygon case.
inline std::vector<unsigned char> contact_edges(const Points& P, double dhat) {
  return contact_edges(P, CurveTopology::single(static_cast<int>(P.rows())), dhat);
}

/// The base file name of a knot's data files: the name when it consists of
/// [A-Za-z0-9_.-] (every KnotInfo name), otherwise those characters with every
/// other byte written as "~XX" (hex).
std::string knot_file_name(const std::string& name);

/// Every file of the site of the data set, ledger file or folder of ledgers
/// at `path` (is_ledger_source): the data files, the pages and three.js.
/// Throws InputError for a file that is neither a data set nor a ledger, a
/// damaged one, ledgers that do not merge (merge_ledgers), a missing
/// three.js, and an unknown knot table (the table gives the "alternating"
/// column).
SiteFiles build_site(const std::string& path, const SiteOptions& options);

/// Writes `files` into the folder `dir`, crash-safe: into "<dir>.tmp.<pid>",
/// then renamed onto `dir`. `dir` may be missing or empty; a folder holding
/// other files is an InputError unless `overwrite`, and even then only a
/// folder that a previous `knots site` wrote (it holds data/site.json of
/// this format) is replaced, so no other folder is ever removed. Nothing is
/// written when the check fails.
void write_site(const SiteFiles& files, const std::string& dir, bool overwrite);

/// Throws InputError unless `dir` could be written by write_site (the checks
/// above), without writing anything; called before the work.
void check_site_folder(const std::string& dir, bool overwrite);

/// The Content-Type of a site file by its extension.
std::string content_type(const std::string& path);

}  // namespace ek
