#include "vissort/cpu_oracle.h"
#include "vissort/exact_oracle.h"
#include "vissort/fast_cpu_oracle.h"
#include "vissort/geometry_oracle.h"

#include <stdexcept>

namespace vissort {

bool parseOracleKind(const std::string& name, OracleKind& kind) {
    if (name == "cpu") kind = OracleKind::cpu;
    else if (name == "cpu-reference") kind = OracleKind::cpu_reference;
    else if (name == "exact") kind = OracleKind::exact;
    else return false;
    return true;
}

const char* oracleName(OracleKind kind) {
    switch (kind) {
    case OracleKind::cpu: return "cpu";
    case OracleKind::cpu_reference: return "cpu-reference";
    case OracleKind::exact: return "exact";
    }
    return "?";
}

std::unique_ptr<GeometryOracle> makeOracle(OracleKind kind, RasterMode mode) {
    switch (kind) {
    case OracleKind::cpu: {
        FastCpuOracleOptions options;
        options.mode = mode;
        return std::make_unique<FastCpuOracle>(options);
    }
    case OracleKind::cpu_reference: return std::make_unique<CpuOracle>(mode);
    case OracleKind::exact:
        if (mode != RasterMode::exact)
            throw std::invalid_argument("the exact oracle has no conservative mode (use cpu)");
        return std::make_unique<ExactOracle>();
    }
    return nullptr;
}

std::vector<OracleKind> benchmarkedOracles() { return {OracleKind::cpu_reference, OracleKind::cpu}; }

} // namespace vissort
