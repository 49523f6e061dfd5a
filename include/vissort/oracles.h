#pragma once
// Every occlusion oracle by kind: the one place that knows them all, so that the orderer, the
// renderer and applications need only the GeometryOracle interface (geometry_oracle.h).
//
// Layer: vissort::oracles (the package's `oracles` component; docs/architecture.md).

#include <cstdint>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "vissort/enum_names.h"
#include "vissort/geometry_oracle.h"
#include "vissort/result.h"

namespace vissort {

enum class OracleKind {
    cpu,           // "cpu": the tiled CPU rasterizer (cpu_oracle.h), the default
    cpu_reference, // "cpu-reference": the plain rasterizer that defines the cpu answers
                   // (cpu_reference_oracle.h); cpu gives identical answers, faster
    exact,         // "exact": ray casting at pixel centres, decided by the exact fragment
                   // model (exact_oracle.h)
    gl,            // "gl": OpenGL occlusion queries through headless EGL (gl_oracle.h)
};

inline constexpr EnumName<OracleKind> kOracleKindNames[] = {
    {OracleKind::cpu, "cpu"},
    {OracleKind::cpu_reference, "cpu-reference"},
    {OracleKind::exact, "exact"},
    {OracleKind::gl, "gl"},
};

/// "cpu", "cpu-reference", "exact" or "gl"; else "unknown oracle 'NAME' (expected ...)".
inline Result<OracleKind> parseOracleKind(std::string_view name) {
    return parseEnum<OracleKind>(kOracleKindNames, name, "oracle");
}
inline const char* oracleName(OracleKind kind) {
    return enumName<OracleKind>(kOracleKindNames, kind);
}

/// How an oracle samples and may use the machine. Its answers never depend on threads or SIMD.
struct OracleOptions {
    /// The cpu oracle's threads for pass-level batches, the calling thread included
    /// (CpuOracleOptions::threads): 1 keeps all work on the calling thread; 0 = one per core.
    uint32_t threads = 1;
    /// The cpu oracle walks rows with AVX2 where the CPU has it (CpuOracleOptions).
    bool allow_simd = true;

    friend bool operator==(const OracleOptions&, const OracleOptions&) = default;
};

/// The oracle of that kind with those options. The gl oracle uses
/// the process's shared context (GlContext::shared); when there is none, or vissort was built
/// without OpenGL, the result is a one-line message naming what is missing.
Result<std::unique_ptr<GeometryOracle>> makeOracle(OracleKind kind,
                                                   const OracleOptions& options = {});

/// The rasterizing oracles that `vissort bench oracle` compares (the exact oracle ray-casts every
/// pixel when bound, so it is a reference, not a contender).
std::vector<OracleKind> benchmarkedOracles();

} // namespace vissort
