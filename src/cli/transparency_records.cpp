// The JSON records of a transparency benchmark row (transparency_records.h).

#include "cli/transparency_records.h"

namespace vissort::cli {

namespace {

// One record a method, at `samples` a pixel.
void addRecords(const bench::TransparencyBenchRow& row,
                const std::vector<bench::TransparencyMeasured>& methods, uint32_t samples,
                nlohmann::json& records) {
    const double vissort_ms = methods[bench::kTransparencyVissort].ms;
    for (std::size_t i = 0; i < methods.size(); ++i) {
        const bench::TransparencyMeasured& m = methods[i];
        nlohmann::json record = {{"scene", row.family},
                                 {"specification", row.specification},
                                 {"depth", row.depth},
                                 {"depth_seen", row.seen},
                                 {"method", blendMethodName(bench::kTransparencyMethods[i])},
                                 {"samples", samples},
                                 {"ms", m.ms},
                                 {"order_ms", m.order_ms},
                                 {"passes", m.passes},
                                 {"fragments", m.fragments},
                                 {"ms_over_vissort", m.ms / vissort_ms}};
        if (samples > 1)
            record["ms_over_one_sample"] = m.ms / row.methods[i].ms;
        if (bench::kTransparencyMethods[i] != BlendMethod::linked_list)
            record["error"] = {{"max_abs", m.max_abs}, {"rmse", m.rmse}};
        records.push_back(std::move(record));
    }
}

} // namespace

nlohmann::json transparencyRecords(const bench::TransparencyBenchRow& row) {
    nlohmann::json records = nlohmann::json::array();
    addRecords(row, row.methods, 1, records);
    if (!row.sampled.empty())
        addRecords(row, row.sampled, row.samples, records);
    return records;
}

} // namespace vissort::cli
