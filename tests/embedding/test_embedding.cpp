#include <gtest/gtest.h>

#include <chrono>

#include "ek/core/errors.hpp"
#include "ek/embedding/embedding.hpp"
#include "ek/geometry/polyline.hpp"
#include "ek/knots/alexander.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

void expect_valid(const Embedding& e, int n, double edge) {
  ASSERT_EQ(e.points.rows(), n);
  const VecX len = edge_lengths(e.points);
  EXPECT_LT((len.array() - edge).abs().maxCoeff(), 1e-9 * edge);
  EXPECT_GT(e.clearance, 0.0);
  EXPECT_NEAR(e.clearance, clearance(e.points).distance, 1e-15);
}

}  // namespace

TEST(Embedding, BraidCoilOfTrefoil) {
  const auto& k = KnotTable::global().at("3_1");
  const Embedding e = embed_knot(k, EmbeddingSource::Braid, {});
  expect_valid(e, 400, 1.0);
  EXPECT_EQ(alexander(e.points), alexander(*k.pd));
  // a positive braid: the coil's writhe has the sign of the braid's crossings
}

TEST(Embedding, PDDrawingOfFigureEight) {
  const auto& k = KnotTable::global().at("4_1");
  EmbeddingOptions o;
  o.vertices = 200;
  o.edge_length = 0.5;
  const Embedding e = embed_knot(k, EmbeddingSource::PD, o);
  expect_valid(e, 200, 0.5);
  EXPECT_EQ(alexander(e.points).coefficients, (std::vector<std::int64_t>{-1, 3, -1}));
}

TEST(Embedding, UnknotIsACircle) {
  const Embedding e = embed_knot(KnotTable::global().at("0_1"), EmbeddingSource::Braid, {});
  expect_valid(e, 400, 1.0);
  EXPECT_NEAR(total_curvature(e.points), 2.0 * M_PI, 1e-9);
}

TEST(Embedding, MultiCoveredCircleFromSmallSpacing) {
  // 12a_1019 (paper Fig. 13): a 5-strand braid closed into a nearly 5-covered circle.
  const auto& k = KnotTable::global().at("12a_1019");
  EmbeddingOptions o;
  o.strand_spacing = 0.02;
  o.vertices = 1000;
  const Embedding e = embed_knot(k, EmbeddingSource::Braid, o);
  expect_valid(e, 1000, 1.0);
  // total curvature close to 2π · strands (a multi-covered circle)
  EXPECT_NEAR(total_curvature(e.points) / (2 * M_PI), k.braid->strands, 0.25);
}

TEST(Embedding, BadOptionsAreInputErrors) {
  const auto& k = KnotTable::global().at("3_1");
  EmbeddingOptions o;
  o.vertices = 3;
  EXPECT_THROW(embed_knot(k, EmbeddingSource::Braid, o), InputError);
  o.vertices = 400;
  o.edge_length = -1;
  EXPECT_THROW(embed_knot(k, EmbeddingSource::PD, o), InputError);
  EXPECT_THROW(parse_embedding_source("dt"), InputError);
  // far too few vertices for a 12-crossing knot: the check catches it
  o = {};
  o.vertices = 12;
  EXPECT_THROW(embed_knot(KnotTable::global().at("12n_838"), EmbeddingSource::PD, o), InputError);
}

TEST(Embedding, NonPlanarPDIsRejected) {
  // A Gauss code that is not realisable in the plane (a virtual trefoil-like
  // code): labels pair up but the faces do not satisfy Euler's formula.
  EXPECT_THROW(embed_pd(parse_pd("[[1;3;2;4];[3;1;4;2]]")), InputError);
}

// Every table knot: Alexander polynomial of the PD code = braid word = 3D
// braid embedding = 3D PD embedding (n = 400), and every embedding is simple.
TEST(Embedding, AllTableKnotsBothEmbeddingsKeepTheKnotType) {
  const auto t0 = std::chrono::steady_clock::now();
  int checked = 0;
  EmbeddingOptions o;
  o.verify = false;  // checked here explicitly
  for (const auto& rec : KnotTable::global().records()) {
    if (rec.crossing_number == 0) continue;
    const AlexanderPolynomial expected = alexander(*rec.pd);
    ASSERT_EQ(alexander(*rec.braid), expected) << rec.name;
    const Embedding b = embed_knot(rec, EmbeddingSource::Braid, o);
    EXPECT_EQ(alexander(b.points), expected) << rec.name << " braid embedding";
    EXPECT_GT(b.clearance, 0.0) << rec.name;
    const Embedding p = embed_knot(rec, EmbeddingSource::PD, o);
    EXPECT_EQ(alexander(p.points), expected) << rec.name << " pd embedding";
    EXPECT_GT(p.clearance, 0.0) << rec.name;
    ++checked;
  }
  EXPECT_EQ(checked, 2977);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "[ sweep    ] 2977 knots, 4 Alexander routes each, in " << seconds << " s\n";
}
