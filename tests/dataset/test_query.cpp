// The filter syntax of `knots query` and Dataset.query(): ATTR<VALUE with the
// operators < <= > >= = == !=.
#include <gtest/gtest.h>

#include "ek/core/errors.hpp"
#include "ek/dataset/query.hpp"

using namespace ek;

TEST(QueryCondition, ParsesEveryOperator) {
  const QueryCondition le = parse_query_condition("energy<=3.5");
  EXPECT_EQ(le.attribute, "energy");
  EXPECT_EQ(le.op, "<=");
  EXPECT_EQ(le.value, 3.5);
  EXPECT_TRUE(le.holds(3.5));
  EXPECT_FALSE(le.holds(3.6));
  EXPECT_TRUE(parse_query_condition("threedim>0.1").holds(0.2));
  EXPECT_FALSE(parse_query_condition("threedim>0.1").holds(0.1));
  EXPECT_TRUE(parse_query_condition("writhe>=-2").holds(-2.0));
  EXPECT_TRUE(parse_query_condition("writhe<-1e-3").holds(-1.0));
  EXPECT_TRUE(parse_query_condition("contacts=4").holds(4.0));
  EXPECT_TRUE(parse_query_condition("contacts==4").holds(4.0));
  EXPECT_TRUE(parse_query_condition("contacts!=4").holds(5.0));
  EXPECT_FALSE(parse_query_condition("contacts!=4").holds(4.0));
}

TEST(QueryCondition, MalformedConditionsAreInputErrors) {
  for (const char* text : {"energy~1", "<3", "energy<", "energy<abc", "energy<inf", ""})
    EXPECT_THROW(parse_query_condition(text), InputError) << text;
}
