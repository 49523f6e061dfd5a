#include "vissort/oracles.h"

#include <stdexcept>

#include "vissort/cpu_oracle.h"
#include "vissort/cpu_reference_oracle.h"
#include "vissort/exact_oracle.h"

#if VISSORT_WITH_GL
#include "vissort/gl_context.h"
#include "vissort/gl_oracle.h"
#endif

namespace vissort {

Result<std::unique_ptr<GeometryOracle>> makeOracle(OracleKind kind, const OracleOptions& options) {
    using Made = Result<std::unique_ptr<GeometryOracle>>;
    switch (kind) {
    case OracleKind::cpu: {
        CpuOracleOptions fast;
        fast.threads = options.threads;
        fast.allow_simd = options.allow_simd;
        return {std::make_unique<CpuOracle>(fast), {}};
    }
    case OracleKind::cpu_reference:
        return {std::make_unique<CpuReferenceOracle>(), {}};
    case OracleKind::exact:
        return {std::make_unique<ExactOracle>(), {}};
    case OracleKind::gl: {
#if VISSORT_WITH_GL
        Result<std::shared_ptr<GlContext>> context = GlContext::shared();
        if (!context)
            return Made::failure(context.error);
        return {std::make_unique<GlOracle>(*context.value), {}};
#else
        return Made::failure("this vissort was built without OpenGL (VISSORT_WITH_GL=OFF): the gl "
                             "oracle is not available");
#endif
    }
    }
    throw std::invalid_argument("unknown oracle kind");
}

std::vector<OracleKind> benchmarkedOracles() {
    return {OracleKind::cpu_reference, OracleKind::cpu};
}

} // namespace vissort
