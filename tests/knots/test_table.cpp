#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <set>

#include "ek/core/errors.hpp"
#include "ek/core/paths.hpp"
#include "ek/knots/table.hpp"

using namespace ek;

TEST(KnotTable, LoadsAllKnots) {
  const auto& table = KnotTable::global();
  // KnotInfo: the unknot plus 2,977 prime knots with up to 12 crossings.
  EXPECT_EQ(table.size(), 2978u);
  EXPECT_EQ(table.up_to_crossings(12).size(), 2977u);
  EXPECT_EQ(table.with_crossings(3).size(), 1u);
  EXPECT_EQ(table.with_crossings(8).size(), 21u);
  EXPECT_EQ(table.with_crossings(10).size(), 165u);
  EXPECT_EQ(table.with_crossings(12).size(), 2176u);
  const auto& k = table.at("12n_838");
  EXPECT_EQ(k.crossing_number, 12);
  EXPECT_EQ(*k.bridge_index, 3);
  EXPECT_EQ(*k.braid_index, 5);
  ASSERT_TRUE(k.pd.has_value());
  EXPECT_EQ(k.pd->size(), 12);
  const auto& t = table.at("3_1");
  EXPECT_EQ(*t.bridge_index, 2);
  EXPECT_EQ(*t.braid_index, 2);
  EXPECT_EQ(t.symmetry_type, "reversible");
  EXPECT_EQ(table.at("10_123").crossing_number, 10);
  EXPECT_EQ(table.at("12a_1019").crossing_number, 12);
  EXPECT_EQ(table.at("unknot").name, "0_1");
  EXPECT_EQ(table.at("0_1").crossing_number, 0);
  EXPECT_FALSE(table.at("0_1").pd.has_value());
}

TEST(KnotTable, UnknownKnotIsInputError) {
  const auto& table = KnotTable::global();
  EXPECT_EQ(table.find("13_1"), nullptr);
  try {
    table.at("3_2");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown knot '3_2'"), std::string::npos);
  }
}

namespace {

std::string write_temp(const std::string& name, const std::string& text) {
  std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

void expect_table_error(const std::string& text, const std::string& needle) {
  const std::string path = write_temp("bad_table.csv", text);
  try {
    KnotTable::load(path);
    FAIL() << "expected InputError containing '" << needle << "'";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(needle), std::string::npos) << msg;
    EXPECT_NE(msg.find(path), std::string::npos) << msg;  // names the file
    EXPECT_EQ(msg.find('\n'), std::string::npos) << "one line";
  }
  std::remove(path.c_str());
}

const std::string kHeader =
    "Name,DT Notation,PD Notation,Braid Notation,Crossing Number,Bridge Index,Braid Index,Symmetry Type\n";

}  // namespace

TEST(KnotTable, MalformedTablesNameFileRowAndColumn) {
  expect_table_error("", "file is empty");
  expect_table_error("Name,DT Notation\n3_1,[4; 6; 2]\n", "column 'PD Notation' is missing");
  expect_table_error(kHeader + "3_1,[4; 6; 2],[[1;5;2;4];[3;1;4;6];[5;3;6;2]],{1;1;1},3,2,2\n",
                     "row 1: 7 fields, expected 8");
  expect_table_error(kHeader + "3_1,[4; 6; 2],[[1;5;2;4];[3;1;4;6];[5;3;6;2]],{1;1;1},three,2,2,reversible\n",
                     "row 1, column 'Crossing Number': 'three' is not a non-negative integer");
  expect_table_error(kHeader + "3_1,[4; 6; 3],[[1;5;2;4];[3;1;4;6];[5;3;6;2]],{1;1;1},3,2,2,reversible\n",
                     "row 1, column 'DT Notation'");
  expect_table_error(kHeader + "3_1,[4; 6; 2],[[1;5;2;4];[3;1;4;6];[5;3;6;7]],{1;1;1},3,2,2,reversible\n",
                     "row 1, column 'PD Notation'");
  expect_table_error(kHeader + "3_1,[4; 6; 2],[[1;5;2;4];[3;1;4;6];[5;3;6;2]],{1;0;1},3,2,2,reversible\n",
                     "row 1, column 'Braid Notation'");
  expect_table_error(kHeader + "3_1,[4; 6; 2],[[1;5;2;4];[3;1;4;6];[5;3;6;2]],{1;1;1},4,2,2,reversible\n",
                     "Crossing Number is 4");
  expect_table_error(kHeader + "3_1,[4; 6; 2],[[1;5;2;4];[3;1;4;6];[5;3;6;2]],{1;1;1},3,2,2,reversible\n" +
                         "3_1,[4; 6; 2],[[1;5;2;4];[3;1;4;6];[5;3;6;2]],{1;1;1},3,2,2,reversible\n",
                     "row 2, column 'Name': knot '3_1' appears twice");
}

TEST(KnotTable, MissingFile) {
  try {
    KnotTable::load("/nonexistent/knotinfo.csv");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/knotinfo.csv"), std::string::npos);
  }
}

// Found by fuzzing the table reader: a row named "0" (or "unknot") was not
// found by its own name, which find() took as an alias of 0_1.
TEST(KnotTable, AliasesDoNotHideRowsWithThatName) {
  const std::string zero = kHeader + "0,?,?,{1;-1;1},0,1,1,?\n";
  const KnotTable t = KnotTable::parse(zero, "zero.csv");
  ASSERT_NE(t.find("0"), nullptr);
  EXPECT_EQ(t.find("0")->name, "0");
  EXPECT_EQ(t.find("0_1"), nullptr);
  const KnotTable u = KnotTable::parse(kHeader + "0_1,?,?,{1;-1;1},0,1,1,?\n", "unknot.csv");
  ASSERT_NE(u.find("0"), nullptr);
  EXPECT_EQ(u.find("0")->name, "0_1");
  EXPECT_EQ(u.find("unknot"), u.find("0_1"));
}
