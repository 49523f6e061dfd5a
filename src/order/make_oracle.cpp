#include "vissort/cpu_oracle.h"
#include "vissort/exact_oracle.h"
#include "vissort/fast_cpu_oracle.h"
#include "vissort/geometry_oracle.h"

#include <stdexcept>

#if VISSORT_WITH_GL
#include "vissort/gl_oracle.h"
#endif

namespace vissort {

bool parseOracleKind(const std::string& name, OracleKind& kind) {
    if (name == "cpu") kind = OracleKind::cpu;
    else if (name == "cpu-reference") kind = OracleKind::cpu_reference;
    else if (name == "exact") kind = OracleKind::exact;
    else if (name == "gl") kind = OracleKind::gl;
    else return false;
    return true;
}

const char* oracleName(OracleKind kind) {
    switch (kind) {
    case OracleKind::cpu: return "cpu";
    case OracleKind::cpu_reference: return "cpu-reference";
    case OracleKind::exact: return "exact";
    case OracleKind::gl: return "gl";
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
    case OracleKind::gl: {
        if (mode != RasterMode::exact)
            throw std::invalid_argument("the gl oracle has no conservative mode (use cpu)");
#if VISSORT_WITH_GL
        Loaded<std::shared_ptr<GlContext>> context = GlContext::shared();
        if (!context) throw std::runtime_error(context.error);
        return std::make_unique<GlOracle>(*context.value);
#else
        throw std::runtime_error("this vissort was built without OpenGL (VISSORT_WITH_GL=OFF)");
#endif
    }
    }
    return nullptr;
}

std::vector<OracleKind> benchmarkedOracles() { return {OracleKind::cpu_reference, OracleKind::cpu}; }

} // namespace vissort
