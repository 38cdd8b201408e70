#pragma once
// A small RFC 4180 reader for the tests: fields separated by commas, records by
// LF or CRLF, quoted fields may hold commas, CR/LF and doubled quotes. Written
// independently of mbmodel/CsvWriter so the tests read files the way any other
// CSV reader would.
#include <cmath>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rockroll::test {

using CsvRecords = std::vector<std::vector<std::string>>;

/// Throws std::runtime_error on a malformed file (stray quote, unterminated quote).
inline CsvRecords parseCsv(const std::string& text) {
    CsvRecords records;
    std::vector<std::string> record;
    std::string field;
    bool quoted = false, fieldWasQuoted = false, any = false;
    size_t i = 0;
    auto endField = [&] {
        record.push_back(field);
        field.clear();
        fieldWasQuoted = false;
    };
    auto endRecord = [&] {
        endField();
        records.push_back(record);
        record.clear();
        any = false;
    };
    while (i < text.size()) {
        const char c = text[i];
        if (quoted) {
            if (c == '"') {
                if (i + 1 < text.size() && text[i + 1] == '"') {
                    field += '"';
                    i += 2;
                    continue;
                }
                quoted = false;
                ++i;
                if (i < text.size() && text[i] != ',' && text[i] != '\n' && text[i] != '\r')
                    throw std::runtime_error("CSV: text after a closing quote at byte " + std::to_string(i));
                continue;
            }
            field += c;
            ++i;
            continue;
        }
        if (c == '"') {
            if (!field.empty() || fieldWasQuoted)
                throw std::runtime_error("CSV: quote inside an unquoted field at byte " + std::to_string(i));
            quoted = fieldWasQuoted = any = true;
            ++i;
        } else if (c == ',') {
            endField();
            any = true;
            ++i;
        } else if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') {
            endRecord();
            i += 2;
        } else if (c == '\n') {
            endRecord();
            ++i;
        } else {
            field += c;
            any = true;
            ++i;
        }
    }
    if (quoted) throw std::runtime_error("CSV: unterminated quoted field");
    if (any || !field.empty() || !record.empty()) endRecord();
    return records;
}

/// A finite or non-finite number written as the whole field ("nan" included); nullopt otherwise.
inline std::optional<double> parseNumber(const std::string& s) {
    if (s.empty()) return std::nullopt;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size()) return std::nullopt;
    return v;
}

/// A table: header plus rows, every row checked to have as many fields as the header.
struct CsvTable {
    std::vector<std::string> columns;
    std::vector<std::vector<std::string>> rows;

    int find(const std::string& name) const {
        for (size_t k = 0; k < columns.size(); ++k)
            if (columns[k] == name) return int(k);
        return -1;
    }
    /// Every value of a column as a number; throws when the column is missing or a cell is not a number.
    std::vector<double> numbers(const std::string& name) const {
        const int k = find(name);
        if (k < 0) throw std::runtime_error("no column " + name);
        std::vector<double> out;
        for (size_t r = 0; r < rows.size(); ++r) {
            const auto v = parseNumber(rows[r][k]);
            if (!v) throw std::runtime_error("column " + name + " row " + std::to_string(r + 1) + ": \"" + rows[r][k] + "\" is not a number");
            out.push_back(*v);
        }
        return out;
    }
};

inline CsvTable parseCsvTable(const std::string& text) {
    const CsvRecords rec = parseCsv(text);
    if (rec.empty()) throw std::runtime_error("CSV: no header");
    CsvTable t;
    t.columns = rec[0];
    for (size_t r = 1; r < rec.size(); ++r) {
        if (rec[r].size() != t.columns.size())
            throw std::runtime_error("CSV: row " + std::to_string(r) + " has " + std::to_string(rec[r].size()) +
                                     " fields, header has " + std::to_string(t.columns.size()));
        t.rows.push_back(rec[r]);
    }
    return t;
}

}  // namespace rockroll::test
