// Numbers read where they stand in a line (TokenReader::nextInt64 and
// nextDouble, the mesh readers' fast path) agree with finding the token
// first and parsing it after (next + parseInt64 / parseDouble) on every
// kind of token: the fast path may only be faster, never read otherwise.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "io/text.h"

namespace meshtrace {
namespace {

// Tokens at and around every edge of the fast paths: digits only, up to
// and past 18 digits and int64's range, odd and even counts of digits
// (read two at a time) before a stray character; signs; numbers run into other
// characters; the forms from_chars takes for doubles (exponents, inf,
// nan) and ones it stops inside.
const std::vector<std::string> kTokens = {"0",
                                          "7",
                                          "007",
                                          "42",
                                          "500096",
                                          "123456789012345678",
                                          "1234567890123456789",
                                          "9223372036854775807",
                                          "9223372036854775808",
                                          "99999999999999999999",
                                          "+5",
                                          "-3",
                                          "+-3",
                                          "--3",
                                          "+",
                                          "-",
                                          "12x",
                                          "1x",
                                          "123x",
                                          "1234x5",
                                          "12345678901234567",
                                          "x12",
                                          "1.",
                                          ".5",
                                          "1.5",
                                          "-0.013166238617716368",
                                          "1.5e3",
                                          "1.5e",
                                          "1.5e+",
                                          "1e-400",
                                          "1e400",
                                          "inf",
                                          "-inf",
                                          "nan",
                                          "infinity",
                                          "0x1A",
                                          "1,5",
                                          "3.3.3",
                                          "1e5x",
                                          "\x01",
                                          "#",
                                          "1#2"};

// A line with `token` between the given spaces, then another token.
std::string lineWith(const std::string& token, const std::string& before,
                     const std::string& after) {
  return before + token + after + "9";
}

// Reads the first token of `line` both ways, found and then parsed by
// `parse`, and in place by `read`: they must agree on whether it is a
// number, on its value and its token, and continue at the same place.
template <typename Parse, typename Read>
void expectInPlaceReadingAgrees(const std::string& line, const std::string& token,
                                const Parse& parse, const Read& read) {
  text::TokenReader found(line), inPlace(line);
  std::string_view word, seen;
  ASSERT_TRUE(found.next(word));
  std::int64_t expected = -1, got = -2;
  const bool parses = parse(word, expected);
  EXPECT_EQ(read(inPlace, got, seen) == text::NumberToken::Read, parses)
      << "token '" << token << "'";
  EXPECT_EQ(seen, word) << "token '" << token << "'";
  if (parses) {
    EXPECT_EQ(got, expected) << "token '" << token << "'";
  }
  std::string_view nextFound, nextInPlace;
  ASSERT_TRUE(found.next(nextFound));
  ASSERT_TRUE(inPlace.next(nextInPlace));
  EXPECT_EQ(nextFound, nextInPlace) << "token '" << token << "'";
}

TEST(TokenNumbers, InPlaceIntegersAgreeWithParsingTheFoundToken) {
  for (const std::string& token : kTokens)
    for (const std::string& space : {std::string(" "), std::string("\t\r")})
      expectInPlaceReadingAgrees(
          lineWith(token, space, space), token,
          [](std::string_view word, std::int64_t& out) { return text::parseInt64(word, out); },
          [](text::TokenReader& r, std::int64_t& out, std::string_view& seen) {
            return r.nextInt64(out, seen);
          });
}

// OBJ corners: the integer before the first '/', read where it stands,
// agrees with parsing that part of the found token, for every token above
// and each of them with a slash and more after it.
TEST(TokenNumbers, LeadingIntegersAgreeWithParsingTheFoundTokensStart) {
  std::vector<std::string> tokens = kTokens;
  for (const std::string& token : kTokens)
    for (const char* after : {"/", "/2", "//5", "/2/5", "/x"}) tokens.push_back(token + after);
  for (const char* odd : {"/", "//", "/5", "-/1", "+7/1"}) tokens.push_back(odd);
  for (const std::string& token : tokens)
    expectInPlaceReadingAgrees(
        lineWith(token, " ", "\t"), token,
        [](std::string_view word, std::int64_t& out) {
          return text::parseInt64(word.substr(0, word.find('/')), out);
        },
        [](text::TokenReader& r, std::int64_t& out, std::string_view& seen) {
          return r.nextLeadingInt64(out, seen);
        });
}

TEST(TokenNumbers, InPlaceDoublesAgreeWithParsingTheFoundToken) {
  for (const std::string& token : kTokens) {
    for (const std::string& space : {std::string(" "), std::string("\t\v\f")}) {
      const std::string line = lineWith(token, space, space);
      text::TokenReader found(line), inPlace(line);
      std::string_view word, seen;
      ASSERT_TRUE(found.next(word));
      double expected = -1.0, got = -2.0;
      const bool parses = text::parseDouble(word, expected);
      const text::NumberToken read = inPlace.nextDouble(got, seen);
      EXPECT_EQ(read == text::NumberToken::Read, parses) << "token '" << token << "'";
      EXPECT_EQ(seen, word) << "token '" << token << "'";
      if (parses && !std::isnan(expected)) {
        EXPECT_EQ(got, expected) << "token '" << token << "'";
      }
      if (parses && std::isnan(expected)) {
        EXPECT_TRUE(std::isnan(got)) << "token '" << token << "'";
      }
      std::string_view nextFound, nextInPlace;
      ASSERT_TRUE(found.next(nextFound));
      ASSERT_TRUE(inPlace.next(nextInPlace));
      EXPECT_EQ(nextFound, nextInPlace) << "token '" << token << "'";
    }
  }
}

TEST(TokenNumbers, ANumberAtTheLineEndIsReadAndThenTheLineEnds) {
  text::TokenReader tokens("  12 3.5");
  std::int64_t i = 0;
  double d = 0.0;
  std::string_view token;
  ASSERT_EQ(tokens.nextInt64(i, token), text::NumberToken::Read);
  EXPECT_EQ(i, 12);
  ASSERT_EQ(tokens.nextDouble(d, token), text::NumberToken::Read);
  EXPECT_EQ(d, 3.5);
  EXPECT_EQ(tokens.nextInt64(i, token), text::NumberToken::LineEnded);
  EXPECT_EQ(tokens.nextDouble(d, token), text::NumberToken::LineEnded);
}

}  // namespace
}  // namespace meshtrace
