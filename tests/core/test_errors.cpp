#include <gtest/gtest.h>

#include "ek/core/errors.hpp"

using namespace ek;

// An InputError quoting input with control characters stays one line (the
// CLI prints it as its one error line); found by fuzzing the code parsers.
TEST(Errors, InputErrorMessageIsOneLine) {
  EXPECT_EQ(one_line("plain text"), "plain text");
  EXPECT_EQ(one_line("a\nb\r\tc"), "a\\nb\\r\\tc");
  EXPECT_EQ(one_line(std::string("x\0y\x7f", 4)), "x\\x00y\\x7f");
  EXPECT_EQ(one_line("caf\xc3\xa9"), "caf\xc3\xa9");  // UTF-8 is kept
  EXPECT_EQ(one_line(one_line("a\nb")), one_line("a\nb"));
  const InputError e("DT code '[4\n; x]': unexpected token");
  EXPECT_STREQ(e.what(), "DT code '[4\\n; x]': unexpected token");
}
