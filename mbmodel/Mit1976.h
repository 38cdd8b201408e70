#pragma once
// The 1976 MIT report's published numbers (Tables 1, 3, 4, §3.1, what §3.2 says of its
// roll-against-speed figures, §4.3's describing function), read at run time from the
// one data file scenarios/reference/mit1976.toml. Every number there carries its
// unit, its source (section, table or figure, car and amplitude) and, optionally, the
// report's words that print it; nothing published is a C++ literal. Keys are dotted
// paths, arrays of tables indexed: "table3[1].max_roll".
#include "mbmodel/DataFiles.h"

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace rockroll {

struct PublishedValue {
    double value = 0;
    std::string unit;       ///< as the report prints it: "lb", "kip", "in", "deg", "mph", "Hz", "%"
    std::string qualifier;  ///< the report's own hedge ("up to", "about"), or empty
    std::string source;     ///< section, table or figure, with the car and amplitude
    std::string page;       ///< page of the report ("?": the OCR text has no page numbers)
    std::string quote;      ///< the report's words that print it (verbatim from the OCR text), or empty
};

/// A text quoted from the report ({ text, source, page, quote } in the data file).
struct PublishedText {
    std::string text;
    std::string source;
    std::string page;
    std::string quote;  ///< the report's sentence the text is taken from, or empty
};

class Mit1976 {
public:
    /// The data file, loaded once (thread-safe); throws std::runtime_error when it is
    /// missing or malformed.
    static const Mit1976& get();

    /// Where the data file is looked for, in order: $ROCKROLL_MIT1976 when set, then
    /// scenarios/reference/mit1976.toml in each of getDataDirs() (mbmodel/DataFiles.h).
    static std::vector<std::filesystem::path> getSearchPaths();
    static std::filesystem::path findFile();  ///< the first search path that exists; throws when none

    explicit Mit1976(const std::filesystem::path& file);

    bool has(const std::string& key) const { return values_.count(key) > 0; }
    bool hasText(const std::string& key) const { return texts_.count(key) > 0; }  ///< a quoted text or a label
    /// The published value at `key`; throws unless it exists and is printed in `unit`.
    const PublishedValue& value(const std::string& key, std::string_view unit) const;
    double operator()(const std::string& key, std::string_view unit) const { return value(key, unit).value; }
    /// A text quoted from the report, or a label of this file ("table3[0].car"); throws when missing.
    const std::string& text(const std::string& key) const;
    /// The number of tables in the array of tables at `key` ("table3"), 0 when none.
    size_t count(const std::string& key) const;

    const std::filesystem::path& getFile() const { return file_; }
    const std::map<std::string, PublishedValue>& getValues() const { return values_; }
    /// The texts quoted from the report ({ text, ... } tables; not the file's plain-string labels).
    const std::map<std::string, PublishedText>& getQuotedTexts() const { return quotedTexts_; }

private:
    std::filesystem::path file_;
    std::map<std::string, PublishedValue> values_;
    std::map<std::string, std::string> texts_;
    std::map<std::string, PublishedText> quotedTexts_;
    std::map<std::string, size_t> counts_;
};

/// A published number as the report prints it: "90 000" (thousands grouped by a space), "2", "19.5".
std::string formatPublished(double value);
/// A published value with the report's hedge: "up to 90 000"; with its unit: "up to 90 000 lb".
std::string formatPublished(const PublishedValue& v, bool withUnit = false);

}  // namespace rockroll
