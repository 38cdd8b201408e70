#pragma once
// The one CSV writer of the program (RFC 4180). A table is a header of column
// names, which carry their units (`speed_mph`, `roll_amplitude_deg`), then rows
// of exactly as many cells. Cells are numbers (shortest round-trip text by
// default, or a fixed number of decimals or significant digits) or text; a
// cell containing a comma, a double quote, CR or LF is quoted and its quotes
// doubled, so a reader never sees the columns shift. Lines end in "\n".
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace rockroll {

/// One CSV cell, already formatted.
class CsvCell {
public:
    CsvCell(double value);              ///< shortest text that reads back to the same double
    CsvCell(int value);
    CsvCell(long value);
    CsvCell(long long value);
    CsvCell(unsigned value);
    CsvCell(unsigned long value);
    CsvCell(unsigned long long value);
    CsvCell(std::string_view text);
    CsvCell(const std::string& text);
    CsvCell(const char* text);
    CsvCell(bool) = delete;             ///< say what a flag means: text ("yes") or 0/1 explicitly

    static CsvCell fixed(double value, int decimals);        ///< "{:.Nf}"
    static CsvCell significant(double value, int digits);    ///< "{:.Ng}"
    static CsvCell empty();                                  ///< a missing value

    const std::string& text() const { return text_; }

private:
    CsvCell() = default;
    std::string text_;
};

/// RFC 4180 field: quoted when it contains a comma, a double quote, CR or LF.
std::string quoteCsvField(std::string_view field);

class CsvWriter {
public:
    /// Writes the header line. Column names must be unique and non-empty.
    CsvWriter(std::ostream& out, std::vector<std::string> columns);

    /// Writes one row; throws std::logic_error unless it has one cell per column.
    void writeRow(const std::vector<CsvCell>& cells);

    const std::vector<std::string>& getColumns() const { return columns_; }
    size_t getRowCount() const { return rows_; }

private:
    void writeLine(const std::vector<std::string>& fields);
    std::ostream& out_;
    std::vector<std::string> columns_;
    size_t rows_ = 0;
};

}  // namespace rockroll
