// Time-series input: every bad case names file, line and column.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/io/csv_fields.hpp"
#include "pneumachaos/io/csv_reader.hpp"

namespace pneumachaos {
namespace {

std::string error_of(const std::string& text, CsvSeriesOptions o = {}) {
  try {
    parse_csv_series(text, "rec.csv", o);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(CsvReader, ReadsAColumnByNameWithTimeOrRate) {
  const auto s =
      parse_csv_series("t[s],x[m],v[m/s]\n0,1,0.5\n0.001,2,0.25\n0.002,3,0.125\n", "rec.csv", {});
  EXPECT_EQ(s.size(), 3u);
  EXPECT_NEAR(s.rate_Hz(), 1000.0, 1e-9);
  EXPECT_EQ(s.channels().front().name, "v");
  EXPECT_EQ(s.channels().front().unit, "m/s");
  EXPECT_EQ(s.channels().front().values[2], 0.125);
  CsvSeriesOptions o;
  o.column = "speed";
  o.rate_Hz = 500.0;
  const auto r = parse_csv_series("speed\r\n1\r\n2\r\n\r\n", "rec.csv", o);
  EXPECT_EQ(r.size(), 2u);
  EXPECT_EQ(r.rate_Hz(), 500.0);
}

// A file is read whole into memory at its size: the same series as the text parsed directly
// (a byte-order mark, CRLF ends, a comment, a last line without '\n'); an empty file, a
// directory and a missing file named in the error.
TEST(CsvReader, AFileReadsAsItsText) {
  const std::string text = "\xEF\xBB\xBFt,v\r\n# comment\r\n0,1.5\r\n0.01,-2\r\n0.02,3e-3";
  const auto dir = std::filesystem::temp_directory_path() /
                   ("pneumachaos_csv_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto path = (dir / "rec.csv").string();
  std::ofstream(path, std::ios::binary) << text;
  const TimeSeries from_file = read_csv_series(path, {});
  const TimeSeries from_text = parse_csv_series(text, path, {});
  EXPECT_EQ(from_file.channels().front().values, from_text.channels().front().values);
  EXPECT_EQ(from_file.channels().front().values, (std::vector<double>{1.5, -2.0, 3e-3}));
  EXPECT_EQ(from_file.rate_Hz(), from_text.rate_Hz());
  EXPECT_EQ(from_file.start_s(), from_text.start_s());
  std::ofstream(path, std::ios::binary | std::ios::trunc).flush();
  try {
    read_csv_series(path, {});
    ADD_FAILURE() << "an empty file was read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("the file is empty"), std::string::npos) << e.what();
  }
  try {
    read_csv_series(dir.string(), {});  // a directory reads as nothing
    ADD_FAILURE() << "a directory was read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("the file is empty"), std::string::npos) << e.what();
  }
  try {
    read_csv_series((dir / "missing.csv").string(), {});
    ADD_FAILURE() << "a missing file was read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("missing.csv"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cannot open the file"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(CsvReader, ReadsBlankSeparatedColumnsWithOrWithoutAHeader) {
  // TISEAN-style: no header, blanks and tabs, a comment line; the rate gives the time base.
  CsvSeriesOptions o;
  o.rate_Hz = 100.0;
  o.column = "2";
  const auto s = parse_csv_series("# lab export\n0.0  1.5\n0.01\t-2.5\n0.02   3e-1\n", "rec.dat", o);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s.channels().front().name, "column 2");
  EXPECT_EQ(s.channels().front().values[1], -2.5);
  EXPECT_EQ(s.rate_Hz(), 100.0);
  o.column = "v";  // the default: the first column of a headerless file
  EXPECT_EQ(parse_csv_series("4\n5\n", "rec.dat", o).channels().front().values[0], 4.0);
  // Blank-separated with a header: the time column gives the rate.
  const auto h = parse_csv_series("t[s] v[m/s]\n0 1\n0.5 2\n1.0 3\n", "rec.dat", {});
  EXPECT_NEAR(h.rate_Hz(), 2.0, 1e-12);
  EXPECT_EQ(h.channels().front().unit, "m/s");
}

TEST(CsvReader, AHeaderlessFileNeedsARateAndANumberedColumn) {
  EXPECT_EQ(error_of("1 2\n3 4\n"),
            "rec.csv:1: the file has no header and so no time column: give the sample rate "
            "(--rate)");
  CsvSeriesOptions o;
  o.rate_Hz = 10.0;
  o.column = "3";
  EXPECT_EQ(error_of("1 2\n3 4\n", o),
            "rec.csv:1: the file has no header: give --column as a number from 1 to 2, got \"3\"");
  o.column = "2";
  EXPECT_EQ(error_of("1 2\n3 x\n", o), "rec.csv:2: column 2 (column 2): expected a number, got \"x\"");
}

TEST(CsvReader, BadInputNamesTheLineAndColumn) {
  EXPECT_EQ(error_of("t,v\n0,1\n0.001,abc\n"),
            "rec.csv:3: column 2 (v): expected a number, got \"abc\"");
  EXPECT_EQ(error_of("t,v\n0,1\n0.001,nan\n"),
            "rec.csv:3: column 2 (v): expected a finite number, got nan");
  EXPECT_EQ(error_of("t,v\n0,1\n0.001\n"), "rec.csv:3: expected 2 fields as in the header, got 1");
  EXPECT_EQ(error_of("t,v\n0,1\n0,2\n"),
            "rec.csv:3: column 1 (t): time must increase: 0 follows 0");
  EXPECT_NE(error_of("t,v\n0,1\n0.001,2\n0.003,3\n0.004,4\n").find("non-uniform sampling"),
            std::string::npos);
  EXPECT_NE(error_of("t,x\n0,1\n").find("no column \"v\""), std::string::npos);
  EXPECT_NE(error_of("v\n1\n2\n").find("give the sample rate"), std::string::npos);
  EXPECT_NE(error_of("t,v\n0,1\n").find("at least 2"), std::string::npos);
  EXPECT_NE(error_of("").find("empty"), std::string::npos);
}


// The reader cuts lines and fields itself (docs/notes/performance.md "Reading a record at once"):
// quoting, blanks, comments and separators are decided by that code, so each case is checked
// here against expected values written out by hand.
TEST(CsvReader, LinesAndFieldsAsAStreamWouldCutThem) {
  CsvSeriesOptions o;
  o.rate_Hz = 10.0;
  // Quoted cells and blanks around them, comment and blank lines (one quoted), a last line
  // without a newline.
  const auto s =
      parse_csv_series("t , \"v\"\n#c\n  \n\"# quoted comment\"\n0, \"1.5\" \n\t\n0.1,-2", "r.csv", o);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s.channels().front().values[0], 1.5);
  EXPECT_EQ(s.channels().front().values[1], -2.0);
  // A trailing comma is one more (empty) field; an empty quoted cell is no number.
  EXPECT_EQ(error_of("t,v\n0,1,\n"), "rec.csv:2: expected 2 fields as in the header, got 3");
  EXPECT_EQ(error_of("t,v\n0,\"\"\n0.1,2\n"),
            "rec.csv:2: column 2 (v): expected a number, got \"\"");
  EXPECT_EQ(error_of("t,v\n0,  \n"), "rec.csv:2: column 2 (v): expected a number, got \"\"");
  EXPECT_EQ(split_csv_fields(""), std::vector<std::string>{});
  EXPECT_EQ(split_csv_fields(","), (std::vector<std::string>{"", ""}));
  EXPECT_EQ(split_csv_fields("a,,b "), (std::vector<std::string>{"a", "", "b "}));
  // Blank-separated: runs of blanks and tabs, quotes stripped from a cell.
  o.column = "2";
  const auto b = parse_csv_series(" 1 \t \"2.5\"\n3 4\n", "r.dat", o);
  EXPECT_EQ(b.channels().front().values[0], 2.5);
  EXPECT_EQ(b.channels().front().values[1], 4.0);
}

// A rate that disagrees with the time column, a headerless file whose first column is a clock,
// and a ';'-separated export are refused with what to do, never read silently.
TEST(CsvReader, ARateMustAgreeWithTheTimeColumn) {
  CsvSeriesOptions o;
  o.rate_Hz = 2000.0;
  EXPECT_EQ(error_of("t[s],v\n0,1\n0.001,2\n0.002,3\n", o),
            "sampling rate: 2000 Hz disagrees with the time column \"t[s]\" of rec.csv, sampled "
            "at 1000 Hz: drop the rate option to use the time column, or correct one of them");
  o.rate_Hz = 1000.0;  // agreeing: read, on the file's own clock
  const auto s = parse_csv_series("t,v\n4,1\n4.001,2\n4.002,3\n", "rec.csv", o);
  EXPECT_NEAR(s.rate_Hz(), 1000.0, 1e-6);
  EXPECT_EQ(s.start_s(), 4.0);
}

TEST(CsvReader, TheClockIsReadInItsUnit) {
  const std::string ms = "t[ms],v[m/s]\n0,0.1\n1,0.2\n2,0.1\n3,0.3\n";
  const auto s = parse_csv_series(ms, "rec.csv", {});
  EXPECT_NEAR(s.rate_Hz(), 1000.0, 1e-9);
  const auto us = parse_csv_series("t[us],v\n10,1\n20,2\n30,3\n", "rec.csv", {});
  EXPECT_NEAR(us.rate_Hz(), 1e5, 1e-6);
  EXPECT_NEAR(us.start_s(), 1e-5, 1e-15);
  CsvSeriesOptions o;
  o.units = {{"t", "ms"}};
  EXPECT_NEAR(parse_csv_series("t,v\n0,1\n1,2\n2,3\n", "rec.csv", o).rate_Hz(), 1000.0, 1e-9);
  const std::string unknown = error_of("t[min],v\n0,1\n1,2\n");
  EXPECT_NE(unknown.find("rec.csv:1:1"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("column t[min]"), std::string::npos) << unknown;
}

TEST(CsvReader, ARateOffByAThousandNamesTheClocksUnit) {
  CsvSeriesOptions o;
  o.rate_Hz = 1000.0;
  const std::string m = error_of("t[s],v\n0,1\n1,2\n2,3\n", o);  // milliseconds under [s]
  EXPECT_NE(m.find("the clock looks like it counts ms, not s: head the column t[ms]"),
            std::string::npos)
      << m;
}

TEST(CsvReader, AnalysedValuesOfAKnownUnitMustBePhysical) {
  CsvSeriesOptions o;
  o.column = "P1";
  const std::string kpa = error_of("t[s],P1[Pa]\n0,300\n0.001,301\n0.002,302\n", o);
  EXPECT_NE(kpa.find("rec.csv:2: column 2 (P1[Pa])"), std::string::npos) << kpa;
  EXPECT_NE(kpa.find("look like gauge values or kPa"), std::string::npos) << kpa;
  EXPECT_NO_THROW(parse_csv_series("t[s],P1[kPa g]\n0,0\n0.001,1\n0.002,2\n", "rec.csv", o));
  const std::string mm = error_of("t[s],v[m/s]\n0,20\n0.001,35\n0.002,2\n");
  EXPECT_NE(mm.find("look like mm/s"), std::string::npos) << mm;
  o.column = "u";  // a unit this reader does not know only labels the series
  EXPECT_EQ(parse_csv_series("t[s],u[V]\n0,1e6\n0.001,2\n", "rec.csv", o).channels().front().unit,
            "V");
}

TEST(CsvReader, AHeaderlessClockColumnIsNotAnalysedByDefault) {
  CsvSeriesOptions o;
  o.rate_Hz = 1000.0;
  const std::string text = "0 5\n0.001 6\n0.002 4\n0.003 5\n";
  EXPECT_EQ(error_of(text, o),
            "rec.csv:1: the file has no header and its first column rises at a constant step of "
            "0.001, like a time column: name the column to analyse, e.g. --column 2 (or --column "
            "1 to analyse the first column anyway)");
  o.column = "1";
  EXPECT_EQ(parse_csv_series(text, "rec.csv", o).channels().front().values[3], 0.003);
  o.column = "v";  // a first column that is no clock is read as data
  EXPECT_EQ(parse_csv_series("1 5\n0.5 6\n2 4\n", "rec.csv", o).channels().front().values[1], 0.5);
}

TEST(CsvReader, SemicolonsAreRecognisedAndExplained) {
  const std::string e = error_of("t;v\n0;1,5\n0,001;2,5\n");
  EXPECT_NE(e.find("no column \"v\" in the header; it has: t;v; the fields look separated by "
                   "';'"),
            std::string::npos) << e;
  EXPECT_NE(e.find("tr ',;' '.,'"), std::string::npos) << e;
}

}  // namespace
}  // namespace pneumachaos
