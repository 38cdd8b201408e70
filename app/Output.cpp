#include "app/Output.h"
#include "mbmodel/CsvWriter.h"

#include <cmath>
#include <fmt/format.h>
#include <fstream>

namespace rockroll::app {

/// Writes through a temporary name and renames when complete, so a reader never
/// sees a half-written file.
void writeAtomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write) {
    const std::filesystem::path tmp = path.string() + ".tmp";
    {
        std::ofstream out(tmp);
        if (!out) throw std::runtime_error(fmt::format("cannot write {}", tmp.string()));
        write(out);
        out.flush();
        if (!out) throw std::runtime_error(fmt::format("error while writing {}", tmp.string()));
    }
    std::filesystem::rename(tmp, path);
}

void writeHistoryCsv(std::ostream& out, const TimeHistory& h, const std::vector<std::string>& columns, int digits) {
    const std::vector<std::string>& names = columns.empty() ? h.names : columns;
    std::vector<int> index;
    for (const auto& c : names) index.push_back(h.column(c));
    CsvWriter csv(out, names);
    std::vector<CsvCell> cells;
    for (const auto& row : h.samples) {
        cells.clear();
        for (int k : index) cells.push_back(CsvCell::significant(row.at(k), digits));
        csv.writeRow(cells);
    }
}

}  // namespace rockroll::app
