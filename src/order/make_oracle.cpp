#include "vissort/cpu_oracle.h"
#include "vissort/exact_oracle.h"
#include "vissort/geometry_oracle.h"

namespace vissort {

bool parseOracleKind(const std::string& name, OracleKind& kind) {
    if (name == "cpu") kind = OracleKind::cpu;
    else if (name == "exact") kind = OracleKind::exact;
    else return false;
    return true;
}

const char* oracleName(OracleKind kind) { return kind == OracleKind::cpu ? "cpu" : "exact"; }

std::unique_ptr<GeometryOracle> makeOracle(OracleKind kind) {
    if (kind == OracleKind::exact) return std::make_unique<ExactOracle>();
    return std::make_unique<CpuOracle>();
}

std::vector<OracleKind> benchmarkedOracles() { return {OracleKind::cpu}; }

} // namespace vissort
