// RFC 4180 CSV writer: quoting, line endings, deterministic numbers.
#include <gtest/gtest.h>

#include <clocale>
#include <cmath>
#include <limits>
#include <sstream>

#include "io/csv.hpp"

using mc::io::CsvOptions;
using mc::io::CsvWriter;
using mc::io::LineEnding;

TEST(Csv, QuotesOnlyWhenNeeded) {
  EXPECT_EQ(mc::io::csv_escape("NL.IMBAG.Pand.0503100000000010"), "NL.IMBAG.Pand.0503100000000010");
  EXPECT_EQ(mc::io::csv_escape(""), "");
  EXPECT_EQ(mc::io::csv_escape("a,b"), "\"a,b\"");
  EXPECT_EQ(mc::io::csv_escape("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(mc::io::csv_escape("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(mc::io::csv_escape("cr\rhere"), "\"cr\rhere\"");
  EXPECT_EQ(mc::io::csv_escape(" spaces kept "), " spaces kept ");
  EXPECT_EQ(mc::io::csv_escape("Delft ü"), "Delft ü");
}

TEST(Csv, FixedNumbers) {
  EXPECT_EQ(mc::io::format_fixed(1.0 / 3, 4), "0.3333");
  EXPECT_EQ(mc::io::format_fixed(2.5, 0), "2");  // round-half-even of the exact binary value
  EXPECT_EQ(mc::io::format_fixed(155000.0, 3), "155000.000");
  EXPECT_EQ(mc::io::format_fixed(-1e-9, 3), "0.000");
  EXPECT_EQ(mc::io::format_fixed(-0.0, 2), "0.00");
  EXPECT_EQ(mc::io::format_fixed(-1.25, 1), "-1.2");
  EXPECT_EQ(mc::io::format_fixed(1e20, 1), "100000000000000000000.0");
  EXPECT_EQ(mc::io::format_fixed(std::nan(""), 3), "");
  EXPECT_EQ(mc::io::format_fixed(std::numeric_limits<double>::infinity(), 3), "");
}

TEST(Csv, LocaleDoesNotChangeNumbers) {
  const char* old = std::setlocale(LC_NUMERIC, nullptr);
  const std::string saved = old ? old : "C";
  // A decimal-comma locale would break CSV; it may not be installed, which is fine too.
  if (std::setlocale(LC_NUMERIC, "de_DE.UTF-8") || std::setlocale(LC_NUMERIC, "nl_NL.UTF-8")) {
    EXPECT_EQ(mc::io::format_fixed(3.25, 2), "3.25");
  }
  std::setlocale(LC_NUMERIC, saved.c_str());
}

TEST(Csv, RowsWithCrlfByDefault) {
  std::ostringstream out;
  CsvWriter w(out);
  w.field("id").field("status").field("parts").field("volume").end_row();
  w.field("b,1").field("ok").field(3).field(12.5).end_row();
  w.field("b\"2").field("failed").empty().field(std::nan("")).end_row();
  EXPECT_EQ(out.str(),
            "id,status,parts,volume\r\n"
            "\"b,1\",ok,3,12.500000\r\n"
            "\"b\"\"2\",failed,,\r\n");
  EXPECT_EQ(w.rows(), 3u);
}

TEST(Csv, LfAndPrecisionOptions) {
  std::ostringstream out;
  CsvWriter w(out, CsvOptions{LineEnding::LF, 2});
  w.field("lon").field("lat").field("flag").field("n").end_row();
  w.field(4.3612345678, 7).field(52.0).field(true).field(uint64_t{18446744073709551615ULL}).end_row();
  EXPECT_EQ(out.str(), "lon,lat,flag,n\n4.3612346,52.00,true,18446744073709551615\n");
}

TEST(Csv, LoneEmptyFieldIsQuoted) {
  std::ostringstream out;
  CsvWriter w(out, CsvOptions{LineEnding::LF});
  w.field("note").end_row();
  w.field("").end_row();
  EXPECT_EQ(out.str(), "note\n\"\"\n");
}

TEST(Csv, RaggedRowsAreABug) {
  std::ostringstream out;
  CsvWriter w(out);
  w.field("a").field("b").end_row();
  w.field("only one");
  EXPECT_THROW(w.end_row(), std::logic_error);
}

TEST(Csv, ByteIdenticalAcrossRuns) {
  auto render = [] {
    std::ostringstream out;
    CsvWriter w(out);
    for (int i = 0; i < 100; ++i)
      w.field("b" + std::to_string(i)).field(std::sqrt(i) * 1e3).field(-i / 7.0).end_row();
    return out.str();
  };
  EXPECT_EQ(render(), render());
}
