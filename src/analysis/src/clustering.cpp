#include "ek/analysis/clustering.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "ek/core/errors.hpp"

namespace ek {

namespace {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(static_cast<size_t>(n)) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[static_cast<size_t>(x)] != x) {
      parent[static_cast<size_t>(x)] = parent[static_cast<size_t>(parent[static_cast<size_t>(x)])];
      x = parent[static_cast<size_t>(x)];
    }
    return x;
  }
};

}  // namespace

Dendrogram complete_linkage(const Eigen::MatrixXd& D) {
  const int N = static_cast<int>(D.rows());
  require(N >= 1 && D.cols() == N, "complete_linkage: a square distance matrix with N >= 1 expected");
  require(D.allFinite(), "complete_linkage: non-finite distances");
  const double scale = D.cwiseAbs().maxCoeff();
  require((D - D.transpose()).cwiseAbs().maxCoeff() <= 1e-9 * scale, "complete_linkage: the distance matrix is not symmetric");

  // Working copy, symmetric, from the strict upper triangle.
  Eigen::MatrixXd d(N, N);
  for (int i = 0; i < N; ++i) {
    d(i, i) = 0.0;
    for (int j = i + 1; j < N; ++j) d(i, j) = d(j, i) = D(i, j);
  }
  std::vector<char> active(static_cast<size_t>(N), 1);
  std::vector<int> size(static_cast<size_t>(N), 1);
  struct Raw {
    int a, b;  // representative leaves (slots) of the merged clusters
    double h;
  };
  std::vector<Raw> raw;
  raw.reserve(static_cast<size_t>(std::max(N - 1, 0)));
  std::vector<int> chain;
  chain.reserve(static_cast<size_t>(N));
  int remaining = N;
  while (remaining > 1) {
    if (chain.empty()) {
      for (int i = 0; i < N; ++i)
        if (active[static_cast<size_t>(i)]) {
          chain.push_back(i);
          break;
        }
    }
    for (;;) {
      const int x = chain.back();
      const int prev = chain.size() >= 2 ? chain[chain.size() - 2] : -1;
      // nearest active neighbour of x; ties: prefer the previous chain element, then the lowest index
      int y = -1;
      double best = std::numeric_limits<double>::infinity();
      if (prev >= 0) {
        y = prev;
        best = d(x, prev);
      }
      for (int k = 0; k < N; ++k) {
        if (k == x || !active[static_cast<size_t>(k)]) continue;
        if (d(x, k) < best) {
          best = d(x, k);
          y = k;
        }
      }
      if (y == prev) {  // reciprocal nearest neighbours: merge x and y
        chain.pop_back();
        chain.pop_back();
        const int keep = std::min(x, y), gone = std::max(x, y);
        raw.push_back({keep, gone, best});
        for (int k = 0; k < N; ++k) {
          if (!active[static_cast<size_t>(k)] || k == keep || k == gone) continue;
          const double v = std::max(d(keep, k), d(gone, k));
          d(keep, k) = d(k, keep) = v;
        }
        active[static_cast<size_t>(gone)] = 0;
        size[static_cast<size_t>(keep)] += size[static_cast<size_t>(gone)];
        --remaining;
        break;
      }
      chain.push_back(y);
    }
  }

  // Sort merges by height (stable: ties keep their discovery order) and relabel
  // the clusters SciPy-style with a union-find over the leaf slots.
  std::vector<size_t> order(raw.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](size_t p, size_t q) { return raw[p].h < raw[q].h; });
  Dendrogram out;
  out.leaves = N;
  UnionFind uf(N);
  std::vector<int> cluster_id(static_cast<size_t>(N));  // by union-find root
  std::vector<int> cluster_size(static_cast<size_t>(N), 1);
  std::iota(cluster_id.begin(), cluster_id.end(), 0);
  for (size_t k = 0; k < order.size(); ++k) {
    const Raw& m = raw[order[k]];
    const int ra = uf.find(m.a), rb = uf.find(m.b);
    const int ida = cluster_id[static_cast<size_t>(ra)], idb = cluster_id[static_cast<size_t>(rb)];
    Merge merge;
    merge.a = std::min(ida, idb);
    merge.b = std::max(ida, idb);
    merge.height = m.h;
    merge.size = cluster_size[static_cast<size_t>(ra)] + cluster_size[static_cast<size_t>(rb)];
    out.merges.push_back(merge);
    uf.parent[static_cast<size_t>(rb)] = ra;
    cluster_id[static_cast<size_t>(ra)] = N + static_cast<int>(k);
    cluster_size[static_cast<size_t>(ra)] = merge.size;
  }
  return out;
}

Dendrogram complete_linkage_from_similarity(const Eigen::MatrixXd& similarity) {
  require(similarity.rows() == similarity.cols(), "complete_linkage_from_similarity: a square matrix expected");
  Eigen::MatrixXd D = Eigen::MatrixXd::Ones(similarity.rows(), similarity.cols()) - similarity;
  D.diagonal().setZero();
  return complete_linkage(D);
}

Dendrogram Dendrogram::from_linkage(const Eigen::MatrixXd& linkage) {
  require(linkage.rows() == 0 || linkage.cols() == 4, "Dendrogram::from_linkage: expected 4 columns");
  Dendrogram d;
  d.leaves = static_cast<int>(linkage.rows()) + 1;
  for (Eigen::Index k = 0; k < linkage.rows(); ++k) {
    Merge m{static_cast<int>(linkage(k, 0)), static_cast<int>(linkage(k, 1)), linkage(k, 2),
            static_cast<int>(linkage(k, 3))};
    require(m.a >= 0 && m.b > m.a && m.b < d.leaves + static_cast<int>(k), "Dendrogram::from_linkage: bad merge");
    d.merges.push_back(m);
  }
  return d;
}

Eigen::MatrixXd Dendrogram::linkage_matrix() const {
  Eigen::MatrixXd Z(static_cast<Eigen::Index>(merges.size()), 4);
  for (size_t k = 0; k < merges.size(); ++k) {
    const auto r = static_cast<Eigen::Index>(k);
    Z(r, 0) = merges[k].a;
    Z(r, 1) = merges[k].b;
    Z(r, 2) = merges[k].height;
    Z(r, 3) = merges[k].size;
  }
  return Z;
}

std::vector<int> Dendrogram::leaf_order() const {
  std::vector<int> order;
  if (leaves == 0) return order;
  if (merges.empty()) return {0};
  std::vector<int> stack = {leaves + static_cast<int>(merges.size()) - 1};
  while (!stack.empty()) {
    const int c = stack.back();
    stack.pop_back();
    if (c < leaves) {
      order.push_back(c);
      continue;
    }
    const Merge& m = merges[static_cast<size_t>(c - leaves)];
    stack.push_back(m.b);  // b is visited after a
    stack.push_back(m.a);
  }
  return order;
}

std::vector<int> cut_dendrogram(const Dendrogram& dendrogram, double threshold) {
  const int N = dendrogram.leaves;
  require(static_cast<int>(dendrogram.merges.size()) == std::max(N - 1, 0), "cut_dendrogram: malformed dendrogram");
  require(!std::isnan(threshold), "cut_dendrogram: threshold is NaN");
  // a representative leaf per cluster id, then union the leaves of applied merges
  std::vector<int> rep(static_cast<size_t>(N + std::max(N - 1, 0)));
  for (int i = 0; i < N; ++i) rep[static_cast<size_t>(i)] = i;
  UnionFind uf(N);
  for (size_t k = 0; k < dendrogram.merges.size(); ++k) {
    const Merge& m = dendrogram.merges[k];
    const int ra = rep[static_cast<size_t>(m.a)], rb = rep[static_cast<size_t>(m.b)];
    rep[static_cast<size_t>(N) + k] = ra;
    if (m.height <= threshold) uf.parent[static_cast<size_t>(uf.find(rb))] = uf.find(ra);
  }
  std::vector<int> label(static_cast<size_t>(N), -1), root_label(static_cast<size_t>(N), -1);
  int next = 0;
  for (int i = 0; i < N; ++i) {
    const int r = uf.find(i);
    if (root_label[static_cast<size_t>(r)] < 0) root_label[static_cast<size_t>(r)] = next++;
    label[static_cast<size_t>(i)] = root_label[static_cast<size_t>(r)];
  }
  return label;
}

int cluster_count(const Dendrogram& dendrogram, double threshold) {
  const std::vector<int> labels = cut_dendrogram(dendrogram, threshold);
  return labels.empty() ? 0 : 1 + *std::max_element(labels.begin(), labels.end());
}

Eigen::MatrixXd cophenetic_distances(const Dendrogram& dendrogram) {
  const int N = dendrogram.leaves;
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(N, N);
  std::vector<std::vector<int>> members(static_cast<size_t>(N + std::max(N - 1, 0)));
  for (int i = 0; i < N; ++i) members[static_cast<size_t>(i)] = {i};
  for (size_t k = 0; k < dendrogram.merges.size(); ++k) {
    const Merge& m = dendrogram.merges[k];
    auto& A = members[static_cast<size_t>(m.a)];
    auto& B = members[static_cast<size_t>(m.b)];
    for (int i : A)
      for (int j : B) C(i, j) = C(j, i) = m.height;
    auto& M = members[static_cast<size_t>(N) + k];
    M = std::move(A);
    M.insert(M.end(), B.begin(), B.end());
    B.clear();
  }
  return C;
}

}  // namespace ek
