// csv::RowReader reads what csv::read() reads, row by row: the same fields and lines on every
// dialect feature, whatever the chunk size, and the same errors on the malformed corpus.
#include "fogdrift/base/csv_rows.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "fogdrift/base/csv.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/text_file.hpp"

namespace fogdrift::csv {
namespace {

/// Every row as RowReader gives it, with its line, read `chunk` bytes at a time.
Table rows_of(const std::string& text, std::size_t chunk, const ReadOptions& options = {}) {
  std::istringstream in(text);
  RowReader r(in, "t.csv", options, chunk);
  Table t;
  t.file = r.file();
  t.header = r.header();
  std::vector<std::string_view> fields;
  std::size_t line = 0;
  while (r.next(fields, line)) {
    t.rows.emplace_back(fields.begin(), fields.end());
    t.row_line.push_back(line);
  }
  return t;
}

/// What went wrong, or "" when nothing did.
template <typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CsvRows, TheSameRowsAsReadOnEveryDialectFeatureAndChunkSize) {
  const std::vector<std::string> texts = {
      "a,b\n1,2\n3,4\n",
      "a,b\r\n1,2\r\n3,4",  // CRLF, no final line end
      "a,b\r1,2\r3,4\r",    // lone CRs (an old Mac file)
      "\xEF\xBB\xBF"
      "a,b\n1,2\n",                                 // a UTF-8 byte-order mark
      "a,b\n\"x,y\",\"say \"\"hi\"\"\"\n 5 , 6\n",  // quotes, spaces kept
      "a,b\n1,2\n\n\n",                             // trailing empty lines
      "a,b\r\r\n1,2\n",  // a lone CR, then a CRLF: an empty line before the rows, an error
  };
  for (std::size_t k = 0; k + 1 < texts.size(); ++k) {
    const Table expected = parse(texts[k], "t.csv");
    for (std::size_t chunk : {1u, 2u, 3u, 7u, 1u << 20}) {
      const Table got = rows_of(texts[k], chunk);
      EXPECT_EQ(got.header, expected.header) << k << " chunk " << chunk;
      EXPECT_EQ(got.rows, expected.rows) << k << " chunk " << chunk;
      EXPECT_EQ(got.row_line, expected.row_line) << k << " chunk " << chunk;
    }
  }
  // Comments and a preamble, as ReadOptions say.
  ReadOptions o;
  o.skip_lines = 1;
  o.comment = '#';
  const std::string logger = "LOGGER v2\na;b\n# note\n1;2\n";
  o.delimiter = ';';
  EXPECT_EQ(rows_of(logger, 3, o).rows, parse(logger, "t.csv", o).rows);
  EXPECT_EQ(rows_of(logger, 3, o).row_line, (std::vector<std::size_t>{4}));
  // A byte-order mark alone is an empty file, as read() says.
  EXPECT_EQ(error_of([&] { rows_of("\xEF\xBB\xBF", 2); }),
            error_of([&] { parse("\xEF\xBB\xBF", "t.csv"); }));
  // The last text is an error either way, the same one.
  EXPECT_EQ(error_of([&] { rows_of(texts.back(), 2); }),
            error_of([&] { parse(texts.back(), "t.csv"); }));
}

TEST(CsvRows, TheSameErrorsAsReadOnTheMalformedCorpus) {
  std::size_t compared = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(FOGDRIFT_TEST_DATA) + "/malformed")) {
    if (entry.path().extension() != ".csv") continue;
    const std::string text = read_text_file(entry.path());
    const std::string expected = error_of([&] { parse(text, "t.csv"); });
    if (expected.empty()) continue;  // a recording's rule, not the CSV's
    for (std::size_t chunk : {5u, 1u << 20})
      EXPECT_EQ(error_of([&] { rows_of(text, chunk); }), expected) << entry.path();
    ++compared;
  }
  EXPECT_GE(compared, 8u);
}

TEST(CsvRows, ALineLongerThanAChunkAndDropEmptyRefused) {
  const std::string wide = "a,b\n" + std::string(5000, '7') + ",1\n";
  EXPECT_EQ(rows_of(wide, 64).rows[0][0], std::string(5000, '7'));
  std::istringstream in("a\n1\n");
  ReadOptions o;
  o.drop_empty = true;
  EXPECT_THROW(RowReader(in, "t.csv", o), std::invalid_argument);
}

}  // namespace
}  // namespace fogdrift::csv
