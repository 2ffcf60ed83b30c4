// The column codec of the HDF5 tables (h5_columns.hpp): every column type
// round trips bit for bit, a derived column is written and only required
// on reading, and a missing column, columns of different lengths and a
// table that is not one-dimensional are InputErrors naming the column.
#include <gtest/gtest.h>

#include <filesystem>
#include <limits>

#include "ek/core/errors.hpp"
#include "ek/dataset/h5_columns.hpp"
#include "testing.hpp"

using namespace ek;

namespace {

struct Row {
  int index = 0;
  bool flag = false;
  std::uint64_t seed = 0;
  double value = 0.0;
  std::string text;
  Points curve;
};

struct Scale {
  double factor = 1.0;
};

std::vector<h5::Column<Row, Scale>> columns() {
  using h5::member_column;
  return {member_column<Row, Scale>("index", &Row::index),
          member_column<Row, Scale>("flag", &Row::flag),
          member_column<Row, Scale>("seed", &Row::seed),
          member_column<Row, Scale>("value", &Row::value),
          member_column<Row, Scale>("text", &Row::text),
          member_column<Row, Scale>("curve", &Row::curve),
          h5::derived_column<Row, Scale>("scaled", [](const Row& r, const Scale& s) { return r.value * s.factor; })};
}

std::vector<Row> rows() {
  return {{-3, true, std::numeric_limits<std::uint64_t>::max(), 0.1, "a", fixtures::circle(5, 1.0)},
          {7, false, 42, -std::numeric_limits<double>::denorm_min(), "", fixtures::circle(5, 2.0)}};
}

/// A file with the table of rows() in the group "t".
std::string table_file(const std::string& name) {
  const std::string path = ::testing::TempDir() + name;
  std::filesystem::remove(path);
  h5::Handle f = h5::create_file(path);
  h5::Handle g = h5::create_group(f.id(), "t");
  h5::write_columns(g.id(), columns(), rows(), Scale{2.0});
  return path;
}

}  // namespace

TEST(H5Columns, EveryTypeRoundTripsBitForBit) {
  const std::string path = table_file("columns.h5");
  h5::Handle f = h5::open_file(path, false);
  h5::Handle g = h5::open_group(f.id(), "t");
  const std::vector<Row> back = h5::read_columns(g.id(), columns(), "t");
  const std::vector<Row> want = rows();
  ASSERT_EQ(back.size(), want.size());
  for (size_t k = 0; k < want.size(); ++k) {
    EXPECT_EQ(back[k].index, want[k].index);
    EXPECT_EQ(back[k].flag, want[k].flag);
    EXPECT_EQ(back[k].seed, want[k].seed);
    EXPECT_EQ(back[k].value, want[k].value);
    EXPECT_EQ(back[k].text, want[k].text);
    EXPECT_TRUE(back[k].curve == want[k].curve);
  }
  const std::vector<double> scaled{0.2, -2 * std::numeric_limits<double>::denorm_min()};
  EXPECT_EQ(h5::read_doubles(g.id(), "scaled"), scaled);
  std::filesystem::remove(path);
}

TEST(H5Columns, DamagedTablesAreInputErrorsNamingTheColumn) {
  const std::string path = table_file("damaged_columns.h5");
  h5::Handle f = h5::open_file(path, true);
  h5::Handle g = h5::open_group(f.id(), "t");
  std::vector<h5::Column<Row, Scale>> more = columns();
  more.push_back(h5::member_column<Row, Scale>("absent", &Row::value));
  fixtures::expect_input_error([&] { h5::read_columns(g.id(), more, "t"); }, "the column 't/absent' is missing");
  std::vector<h5::Column<Row, Scale>> derived_absent = columns();
  derived_absent.push_back(h5::derived_column<Row, Scale>("gone", [](const Row&, const Scale&) { return 0.0; }));
  fixtures::expect_input_error([&] { h5::read_columns(g.id(), derived_absent, "t"); },
                               "the column 't/gone' is missing");
  const double one = 1.0;
  h5::write_doubles(g.id(), "short", {1}, &one);
  std::vector<h5::Column<Row, Scale>> uneven = columns();
  uneven.push_back(h5::member_column<Row, Scale>("short", &Row::value));
  fixtures::expect_input_error([&] { h5::read_columns(g.id(), uneven, "t"); },
                               "t: column 'short' has 1 rows, 'index' 2");
  const double square[4] = {1, 2, 3, 4};
  h5::write_doubles(g.id(), "square", {2, 2}, square);
  std::vector<h5::Column<Row, Scale>> flat = columns();
  flat.push_back(h5::member_column<Row, Scale>("square", &Row::value));
  fixtures::expect_input_error([&] { h5::read_columns(g.id(), flat, "t"); }, "'t/square' is not a column");
  std::filesystem::remove(path);
}
