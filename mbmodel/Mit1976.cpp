#include "mbmodel/Mit1976.h"
#include "mbmodel/DataFiles.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>
#include <stdexcept>
#include <toml++/toml.h>
#include <unistd.h>

namespace rockroll {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const fs::path& file, const std::string& key, const std::string& what) {
    throw DataFileError(fmt::format("{}: {}: {}", file.string(), key, what));
}

std::string getString(const fs::path& file, const std::string& key, const toml::table& t, const char* name,
                      bool required) {
    const toml::node* n = t.get(name);
    if (!n) {
        if (required) fail(file, key, fmt::format("missing \"{}\"", name));
        return "";
    }
    const auto s = n->value<std::string>();
    if (!s) fail(file, key, fmt::format("\"{}\" must be a string", name));
    return *s;
}

}  // namespace

Mit1976::Mit1976(const fs::path& file) : file_(file) {
    toml::table root;
    try {
        root = toml::parse_file(file.string());
    } catch (const toml::parse_error& e) {
        throw DataFileError(fmt::format("{}: {} (line {})", file.string(), std::string(e.description()),
                                             e.source().begin.line));
    }
    // Walks the file: { value, unit, qualifier, source, page, quote } tables are numbers,
    // { text, source, page, quote } tables quoted texts, plain strings labels; a bare number is
    // refused (no unit, no source), and so is a field of neither list.
    auto refuseUnknown = [&](const toml::table& t, const std::string& key, std::initializer_list<std::string_view> known) {
        for (const auto& [k, _] : t)
            if (std::find(known.begin(), known.end(), k.str()) == known.end())
                fail(file_, key, fmt::format("unknown field \"{}\"", std::string(k.str())));
    };
    auto walk = [&](auto&& self, const toml::node& node, const std::string& key) -> void {
        if (const toml::table* t = node.as_table()) {
            if (t->contains("value")) {
                PublishedValue v;
                const auto x = (*t)["value"].value<double>();
                if (!x) fail(file_, key, "\"value\" must be a number");
                v.value = *x;
                v.unit = getString(file_, key, *t, "unit", true);
                v.qualifier = getString(file_, key, *t, "qualifier", false);
                v.source = getString(file_, key, *t, "source", true);
                v.page = getString(file_, key, *t, "page", true);
                v.quote = getString(file_, key, *t, "quote", false);
                refuseUnknown(*t, key, {"value", "unit", "qualifier", "source", "page", "quote"});
                values_[key] = v;
                return;
            }
            if (t->contains("text")) {
                PublishedText q;
                q.text = getString(file_, key, *t, "text", true);
                q.source = getString(file_, key, *t, "source", true);
                q.page = getString(file_, key, *t, "page", true);
                q.quote = getString(file_, key, *t, "quote", false);
                refuseUnknown(*t, key, {"text", "source", "page", "quote"});
                texts_[key] = q.text;
                quotedTexts_[key] = q;
                return;
            }
            for (const auto& [k, child] : *t) self(self, child, key.empty() ? std::string(k.str()) : key + "." + std::string(k.str()));
            return;
        }
        if (const toml::array* a = node.as_array()) {
            counts_[key] = a->size();
            for (size_t i = 0; i < a->size(); ++i) self(self, *a->get(i), fmt::format("{}[{}]", key, i));
            return;
        }
        if (const auto s = node.value<std::string>()) {
            texts_[key] = *s;
            return;
        }
        fail(file_, key, "a bare value: write it as { value = ..., unit = \"...\", source = \"...\", page = \"...\", "
                        "quote = \"...\" }");
    };
    walk(walk, root, "");
}

const PublishedValue& Mit1976::value(const std::string& key, std::string_view unit) const {
    const auto it = values_.find(key);
    if (it == values_.end()) throw DataFileError(fmt::format("{}: no published value \"{}\"", file_.string(), key));
    if (it->second.unit != unit)
        throw DataFileError(fmt::format("{}: {} is in {}, asked for in {}", file_.string(), key, it->second.unit, unit));
    return it->second;
}

const std::string& Mit1976::text(const std::string& key) const {
    const auto it = texts_.find(key);
    if (it == texts_.end()) throw DataFileError(fmt::format("{}: no text \"{}\"", file_.string(), key));
    return it->second;
}

size_t Mit1976::count(const std::string& key) const {
    const auto it = counts_.find(key);
    return it == counts_.end() ? 0 : it->second;
}

std::vector<fs::path> Mit1976::getSearchPaths() {
    std::vector<fs::path> paths;
    if (const char* env = std::getenv("ROCKROLL_MIT1976"); env && *env) paths.emplace_back(env);
    for (const auto& dir : getDataDirs()) paths.push_back(dir / "scenarios" / "reference" / "mit1976.toml");
    return paths;
}

fs::path Mit1976::findFile() {
    std::vector<std::string> tried;
    for (const auto& p : getSearchPaths()) {
        if (fs::is_regular_file(p)) return p;
        tried.push_back(p.string());
    }
    throw DataFileError(fmt::format("the 1976 report's numbers (mit1976.toml) are in none of: {}", fmt::join(tried, ", ")));
}

const Mit1976& Mit1976::get() {
    static const Mit1976 instance(findFile());
    return instance;
}

std::string formatPublished(double value) {
    std::string s = fmt::format("{:g}", value);
    if (value != std::round(value) || std::abs(value) < 10000 || s.find('e') != std::string::npos) return s;
    const bool negative = s[0] == '-';
    std::string digits = negative ? s.substr(1) : s, out;
    for (size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ' ';
        out += digits[i];
    }
    return negative ? "-" + out : out;
}

std::string formatPublished(const PublishedValue& v, bool withUnit) {
    std::string out = v.qualifier.empty() ? formatPublished(v.value) : v.qualifier + " " + formatPublished(v.value);
    if (withUnit && !v.unit.empty()) out += " " + v.unit;
    return out;
}

}  // namespace rockroll
