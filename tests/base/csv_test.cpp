#include "fogdrift/base/csv.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/random.hpp"

namespace fogdrift::csv {
namespace {

TEST(CsvParse, QuotedFieldsCrlfAndByteOrderMark) {
  const Table t = parse(
      "\xEF\xBB\xBFtime_s,\"Rate X [rad/s], filtered\",note\r\n1,2,\"a \"\"b\"\"\"\r\n"
      "2,3,plain\r\n\r\n",
      "x.csv");
  ASSERT_EQ(t.header.size(), 3u);
  EXPECT_EQ(t.header[0], "time_s");  // the BOM is not part of the first name
  EXPECT_EQ(t.header[1], "Rate X [rad/s], filtered");
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0][2], "a \"b\"");
  EXPECT_EQ(t.row_line[1], 3u);
}

TEST(CsvParse, SemicolonDelimiter) {
  const Table t = parse("a;b\n1,5;2\n", "x.csv", {';'});
  ASSERT_EQ(t.rows.size(), 1u);
  EXPECT_EQ(t.rows[0][0], "1,5");
}

TEST(CsvParse, TrailingDelimiterMakesAnEmptyField) {
  EXPECT_THROW(parse("a,b\n1,2,\n", "x.csv"), InputError);
}

TEST(CsvParse, DropEmptyRemovesASpreadsheetsPaddingWithANote) {
  // A chamber sheet as a spreadsheet exports it: trailing nameless empty columns, a nameless
  // empty column between two named ones, and rows of empty cells at the end.
  const std::string text =
      "\xEF\xBB\xBFTime,T1 (F),,T2 (C),,\n15:40,70.1,,21.0,,\n15:45,70.3,,21.1,,\n,,,,,\n , ,,,,\n";
  EXPECT_THROW(parse(text, "sheet.csv"), InputError);  // strict by default
  ReadOptions tolerant;
  tolerant.drop_empty = true;
  const Table t = parse(text, "sheet.csv", tolerant);
  ASSERT_EQ(t.header, (std::vector<std::string>{"Time", "T1 (F)", "T2 (C)"}));
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[1], (std::vector<std::string>{"15:45", "70.3", "21.1"}));
  EXPECT_EQ(t.row_line[1], 3u);
  ASSERT_EQ(t.notes.size(), 2u);
  EXPECT_EQ(t.notes[0], "dropped 3 empty column(s) with no name (column 3, 5, 6)");
  EXPECT_EQ(t.notes[1], "dropped 2 row(s) with every field empty");
}

TEST(CsvParse, DropEmptyKeepsANamelessColumnThatHoldsAValueAnError) {
  ReadOptions tolerant;
  tolerant.drop_empty = true;
  try {
    parse("Time,,T1\n1,,5\n2,oops,6\n", "sheet.csv", tolerant);
    FAIL() << "a nameless column with a value must be an error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(e.column(), 2u);
    EXPECT_NE(std::string(e.what()).find("no name in the header"), std::string::npos);
  }
  // A row of blanks in the middle is dropped too; nothing else changes.
  const Table t = parse("a,b\n1,2\n,\n3,4\n", "x.csv", tolerant);
  EXPECT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.row_line[1], 4u);
}

TEST(ParseNumber, AcceptsDecimalForms) {
  EXPECT_EQ(*parse_number("1.5"), 1.5);
  EXPECT_EQ(*parse_number(" -2e-3 "), -2e-3);
  EXPECT_EQ(*parse_number("+4"), 4.0);
  EXPECT_EQ(*parse_number(".5"), 0.5);
  EXPECT_EQ(*parse_number("1,25", true), 1.25);
}

TEST(ParseNumber, RejectsNonFiniteAndText) {
  for (const char* bad : {"", " ", "nan", "NaN", "inf", "-Infinity", "1e999", "abc", "1.2.3",
                          "0x10", "1,5", "--1", "+", "-"}) {
    EXPECT_FALSE(parse_number(bad).has_value()) << "'" << bad << "'";
  }
  EXPECT_FALSE(parse_number("1.5", true).has_value());  // a '.' with decimal commas is ambiguous
}

// The short decimals parse_number reads without from_chars (csv.cpp, short_decimal) give the
// correctly rounded double, as glibc's strtod does: random digit strings around every edge of
// that path (19 and 20 digits, 2^53, powers of ten of ±22 and beyond, leading zeros, -0,
// exponents), with both decimal marks.
TEST(ParseNumber, ShortDecimalsAreCorrectlyRoundedAsStrtodReadsThem) {
  Rng rng(7);
  auto digit_string = [&rng](int n) {
    std::string d;
    for (int i = 0; i < n; ++i) d += static_cast<char>('0' + static_cast<int>(rng.uniform(0, 10)));
    return d;
  };
  std::vector<std::string> texts = {"0",
                                    "-0",
                                    "0.0",
                                    "-0.000",
                                    "9007199254740992",
                                    "9007199254740993",
                                    "9007199254740993.0",
                                    "0.1234567890123456789012",
                                    "0.12345678901234567890123",
                                    "1234567890123456789",
                                    "12345678901234567890",
                                    "007.50"};
  for (int i = 0; i < 200000; ++i) {
    const int n = 1 + static_cast<int>(rng.uniform(0, 24));
    std::string d = digit_string(n);
    if (rng.uniform(0, 1) < 0.3)
      d = std::string(static_cast<std::size_t>(rng.uniform(1, 4)), '0') + d;
    const auto at = static_cast<std::size_t>(rng.uniform(0, static_cast<double>(d.size())));
    if (at > 0 && rng.uniform(0, 1) < 0.8) d.insert(at, ".");
    if (rng.uniform(0, 1) < 0.3) {  // an exponent, within the fast path's reach and beyond it
      const int e = static_cast<int>(rng.uniform(-40, 40));
      d += (rng.uniform(0, 1) < 0.5 ? "e" : "E") +
           std::string(e >= 0 && rng.uniform(0, 1) < 0.5 ? "+" : "") +
           (rng.uniform(0, 1) < 0.2 ? (e < 0 ? "-0" : "0") + std::to_string(std::abs(e))
                                    : std::to_string(e));
    }
    texts.push_back(rng.uniform(0, 1) < 0.5 ? "-" + d : d);
  }
  for (const std::string& text : texts) {
    const double reference = std::strtod(text.c_str(), nullptr);
    const auto got = parse_number(text);
    ASSERT_TRUE(got.has_value()) << text;
    ASSERT_EQ(std::bit_cast<std::uint64_t>(*got), std::bit_cast<std::uint64_t>(reference)) << text;
    std::string comma = text;
    std::replace(comma.begin(), comma.end(), '.', ',');
    const auto with_comma = parse_number(comma, true);
    ASSERT_TRUE(with_comma.has_value()) << comma;
    ASSERT_EQ(std::bit_cast<std::uint64_t>(*with_comma), std::bit_cast<std::uint64_t>(reference))
        << comma;
  }
}

TEST(FormatNumber, ShortestTextReadsBackExactly) {
  Rng rng(42);
  for (int i = 0; i < 20000; ++i) {
    const double scale = std::pow(10.0, rng.uniform(-30.0, 30.0));
    const double x = rng.normal() * scale;
    const std::string text = format_number(x);
    const auto back = parse_number(text);
    ASSERT_TRUE(back.has_value()) << text;
    ASSERT_EQ(*back, x) << text;
  }
  EXPECT_EQ(format_number(0.1), "0.1");
  EXPECT_EQ(format_number(-39.73), "-39.73");
  EXPECT_EQ(format_number(1800.0), "1800");
}

TEST(Quote, OnlyWhenNeeded) {
  EXPECT_EQ(quote("plain"), "plain");
  EXPECT_EQ(quote("a,b"), "\"a,b\"");
  EXPECT_EQ(quote("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(quote(" edge"), "\" edge\"");
}

// Found by attack (issue 36, "reader leniency"): a 10 MB number was echoed whole in its error.
TEST(Excerpt, ShowsAFieldWholeUpTo40CharactersElseItsStartAndLength) {
  EXPECT_EQ(excerpt("12.5x"), "12.5x");
  EXPECT_EQ(excerpt(std::string(40, '7')), std::string(40, '7'));
  EXPECT_EQ(excerpt(std::string(10'000'000, '9')), std::string(40, '9') + "…(10000000 characters)");
}

// Found by attack (issue 36, "stream input"): stream echoed the CR of CRLF lines into its output,
// read a CR-only file as one line and refused a byte-order mark. Its lines are those read() sees.
TEST(LineReader, EndsLinesAtLfCrlfOrCrAndDropsTheByteOrderMark) {
  const std::string bom = "\xEF\xBB\xBF";
  for (const std::string& text :
       {bom + "a,b\n1,2\n\n3,4", bom + "a,b\r\n1,2\r\n\r\n3,4\r\n", bom + "a,b\r1,2\r\r3,4\r"}) {
    std::istringstream in(text);
    LineReader lines(in);
    std::vector<std::string> got;
    std::string line;
    while (lines.next(line)) got.push_back(line);
    EXPECT_EQ(got, (std::vector<std::string>{"a,b", "1,2", "", "3,4"})) << text;
  }
  EXPECT_EQ(parse(bom + "a,b\r\n1,2\r\n", "t.csv").header, (std::vector<std::string>{"a", "b"}));
  std::istringstream empty("");
  std::string line;
  EXPECT_FALSE(LineReader(empty).next(line));
}

// Found by an attack (issue 57): messages that named the wrong rule or no place.
TEST(Csv, TinyNumbersAreZeroAndHugeOnesSayWhy) {
  EXPECT_EQ(*parse_number("1e-400"), 0.0);
  EXPECT_EQ(*parse_number("-1e-400"), 0.0);
  EXPECT_TRUE(std::signbit(*parse_number("-1e-400")));
  EXPECT_EQ(*parse_number("0.000001e-399"), 0.0);
  EXPECT_FALSE(parse_number("1e400").has_value());
  EXPECT_FALSE(parse_number(std::string(100000, '9')).has_value());
  EXPECT_EQ(why_not_a_number("1e400"), "is beyond a double's range (magnitude above 1.8e308)");
  EXPECT_EQ(why_not_a_number(std::string(100000, '9')),
            "is beyond a double's range (magnitude above 1.8e308)");
  EXPECT_EQ(why_not_a_number(""), "is empty");
  EXPECT_EQ(why_not_a_number("NaN"), "is not finite (NaN and Inf are not allowed)");
  EXPECT_EQ(why_not_a_number("abc"), "is not a number");
  EXPECT_EQ(excerpt(std::string("1\0"
                                "2",
                                3)),
            "1\\x002");
}

TEST(Csv, LoneCarriageReturnsEndLinesAndEncodingsAreNamed) {
  const Table lf = parse("a,b\n1,2\n3,4\n", "t.csv");
  const Table cr = parse("a,b\r1,2\r3,4\r", "t.csv");
  EXPECT_EQ(cr.header, lf.header);
  EXPECT_EQ(cr.rows, lf.rows);
  try {
    parse(std::string("a,b\n1,\0"
                      "2\n",
                      9),
          "t.csv");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("t.csv:2:3: contains a NUL byte"), std::string::npos)
        << e.what();
  }
  try {
    parse(std::string("\xff\xfe"
                      "a\0,\0",
                      6),
          "t.csv");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("t.csv:1:1: is UTF-16 text"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace fogdrift::csv
