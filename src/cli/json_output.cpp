#include "cli/json_output.h"

#include <fstream>

#include "cli/cli_common.h"

namespace vissort::cli {

int writeJsonFile(const std::string& path, const nlohmann::json& document) {
    std::ofstream out(path);
    out << document.dump(1) << '\n';
    if (!out)
        return fail(kExitFailure, "cannot write " + path);
    return kExitOk;
}

} // namespace vissort::cli
