#include "mbmodel/CsvWriter.h"

#include <fmt/format.h>
#include <set>
#include <stdexcept>

namespace rockroll {

CsvCell::CsvCell(double value) : text_(fmt::format("{}", value)) {}
CsvCell::CsvCell(int value) : text_(fmt::format("{}", value)) {}
CsvCell::CsvCell(long value) : text_(fmt::format("{}", value)) {}
CsvCell::CsvCell(long long value) : text_(fmt::format("{}", value)) {}
CsvCell::CsvCell(unsigned value) : text_(fmt::format("{}", value)) {}
CsvCell::CsvCell(unsigned long value) : text_(fmt::format("{}", value)) {}
CsvCell::CsvCell(unsigned long long value) : text_(fmt::format("{}", value)) {}
CsvCell::CsvCell(std::string_view text) : text_(text) {}
CsvCell::CsvCell(const std::string& text) : text_(text) {}
CsvCell::CsvCell(const char* text) : text_(text) {}

CsvCell CsvCell::fixed(double value, int decimals) {
    CsvCell c;
    c.text_ = fmt::format("{:.{}f}", value, decimals);
    return c;
}

CsvCell CsvCell::significant(double value, int digits) {
    CsvCell c;
    c.text_ = fmt::format("{:.{}g}", value, digits);
    return c;
}

CsvCell CsvCell::empty() { return CsvCell(); }

std::string quoteCsvField(std::string_view field) {
    if (field.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(field);
    std::string q = "\"";
    for (char c : field) {
        if (c == '"') q += '"';
        q += c;
    }
    return q + '"';
}

CsvWriter::CsvWriter(std::ostream& out, std::vector<std::string> columns) : out_(out), columns_(std::move(columns)) {
    if (columns_.empty()) throw std::logic_error("CSV table without columns");
    std::set<std::string> seen;
    for (const auto& c : columns_) {
        if (c.empty()) throw std::logic_error("CSV column without a name");
        if (!seen.insert(c).second) throw std::logic_error(fmt::format("CSV column \"{}\" appears twice", c));
    }
    writeLine(columns_);
}

void CsvWriter::writeRow(const std::vector<CsvCell>& cells) {
    if (cells.size() != columns_.size())
        throw std::logic_error(fmt::format("CSV row {} has {} cells for {} columns", rows_ + 1, cells.size(), columns_.size()));
    std::vector<std::string> fields;
    fields.reserve(cells.size());
    for (const auto& c : cells) fields.push_back(c.text());
    writeLine(fields);
    ++rows_;
}

void CsvWriter::writeLine(const std::vector<std::string>& fields) {
    // One empty field alone would be a blank line, which readers skip.
    if (fields.size() == 1 && fields[0].empty()) {
        out_ << "\"\"\n";
        return;
    }
    for (size_t i = 0; i < fields.size(); ++i) {
        if (i) out_ << ',';
        out_ << quoteCsvField(fields[i]);
    }
    out_ << '\n';
}

}  // namespace rockroll
