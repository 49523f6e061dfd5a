// The JSON records of a transparency benchmark row (transparency_records.h).

#include "cli/transparency_records.h"

namespace vissort::cli {

nlohmann::json transparencyRecords(const bench::TransparencyBenchRow& row) {
    nlohmann::json records = nlohmann::json::array();
    const double vissort_ms = row.methods[bench::kTransparencyVissort].ms;
    for (std::size_t i = 0; i < row.methods.size(); ++i) {
        const bench::TransparencyMeasured& m = row.methods[i];
        nlohmann::json record = {{"scene", row.family},
                                 {"specification", row.specification},
                                 {"depth", row.depth},
                                 {"depth_seen", row.seen},
                                 {"method", blendMethodName(bench::kTransparencyMethods[i])},
                                 {"ms", m.ms},
                                 {"order_ms", m.order_ms},
                                 {"passes", m.passes},
                                 {"fragments", m.fragments},
                                 {"ms_over_vissort", m.ms / vissort_ms}};
        if (bench::kTransparencyMethods[i] != BlendMethod::linked_list)
            record["error"] = {{"max_abs", m.max_abs}, {"rmse", m.rmse}};
        records.push_back(std::move(record));
    }
    return records;
}

} // namespace vissort::cli
