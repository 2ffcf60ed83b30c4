// The strict number parsers (ek/core/parse.hpp) on texts with known answers.
#include <gtest/gtest.h>

#include "ek/core/errors.hpp"
#include "ek/core/parse.hpp"

using namespace ek;

namespace {

/// The InputError message of parse_number(text), or "" when it parses.
std::string number_error(const std::string& text) {
  try {
    parse_number(text, "--x");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Parse, NumbersWithKnownValues) {
  EXPECT_EQ(parse_number("1e-3", "--x"), 1e-3);
  EXPECT_EQ(parse_number("+2.5", "--x"), 2.5);
  EXPECT_EQ(parse_number("-0.125", "--x"), -0.125);
  EXPECT_EQ(parse_number("7", "--x"), 7.0);
  EXPECT_EQ(parse_integer("+12", "--n"), 12);
  EXPECT_EQ(parse_integer("-3", "--n"), -3);
}

TEST(Parse, AnythingButOneNumberIsRefusedWithItsText) {
  for (const std::string bad : {"", " 1", "1 ", "1x", "x", "+", "++1", "1,2", "0x10"})
    EXPECT_EQ(number_error(bad), "--x: '" + bad + "' is not a number") << bad;
  for (const std::string bad : {"inf", "-inf", "nan", "1e999"})
    EXPECT_NE(number_error(bad).find("is not"), std::string::npos) << bad;
  EXPECT_EQ(number_error("inf"), "--x: 'inf' is not a finite number");
  for (const std::string bad : {"", "1.5", "1e3", "12a", "+", "99999999999999999999"})
    EXPECT_THROW(parse_integer(bad, "--n"), InputError) << bad;
}
