#pragma once
// A headless OpenGL 4.5 core context through EGL, shared by everything that renders (the
// occlusion oracle and the transparency renderer). No window and no display server: an EGL
// device (EGL_EXT_platform_device, a GPU's driver) when the machine has one, else Mesa's
// surfaceless platform (EGL_MESA_platform_surfaceless: llvmpipe, OpenGL on the CPU).
// No EGL or GL type appears here.
//
// Layer: vissort::gl (the package's `gl` component; docs/architecture.md).

#include <memory>
#include <string>

#include "vissort/enum_names.h"
#include "vissort/result.h"

namespace vissort {

enum class GlPlatform {
    automatic,   // "auto": a hardware EGL device if there is one, else surfaceless
    device,      // "device": an EGL device (hardware first, else Mesa's software device)
    surfaceless, // "surfaceless": Mesa's surfaceless platform
};

inline constexpr EnumName<GlPlatform> kGlPlatformNames[] = {
    {GlPlatform::automatic, "auto"},
    {GlPlatform::device, "device"},
    {GlPlatform::surfaceless, "surfaceless"},
};
/// "auto", "device" or "surfaceless", or "unknown GL platform 'NAME' (expected ...)".
inline Result<GlPlatform> parseGlPlatform(std::string_view name) {
    return parseEnum<GlPlatform>(kGlPlatformNames, name, "GL platform");
}
inline const char* glPlatformName(GlPlatform platform) {
    return enumName<GlPlatform>(kGlPlatformNames, platform);
}

/// What a context runs on, as EGL and OpenGL name it.
struct GlContextInfo {
    std::string platform; // "device" or "surfaceless"
    std::string device;   // the EGL device's driver or "Mesa software device"; empty on surfaceless
    std::string vendor;   // GL_VENDOR
    std::string renderer; // GL_RENDERER
    std::string version;  // GL_VERSION
    /// Whether OpenGL runs on the CPU: Mesa's software EGL device, or a software renderer
    /// (llvmpipe, softpipe) on any platform. Benchmarks skip what takes minutes a frame there.
    bool software = false;
};

class GlContext {
public:
    /// Creates an OpenGL 4.5 core profile context with no surface and makes it current on the
    /// calling thread. Fails with a one-line message naming what is missing: EGL, the platform,
    /// a device, or OpenGL 4.5. The library reads no environment variable; on Mesa's llvmpipe,
    /// set LP_NUM_THREADS=0 before the first context (the vissort command does): llvmpipe then
    /// rasterizes on the calling thread, 6 times faster for the oracle's many small draws and
    /// queries than with its worker threads (docs/benchmarks.md).
    static Result<std::shared_ptr<GlContext>> create(GlPlatform platform = GlPlatform::automatic);

    /// The context every part of the process shares: created by the first call, kept while any
    /// caller holds it.
    static Result<std::shared_ptr<GlContext>> shared();
    /// The platform the shared context is created on (automatic until set); takes effect when
    /// shared() next creates one.
    static void setSharedPlatform(GlPlatform platform);
    /// Makes shared() fail with reason (one line) until setSharedPlatform: for an application
    /// whose configuration rules OpenGL out, so that only the work that needs it fails.
    static void refuseShared(std::string reason);

    ~GlContext();
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;

    const GlContextInfo& info() const;
    /// Makes the context current on the calling thread: GL calls go to the current context.
    void makeCurrent() const;
    /// Makes no context current on the calling thread, if this one is: another thread may then
    /// make it current (EGL allows a context current on one thread at a time). For applications
    /// that render from several threads in turn (the Python module, under its own lock).
    void releaseCurrent() const;

private:
    struct Impl;
    explicit GlContext(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

} // namespace vissort
