// The program's one CSV writer: RFC 4180 quoting, cell formats, and a round
// trip through the independent reader in tests/CsvReader.h.
#include "mbmodel/CsvWriter.h"
#include "tests/CsvReader.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <sstream>

using namespace rockroll;
using rockroll::test::parseCsv;
using rockroll::test::parseCsvTable;

TEST(CsvWriter, QuotesOnlyFieldsThatNeedIt) {
    EXPECT_EQ(quoteCsvField("speed_mph"), "speed_mph");
    EXPECT_EQ(quoteCsvField(""), "");
    EXPECT_EQ(quoteCsvField("not computed"), "not computed");
    EXPECT_EQ(quoteCsvField("stable (1 yes, 0 no)"), "\"stable (1 yes, 0 no)\"");
    EXPECT_EQ(quoteCsvField("say \"hi\""), "\"say \"\"hi\"\"\"");
    EXPECT_EQ(quoteCsvField("\""), "\"\"\"\"");
    EXPECT_EQ(quoteCsvField("a\nb"), "\"a\nb\"");
    EXPECT_EQ(quoteCsvField("a\rb"), "\"a\rb\"");
}

TEST(CsvWriter, WritesHeaderAndRowsExactly) {
    std::ostringstream out;
    CsvWriter w(out, {"speed_mph", "stable", "roll_amplitude_deg"});
    w.writeRow({12.5, "yes", CsvCell::fixed(0.61234, 4)});
    w.writeRow({13, "not computed", CsvCell::significant(123456.789, 4)});
    w.writeRow({CsvCell::empty(), "a, \"b\"", CsvCell::fixed(91500.4, 0)});
    EXPECT_EQ(out.str(),
              "speed_mph,stable,roll_amplitude_deg\n"
              "12.5,yes,0.6123\n"
              "13,not computed,1.235e+05\n"
              ",\"a, \"\"b\"\"\",91500\n");
    EXPECT_EQ(w.getRowCount(), 3u);
}

TEST(CsvWriter, RejectsRowsOfTheWrongWidthAndBadHeaders) {
    std::ostringstream out;
    CsvWriter w(out, {"a_m", "b_s"});
    EXPECT_THROW(w.writeRow({1.0}), std::logic_error);
    EXPECT_THROW(w.writeRow({1.0, 2.0, 3.0}), std::logic_error);
    EXPECT_THROW(CsvWriter(out, {}), std::logic_error);
    EXPECT_THROW(CsvWriter(out, {"a", "a"}), std::logic_error);
    EXPECT_THROW(CsvWriter(out, {"a", ""}), std::logic_error);
}

TEST(CsvWriter, DoublesRoundTripExactly) {
    const std::vector<double> values{0.1, 1.0 / 3, -2.5e-300, 6.02214076e23, 16.5, 91500, 1e-7,
                                     std::numeric_limits<double>::max(), std::numeric_limits<double>::denorm_min()};
    std::ostringstream out;
    CsvWriter w(out, {"x"});
    for (double v : values) w.writeRow({v});
    const auto t = parseCsvTable(out.str());
    const auto back = t.numbers("x");
    ASSERT_EQ(back.size(), values.size());
    for (size_t i = 0; i < values.size(); ++i) EXPECT_EQ(back[i], values[i]) << i;
}

TEST(CsvWriter, NonFiniteNumbersStayVisible) {
    std::ostringstream out;
    CsvWriter w(out, {"x"});
    w.writeRow({std::numeric_limits<double>::quiet_NaN()});
    w.writeRow({CsvCell::fixed(std::numeric_limits<double>::infinity(), 2)});
    w.writeRow({CsvCell::empty()});
    const auto rec = parseCsv(out.str());
    ASSERT_EQ(rec.size(), 4u);
    EXPECT_TRUE(std::isnan(*test::parseNumber(rec[1][0])));
    EXPECT_TRUE(std::isinf(*test::parseNumber(rec[2][0])));
    EXPECT_EQ(rec[3], std::vector<std::string>{""}) << "a lone empty cell must not become a blank line";
}

TEST(CsvWriter, TextWithCommasQuotesAndNewlinesRoundTrips) {
    const std::vector<std::string> header{"stable (1 yes, 0 no, -1 not computed)", "note \"q\"", "plain"};
    const std::vector<std::vector<std::string>> rows{
        {"yes", "a,b", "c"}, {"\"", "line1\nline2", "cr\r\nlf"}, {"", ",", "trailing space "}, {",,,", "\"\"", "x"}};
    std::ostringstream out;
    CsvWriter w(out, header);
    for (const auto& r : rows) w.writeRow({r[0], r[1], r[2]});
    const auto t = parseCsvTable(out.str());
    EXPECT_EQ(t.columns, header);
    ASSERT_EQ(t.rows.size(), rows.size());
    for (size_t i = 0; i < rows.size(); ++i) EXPECT_EQ(t.rows[i], rows[i]) << i;
    EXPECT_EQ(t.find("stable (1 yes, 0 no, -1 not computed)"), 0);
}

// The reader itself must catch what an unquoting writer produces, or the
// read-back tests of `rockroll validate` could not fail.
TEST(CsvWriter, ReaderRejectsShiftedColumns) {
    EXPECT_THROW(parseCsvTable("branch,stable (1 yes, 0 no),speed_mph\n0,1,12\n"), std::runtime_error);
    EXPECT_THROW(parseCsv("a,b\"c\n"), std::runtime_error);
    EXPECT_THROW(parseCsv("\"abc\n"), std::runtime_error);
    EXPECT_THROW(parseCsv("\"a\"b,c\n"), std::runtime_error);
    EXPECT_EQ(parseCsv("a,b\r\n1,2\r\n").size(), 2u);
}

// Every field built from the characters that need quoting (and a few that do not)
// reads back exactly, in every position of the row, for many combinations.
TEST(CsvWriter, QuotingRoundTripsEveryAwkwardField) {
    const std::string alphabet = ",\"\r\n a";
    std::vector<std::string> fields{""};
    for (char a : alphabet) {
        fields.push_back(std::string(1, a));
        for (char b : alphabet) fields.push_back(std::string{a, b});
    }
    fields.push_back("\"\"\"");
    fields.push_back("a \"quoted\" phrase, with a comma\r\nand a new line");
    std::ostringstream out;
    CsvWriter w(out, {"first", "middle", "last"});
    std::vector<std::vector<std::string>> rows;
    for (size_t i = 0; i < fields.size(); ++i) {
        rows.push_back({fields[i], fields[(i * 7 + 3) % fields.size()], fields[(i * 13 + 5) % fields.size()]});
        w.writeRow({rows.back()[0], rows.back()[1], rows.back()[2]});
    }
    const auto t = parseCsvTable(out.str());
    ASSERT_EQ(t.rows.size(), rows.size());
    for (size_t i = 0; i < rows.size(); ++i) EXPECT_EQ(t.rows[i], rows[i]) << "row " << i;
    // Only the fields that need it are quoted: a plain row is written as is.
    std::ostringstream plain;
    CsvWriter p(plain, {"a_m"});
    p.writeRow({"a b"});
    EXPECT_EQ(plain.str(), "a_m\na b\n");
}
