// analysis: curvature-torsion similarity, clustering, MDS and attributes (paper Section 7).
#include <algorithm>

#include "common.hpp"
#include "ek/analysis/attributes.hpp"
#include "ek/analysis/clustering.hpp"
#include "ek/analysis/json.hpp"
#include "ek/analysis/mds.hpp"
#include "ek/analysis/similarity.hpp"
#include "ek/core/errors.hpp"

namespace ek::python {
namespace {

SimilarityOptions similarity_options(bool reverse, bool mirror, std::optional<int> samples) {
  SimilarityOptions opt;
  opt.reversal = reverse;
  opt.mirror = mirror;
  opt.samples = samples.value_or(0);
  return opt;
}

py::array_t<std::int64_t> index_array(const std::vector<int>& v) {
  py::array_t<std::int64_t> a(static_cast<py::ssize_t>(v.size()));
  for (size_t i = 0; i < v.size(); ++i) a.mutable_data()[i] = v[i];
  return a;
}

/// similarity() and similarity_matrix() (paper Section 7.1).
void bind_similarity(py::module_& m) {
  m.def(
      "similarity",
      [](const py::handle& a, const py::handle& b, bool reverse, bool mirror, std::optional<int> samples) {
        const SimilarityOptions opt = similarity_options(reverse, mirror, samples);
        const Points A = curve_arg(a, "a"), B = curve_arg(b, "b");
        return result_from_json(similarity_json(compare_curves(A, B, opt), opt), "similarity");
      },
      py::arg("a"), py::arg("b"), py::kw_only(), py::arg("reverse") = false, py::arg("mirror") = false,
      py::arg("samples") = py::none(),
      R"doc(Curvature-torsion similarity in [0, 1] of two closed curves, (n, 3) and (m, 3) arrays
(paper Section 7.1), as `knots similarity`: 1 for a curve and any rigidly moved, cyclically
re-indexed copy. reverse: also compare with b reversed; mirror: also with b's mirror image;
samples: the common vertex count (None: the smaller count; other curves are resampled).

Fields: similarity, curvature_correlation, torsion_correlation, best_shift, reversed,
mirrored, samples, reverse_allowed, mirror_allowed.)doc");

  m.def(
      "similarity_matrix",
      [](const py::sequence& curves, bool reverse, bool mirror, std::optional<int> samples) {
        const SimilarityOptions opt = similarity_options(reverse, mirror, samples);
        std::vector<Points> list;
        for (size_t i = 0; i < curves.size(); ++i) list.push_back(curve_arg(curves[i], "curves[" + std::to_string(i) + "]"));
        if (list.empty()) throw InputError("curves: at least one curve");
        Eigen::MatrixXd S;
        {
          py::gil_scoped_release release;
          S = similarity_matrix(list, opt);
        }
        return to_array(S);
      },
      py::arg("curves"), py::kw_only(), py::arg("reverse") = false, py::arg("mirror") = false,
      py::arg("samples") = py::none(),
      "The (N, N) similarity matrix of N closed curves (symmetric, diagonal 1), options as similarity().");
}

/// cluster(), mds() and attributes() (paper Sections 7.2, 7.3).
void bind_clustering(py::module_& m) {
  m.def(
      "cluster",
      [](const py::handle& similarity, std::optional<double> cut) {
        const Eigen::MatrixXd S = to_matrix(similarity, "similarity");
        if (cut && !(*cut >= 0.0 && *cut <= 1.0)) throw InputError("cut must be in [0, 1]");
        const Dendrogram d = complete_linkage_from_similarity(S);
        Result r{"cluster", py::dict()};
        r.fields["linkage"] = to_array(d.linkage_matrix());
        r.fields["leaf_order"] = index_array(d.leaf_order());
        if (cut) {
          const std::vector<int> labels = cut_dendrogram(d, *cut);
          r.fields["cut"] = *cut;
          r.fields["labels"] = index_array(labels);
          r.fields["count"] = labels.empty() ? 0 : 1 + *std::max_element(labels.begin(), labels.end());
        }
        return r;
      },
      py::arg("similarity"), py::kw_only(), py::arg("cut") = py::none(),
      R"doc(Complete-linkage clustering of N curves from their (N, N) similarity matrix, on the
distance 1 - similarity (paper Section 7.2).

Fields: linkage, the (N - 1, 4) merges [a, b, height, size] in SciPy's layout
(scipy.cluster.hierarchy.dendrogram draws it); leaf_order, (N,), the dendrogram's leaves
left to right; with cut in [0, 1] also cut, labels, (N,), the flat clusters joined by
merges at or below the cut (0 .. count - 1 in order of their smallest member), and count.)doc");

  m.def(
      "mds",
      [](const py::handle& similarity, int dims) {
        const Eigen::MatrixXd S = to_matrix(similarity, "similarity");
        if (dims < 1 || (S.rows() > 1 && dims >= S.rows()))
          throw InputError("dims must be in [1, N - 1] for N = " + std::to_string(S.rows()) + " curves");
        const MdsResult mds = classical_mds_from_similarity(S, dims);
        Result r{"mds", py::dict()};
        r.fields["coordinates"] = to_array(mds.coordinates);
        py::array_t<double> eig(mds.eigenvalues.size());
        for (Eigen::Index k = 0; k < mds.eigenvalues.size(); ++k) eig.mutable_data()[k] = mds.eigenvalues(k);
        r.fields["eigenvalues"] = eig;
        r.fields["explained"] = mds.explained;
        r.fields["converged"] = mds.status == MdsStatus::Converged;
        return r;
      },
      py::arg("similarity"), py::kw_only(), py::arg("dims") = 2,
      R"doc(Classical multidimensional scaling of the distance 1 - similarity, (N, N), into dims
dimensions (paper Section 7.2, Fig. 6). Fields: coordinates, (N, dims); eigenvalues, the
dims largest, descending; explained, the share of the squared spread the axes keep;
converged.)doc");

  m.def(
      "attributes",
      [](const py::handle& points, double radius, double young) {
        const AttributeOptions material{radius, young};
        material.validate();
        const Points P = curve_arg(points, "points");
        return result_from_json(attributes_json(compute_attributes(P, material), static_cast<int>(P.rows()), material),
                                "attributes");
      },
      py::arg("points"), py::kw_only(), py::arg("radius") = AttributeOptions{}.radius,
      py::arg("young") = AttributeOptions{}.young_modulus,
      R"doc(Geometric attributes of the closed polygon points, (n, 3) (paper Section 7.3), as
`knots attributes`: vertices, total_curvature, threedim, sphericity, diameter, writhe,
max_stress (with radius and young), energy, energy_stretch, energy_bend, energy_twist,
stiffness (None: not computed here; energy() and the data sets have them), radius,
young_modulus.)doc");
}

}  // namespace

void bind_analysis(py::module_& m) {
  bind_similarity(m);
  bind_clustering(m);
}

}  // namespace ek::python
