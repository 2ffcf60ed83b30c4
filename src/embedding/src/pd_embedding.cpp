#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "common.hpp"
#include "ek/core/errors.hpp"
#include "ek/geometry/link.hpp"
#include "ek/knots/alexander.hpp"
#include "ek/knots/invariants.hpp"

namespace ek {
namespace {

struct Dart {
  int crossing, slot;
};

/// The plane graph of a PD drawing: the two darts of every edge label, and
/// the faces traced from the rotation system.
struct PlaneGraph {
  const PDCode* pd = nullptr;
  std::vector<std::vector<Dart>> where;  // where[label] = the two (crossing, slot) occurrences of the label
  std::vector<std::vector<Dart>> faces;

  int label(Dart d) const { return pd->crossings[static_cast<size_t>(d.crossing)].e[static_cast<size_t>(d.slot)]; }
  Dart partner(Dart d) const {
    const auto& w = where[static_cast<size_t>(label(d))];
    return (w[0].crossing == d.crossing && w[0].slot == d.slot) ? w[1] : w[0];
  }
};

/// Node numbering of the Tutte graph: crossings [0, c), edge midpoints
/// [c, c + m), face centres [c + m, c + m + F).
struct TutteNodes {
  int c, m, F;
  int mid(int lab) const { return c + lab - 1; }
  int face(int f) const { return c + m + f; }
  int count() const { return c + m + F; }
};

/// A Tutte layout in progress: positions, the pinned nodes (1: on the unit
/// circle, 2: removed) and the free nodes' unknown indices.
struct TutteLayout {
  std::vector<Vec2> pos;
  std::vector<int> fixed;
  std::vector<int> index;  // -1 for pinned and removed nodes
  int nfree = 0;
};

using WeightedAdjacency = std::vector<std::vector<std::pair<int, double>>>;

struct Corner {
  Vec2 p;
  double z;
};

PlaneGraph plane_graph(const PDCode& pd) {
  const int c = pd.size(), m = 2 * c;
  PlaneGraph g;
  g.pd = &pd;
  g.where.resize(static_cast<size_t>(m + 1));
  for (int x = 0; x < c; ++x)
    for (int k = 0; k < 4; ++k) g.where[static_cast<size_t>(g.label({x, k}))].push_back({x, k});
  // Faces of the plane graph from the rotation system (slots are counterclockwise).
  std::vector<char> used(static_cast<size_t>(4 * c), 0);
  for (int x = 0; x < c; ++x)
    for (int k = 0; k < 4; ++k) {
      if (used[static_cast<size_t>(4 * x + k)]) continue;
      std::vector<Dart> face;
      Dart d{x, k};
      while (!used[static_cast<size_t>(4 * d.crossing + d.slot)]) {
        used[static_cast<size_t>(4 * d.crossing + d.slot)] = 1;
        face.push_back(d);
        const Dart p = g.partner(d);
        d = {p.crossing, (p.slot + 1) % 4};
      }
      g.faces.push_back(std::move(face));
    }
  const int F = static_cast<int>(g.faces.size());
  if (F != c + 2)
    throw InputError("PD code " + to_string(pd) + ": its diagram is not planar (Euler characteristic " +
                     std::to_string(c - m + F) + " instead of 2)");
  return g;
}

/// Edges of the Tutte graph: crossing - midpoint along the knot, face centre -
/// corner and face centre - midpoint around every face; throws for the
/// nugatory crossings that make an edge a loop or a face meet a crossing twice.
std::vector<std::set<int>> tutte_adjacency(const PlaneGraph& g, const TutteNodes& nodes) {
  const PDCode& pd = *g.pd;
  std::vector<std::set<int>> adj(static_cast<size_t>(nodes.count()));
  auto link = [&](int a, int b) {
    if (a == b) throw InputError("PD code " + to_string(pd) + ": has a nugatory crossing (a loop edge)");
    adj[static_cast<size_t>(a)].insert(b);
    adj[static_cast<size_t>(b)].insert(a);
  };
  for (int x = 0; x < nodes.c; ++x)
    for (int k = 0; k < 4; ++k) link(x, nodes.mid(pd.crossings[static_cast<size_t>(x)].e[static_cast<size_t>(k)]));
  for (int f = 0; f < nodes.F; ++f) {
    std::set<int> corners;
    for (const Dart& d : g.faces[static_cast<size_t>(f)]) {
      if (!corners.insert(d.crossing).second)
        throw InputError("PD code " + to_string(pd) + ": has a nugatory crossing (a face meets crossing " +
                         std::to_string(d.crossing + 1) + " twice)");
      link(nodes.face(f), d.crossing);
      link(nodes.face(f), nodes.mid(g.label(d)));
    }
  }
  return adj;
}

/// Outer face: the largest; its boundary nodes go on the unit circle in
/// order, its centre is removed, every other node is free.
TutteLayout pin_outer_face(const PlaneGraph& g, const TutteNodes& nodes) {
  int outer = 0;
  for (int f = 1; f < nodes.F; ++f)
    if (g.faces[static_cast<size_t>(f)].size() > g.faces[static_cast<size_t>(outer)].size()) outer = f;
  std::vector<int> boundary;
  for (const Dart& d : g.faces[static_cast<size_t>(outer)]) {
    boundary.push_back(d.crossing);
    boundary.push_back(nodes.mid(g.label(d)));
  }
  const int N = nodes.count();
  TutteLayout L;
  L.pos.assign(static_cast<size_t>(N), Vec2::Zero());
  L.fixed.assign(static_cast<size_t>(N), 0);
  L.fixed[static_cast<size_t>(nodes.face(outer))] = 2;  // removed
  for (size_t k = 0; k < boundary.size(); ++k) {
    const double a = 2.0 * M_PI * static_cast<double>(k) / static_cast<double>(boundary.size());
    L.pos[static_cast<size_t>(boundary[k])] = Vec2(std::cos(a), std::sin(a));
    L.fixed[static_cast<size_t>(boundary[k])] = 1;
  }
  L.index.assign(static_cast<size_t>(N), -1);
  for (int v = 0; v < N; ++v)
    if (!L.fixed[static_cast<size_t>(v)]) L.index[static_cast<size_t>(v)] = L.nfree++;
  return L;
}

/// Multiplies every edge weight by its current length over the mean length
/// (clamped to [0.2, 5]), keeping the weights symmetric.
void reweight_by_length(WeightedAdjacency& wadj, const std::vector<Vec2>& pos) {
  const int N = static_cast<int>(wadj.size());
  double mean = 0.0;
  int count = 0;
  for (int v = 0; v < N; ++v)
    for (auto& [w, weight] : wadj[static_cast<size_t>(v)]) {
      mean += (pos[static_cast<size_t>(v)] - pos[static_cast<size_t>(w)]).norm();
      ++count;
    }
  mean /= std::max(count, 1);
  for (int v = 0; v < N; ++v)
    for (auto& [w, weight] : wadj[static_cast<size_t>(v)])
      weight *= std::clamp((pos[static_cast<size_t>(v)] - pos[static_cast<size_t>(w)]).norm() / mean, 0.2, 5.0);
  // keep the weights symmetric
  for (int v = 0; v < N; ++v)
    for (auto& [w, weight] : wadj[static_cast<size_t>(v)])
      for (auto& [x, wx] : wadj[static_cast<size_t>(w)])
        if (x == v && w > v) wx = weight;
}

/// Moves every free node to the weighted mean of its neighbours (one sparse
/// solve of the weighted graph Laplacian with the pinned nodes on the right).
void solve_tutte(const WeightedAdjacency& wadj, TutteLayout& L) {
  const int N = static_cast<int>(wadj.size());
  std::vector<Eigen::Triplet<double>> trip;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(L.nfree, 2);
  for (int v = 0; v < N; ++v) {
    const int i = L.index[static_cast<size_t>(v)];
    if (i < 0) continue;
    double deg = 0.0;
    for (auto [w, weight] : wadj[static_cast<size_t>(v)]) {
      deg += weight;
      if (L.fixed[static_cast<size_t>(w)] == 1)
        rhs.row(i) += weight * L.pos[static_cast<size_t>(w)].transpose();
      else
        trip.emplace_back(i, L.index[static_cast<size_t>(w)], -weight);
    }
    trip.emplace_back(i, i, deg);
  }
  Eigen::SparseMatrix<double> A(L.nfree, L.nfree);
  A.setFromTriplets(trip.begin(), trip.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
  require(solver.info() == Eigen::Success, "PD embedding: Tutte system is singular");
  const Eigen::MatrixXd X = solver.solve(rhs);
  for (int v = 0; v < N; ++v)
    if (L.index[static_cast<size_t>(v)] >= 0)
      L.pos[static_cast<size_t>(v)] = X.row(L.index[static_cast<size_t>(v)]).transpose();
}

/// Tutte's barycentric embedding is planar with convex faces for any positive
/// edge weights (Floater 1997). Uniform weights crowd the inner nodes
/// exponentially; reweighting every edge by its current length (repeatedly)
/// spreads them out, which keeps the resampled polygon faithful. The removed
/// outer face node is not a neighbour.
void tutte_layout(const std::vector<std::set<int>>& adj, TutteLayout& L, int rounds) {
  const int N = static_cast<int>(adj.size());
  WeightedAdjacency wadj(static_cast<size_t>(N));
  for (int v = 0; v < N; ++v)
    for (int w : adj[static_cast<size_t>(v)])
      if (L.fixed[static_cast<size_t>(w)] != 2) wadj[static_cast<size_t>(v)].emplace_back(w, 1.0);
  for (int round = 0; round <= rounds && L.nfree > 0; ++round) {
    if (round > 0) reweight_by_length(wadj, L.pos);
    solve_tutte(wadj, L);
  }
}

/// One component's corners in order: edge e leaves crossing s(e) and
/// enters t(e) = s(e + 1); it runs s(e) -> midpoint(e), at height +1 at s(e)
/// when the strand is over there (e is the over strand's head), -1 under, 0
/// at the midpoint. `range` is the component's labels [first, last] and
/// over_in[i] the over strand's incoming label at crossing i.
std::vector<Corner> component_corners(const PlaneGraph& g, const TutteNodes& nodes, const std::vector<Vec2>& pos,
                                      const std::array<int, 2>& range, const std::vector<int>& over_in) {
  std::vector<Corner> corners;
  for (int e = range[0]; e <= range[1]; ++e) {
    // the crossing where e is outgoing: slot 2 (under) or the over strand's head
    int from = -1;
    bool over = false;
    for (const Dart& d : g.where[static_cast<size_t>(e)]) {
      const bool over_head = (d.slot == 1 || d.slot == 3) && over_in[static_cast<size_t>(d.crossing)] != e;
      if (d.slot == 2 || over_head) {
        from = d.crossing;
        over = (d.slot != 2);
      }
    }
    require(from >= 0, "PD embedding: edge without a tail (code not validated)");
    corners.push_back({pos[static_cast<size_t>(from)], over ? 1.0 : -1.0});
    corners.push_back({pos[static_cast<size_t>(nodes.mid(e))], 0.0});
  }
  return corners;
}

/// Control polygon: crossings at ±h, midpoints at 0. The crossing height h is
/// a fraction of the shortest piece, but at least about one output edge so
/// that the resampled polygon keeps the strands apart.
std::vector<Vec3> control_polygon(const std::vector<Corner>& corners, const EmbeddingOptions& o) {
  double shortest = 1e300;
  for (size_t k = 0; k < corners.size(); ++k)
    shortest = std::min(shortest, (corners[(k + 1) % corners.size()].p - corners[k].p).norm());
  require_input(shortest > 1e-12, "PD embedding: degenerate drawing");
  double planar_length = 0.0;
  for (size_t k = 0; k < corners.size(); ++k) planar_length += (corners[(k + 1) % corners.size()].p - corners[k].p).norm();
  const double h = std::max(o.pd_crossing_height * shortest, o.pd_min_crossing_height * planar_length / o.vertices);
  std::vector<Vec3> ctrl;
  for (const Corner& q : corners) ctrl.emplace_back(q.p.x(), q.p.y(), q.z * h);
  return ctrl;
}

/// Chaikin corner cutting rounds the polygon's corners (so that the
/// equal-chord resampling sees a smooth curve); each round replaces an edge PQ
/// by the points 3/4 P + 1/4 Q and 1/4 P + 3/4 Q, staying inside the triangles
/// of consecutive corners.
void chaikin(std::vector<Vec3>& ctrl, int rounds) {
  for (int round = 0; round < rounds; ++round) {
    std::vector<Vec3> next;
    next.reserve(2 * ctrl.size());
    for (size_t k = 0; k < ctrl.size(); ++k) {
      const Vec3& a = ctrl[k];
      const Vec3& b = ctrl[(k + 1) % ctrl.size()];
      next.push_back(0.75 * a + 0.25 * b);
      next.push_back(0.25 * a + 0.75 * b);
    }
    ctrl.swap(next);
  }
}

/// K equally spaced points on every edge of the closed polygon, from its start.
Points dense_samples(const std::vector<Vec3>& ctrl, int K) {
  Points dense(static_cast<Eigen::Index>(ctrl.size()) * K, 3);
  for (size_t k = 0; k < ctrl.size(); ++k)
    for (int s = 0; s < K; ++s) {
      const double u = static_cast<double>(s) / K;
      dense.row(static_cast<Eigen::Index>(k) * K + s) = ((1.0 - u) * ctrl[k] + u * ctrl[(k + 1) % ctrl.size()]).transpose();
    }
  return dense;
}

/// The dense 3D curves of the PD drawing after `rounds` Tutte
/// reweightings, one per component (label ranges of `pd`).
std::vector<Points> pd_dense_curves(const PDLinkCode& pd, const EmbeddingOptions& o, int rounds) {
  const int c = pd.code.size();
  require_input(c >= 1, "PD embedding: empty code");
  const PlaneGraph g = plane_graph(pd.code);
  const TutteNodes nodes{c, 2 * c, static_cast<int>(g.faces.size())};
  const std::vector<std::set<int>> adj = tutte_adjacency(g, nodes);
  TutteLayout layout = pin_outer_face(g, nodes);
  tutte_layout(adj, layout, rounds);
  std::vector<Points> out;
  for (const auto& range : pd.components) {
    std::vector<Vec3> ctrl = control_polygon(component_corners(g, nodes, layout.pos, range, pd.over_in), o);
    chaikin(ctrl, 3);
    out.push_back(dense_samples(ctrl, o.samples_per_piece));
  }
  return out;
}

/// A knot's code as a one-component link code (its over strands ordered by PDCrossing::sign).
PDLinkCode knot_code(const PDCode& pd) {
  PDLinkCode out;
  out.code = pd;
  out.components = {{1, 2 * pd.size()}};
  for (const PDCrossing& x : pd.crossings) out.over_in.push_back(x.sign(2 * pd.size()) > 0 ? x.e[3] : x.e[1]);
  return out;
}

/// The first of `attempts` (Tutte reweighting rounds) that `finish` accepts,
/// or the best by `score` when one is good enough.
template <class Result, class Finish, class Score>
Result best_drawing(const std::vector<int>& attempts, Finish finish, Score score, double good) {
  std::optional<Result> best;
  std::string last_error;
  for (int rounds : attempts) {
    try {
      Result r = finish(rounds);
      if (!best || score(r) > score(*best)) best = std::move(r);
      if (score(*best) > good) break;
    } catch (const InputError& err) {
      last_error = err.what();
    }
  }
  if (!best) throw InputError(last_error);
  return *best;
}

}  // namespace

Embedding embed_pd(const PDCode& pd, const EmbeddingOptions& o) {
  validate(o);
  const AlexanderPolynomial expected = alexander(pd);
  const PDLinkCode code = knot_code(pd);
  const auto finish = [&](int rounds) {
    return finish_embedding(pd_dense_curves(code, o, rounds).front(), o, EmbeddingMethod::PD, &expected);
  };
  if (!o.verify) return finish(o.pd_reweighting_rounds);
  // The resampled polygon can miss the drawing's tightest places when n is
  // small; try a few reweightings and keep the valid one with most clearance.
  return best_drawing<Embedding>({o.pd_reweighting_rounds, 1, 3, 0, 4, 6}, finish,
                                 [](const Embedding& e) { return e.clearance; }, 0.5 * o.edge_length);
}

LinkEmbedding embed_pd_link(const PDLinkCode& pd, const EmbeddingOptions& o) {
  validate(o);
  require_input(pd.components.size() >= 2, "PD embedding: the code has one component (a knot: use embed_pd)");
  const LinkType expected = link_type(link_diagram_from_pd(pd));
  const auto finish = [&](int rounds) {
    LinkEmbedding e = finish_link_embedding(pd_dense_curves(pd, o, rounds), o, "PD embedding");
    e.linking_numbers = expected.linking_numbers;
    if (o.verify && link_type(e.components) != expected)
      throw InputError("PD embedding with " + std::to_string(o.vertices) +
                       " vertices does not keep the code's link type; use more vertices");
    return e;
  };
  if (!o.verify) return finish(o.pd_reweighting_rounds);
  return best_drawing<LinkEmbedding>({o.pd_reweighting_rounds, 1, 3, 0, 4, 6}, finish,
                                     [](const LinkEmbedding& e) { return validate_link(e.components, "PD embedding"); },
                                     0.5 * o.edge_length);
}

}  // namespace ek
