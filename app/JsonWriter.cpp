#include "app/JsonWriter.h"
#include "app/Output.h"

namespace rockroll::app {

void writeJsonFile(const std::filesystem::path& path, const nlohmann::ordered_json& document) {
    writeAtomically(path, [&](std::ostream& out) { out << document.dump(2) << '\n'; });
}

}  // namespace rockroll::app
