// A headless OpenGL context through EGL (gl_context.h).
// This work is based on: the Khronos EGL 1.5 specification, and the extensions
// EGL_EXT_platform_device, EGL_EXT_device_enumeration, EGL_MESA_platform_surfaceless,
// EGL_KHR_surfaceless_context and EGL_KHR_no_config_context.

#include "vissort/gl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <vector>

#include "gl/gl_api.h"

namespace vissort {
namespace {

// Whether a space-separated extension string names ext (the whole word).
bool hasExtension(const char* extensions, const char* ext) {
    if (extensions == nullptr)
        return false;
    const std::size_t length = std::strlen(ext);
    for (const char* p = extensions; (p = std::strstr(p, ext)) != nullptr; p += length)
        if ((p == extensions || p[-1] == ' ') && (p[length] == ' ' || p[length] == '\0'))
            return true;
    return false;
}

std::string eglErrorName(EGLint error) {
    switch (error) {
    case EGL_NOT_INITIALIZED:
        return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
        return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
        return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
        return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
        return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
        return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY:
        return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
        return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER:
        return "EGL_BAD_PARAMETER";
    default:
        return "EGL error " + std::to_string(error);
    }
}

struct Display {
    EGLDisplay display = EGL_NO_DISPLAY;
    std::string platform, device;
    bool software_device = false; // Mesa's software EGL device
};

// Mesa's renderers that draw on the CPU, as GL_RENDERER names them.
bool softwareRenderer(const std::string& renderer) {
    return renderer.find("llvmpipe") != std::string::npos ||
           renderer.find("softpipe") != std::string::npos;
}

// The EGL devices, hardware ones first (Mesa lists its software device among them).
Result<Display> deviceDisplay(const char* client_extensions, bool hardware_only) {
    if (!hasExtension(client_extensions, "EGL_EXT_platform_device") ||
        !hasExtension(client_extensions, "EGL_EXT_device_enumeration"))
        return Result<Display>::failure("EGL has no device platform (EGL_EXT_platform_device)");
    const auto query_devices =
        reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    const auto query_string = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
        eglGetProcAddress("eglQueryDeviceStringEXT"));
    EGLint count = 0;
    if (query_devices == nullptr || query_string == nullptr || !query_devices(0, nullptr, &count))
        return Result<Display>::failure("cannot enumerate EGL devices");
    std::vector<EGLDeviceEXT> devices(std::size_t(std::max(count, 0)));
    if (count > 0 && !query_devices(count, devices.data(), &count))
        return Result<Display>::failure("cannot enumerate EGL devices");
    for (bool software : {false, true}) {
        if (software && hardware_only)
            break;
        for (EGLDeviceEXT device : devices) {
            const char* extensions = query_string(device, EGL_EXTENSIONS);
            if (hasExtension(extensions, "EGL_MESA_device_software") != software)
                continue;
            Display d;
            d.display = eglGetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
            if (d.display == EGL_NO_DISPLAY)
                continue;
            d.platform = "device";
            d.software_device = software;
            if (software) {
                d.device = "Mesa software device";
            } else {
                const char* file = hasExtension(extensions, "EGL_EXT_device_drm")
                                       ? query_string(device, EGL_DRM_DEVICE_FILE_EXT)
                                       : nullptr;
                d.device = file != nullptr ? file : "hardware device";
            }
            return {d, ""};
        }
    }
    return Result<Display>::failure(hardware_only ? "no hardware EGL device"
                                                  : "no usable EGL device");
}

Result<Display> surfacelessDisplay(const char* client_extensions) {
    if (!hasExtension(client_extensions, "EGL_MESA_platform_surfaceless"))
        return Result<Display>::failure(
            "EGL has no surfaceless platform (EGL_MESA_platform_surfaceless; install Mesa's "
            "libegl-mesa0 and libgl1-mesa-dri)");
    Display d;
    d.display = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (d.display == EGL_NO_DISPLAY)
        return Result<Display>::failure("cannot open the EGL surfaceless display");
    d.platform = "surfaceless";
    return {d, ""};
}

Result<Display> chooseDisplay(GlPlatform platform) {
    // Without EGL 1.5 client extensions there is no platform to ask for.
    const char* client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (client_extensions == nullptr)
        return Result<Display>::failure("EGL has no client extensions (no EGL 1.5 driver)");
    switch (platform) {
    case GlPlatform::device:
        return deviceDisplay(client_extensions, false);
    case GlPlatform::surfaceless:
        return surfacelessDisplay(client_extensions);
    case GlPlatform::automatic:
        break;
    }
    Result<Display> device = deviceDisplay(client_extensions, true);
    if (device)
        return device;
    Result<Display> surfaceless = surfacelessDisplay(client_extensions);
    if (surfaceless)
        return surfaceless;
    return Result<Display>::failure(device.error + ", and " + surfaceless.error);
}

std::string glString(GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return s != nullptr ? s : "";
}

} // namespace

struct GlContext::Impl {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    GlContextInfo info;

    Impl() = default;
    Impl(const Impl&) = delete;
    Impl& operator=(const Impl&) = delete;
    // The display is left initialized: EGL displays are process-wide, and terminating one would
    // pull it from under any other context on it.
    ~Impl() {
        if (context == EGL_NO_CONTEXT)
            return;
        if (eglGetCurrentContext() == context)
            eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display, context);
    }
};

GlContext::GlContext(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
GlContext::~GlContext() = default;

const GlContextInfo& GlContext::info() const {
    return impl_->info;
}

void GlContext::makeCurrent() const {
    if (eglGetCurrentContext() != impl_->context)
        eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, impl_->context);
}

void GlContext::releaseCurrent() const {
    if (eglGetCurrentContext() == impl_->context)
        eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

Result<std::shared_ptr<GlContext>> GlContext::create(GlPlatform platform) {
    using Made = Result<std::shared_ptr<GlContext>>;
    Result<Display> chosen = chooseDisplay(platform);
    if (!chosen)
        return Made::failure("no OpenGL context: " + chosen.error);
    auto impl = std::make_unique<Impl>();
    impl->display = chosen.value->display;
    impl->info.platform = chosen.value->platform;
    impl->info.device = chosen.value->device;
    const auto failure = [&](const std::string& what) {
        return Made::failure("no OpenGL context on the EGL " + impl->info.platform +
                             " platform: " + what + " (" + eglErrorName(eglGetError()) + ")");
    };

    EGLint major = 0, minor = 0;
    if (!eglInitialize(impl->display, &major, &minor))
        return failure("eglInitialize failed");
    const char* extensions = eglQueryString(impl->display, EGL_EXTENSIONS);
    if (!hasExtension(extensions, "EGL_KHR_surfaceless_context"))
        return failure("the display cannot make a context current without a surface");
    if (!eglBindAPI(EGL_OPENGL_API))
        return failure("no desktop OpenGL");
    // Nothing is drawn to a surface, so any config will do; none at all where allowed.
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!hasExtension(extensions, "EGL_KHR_no_config_context")) {
        const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLint count = 0;
        if (!eglChooseConfig(impl->display, wanted, &config, 1, &count) || count < 1)
            return failure("no config for desktop OpenGL");
    }
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 4,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 5,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    impl->context = eglCreateContext(impl->display, config, EGL_NO_CONTEXT, attributes);
    if (impl->context == EGL_NO_CONTEXT)
        return failure("no OpenGL 4.5 core profile context");
    if (!eglMakeCurrent(impl->display, EGL_NO_SURFACE, EGL_NO_SURFACE, impl->context))
        return failure("cannot make the context current");
    impl->info.vendor = glString(GL_VENDOR);
    impl->info.renderer = glString(GL_RENDERER);
    impl->info.version = glString(GL_VERSION);
    impl->info.software = chosen.value->software_device || softwareRenderer(impl->info.renderer);
    return {std::shared_ptr<GlContext>(new GlContext(std::move(impl))), ""};
}

namespace {
std::mutex shared_mutex;
GlPlatform shared_platform = GlPlatform::automatic;
std::string shared_refusal; // non-empty: shared() fails with it
} // namespace

void GlContext::setSharedPlatform(GlPlatform platform) {
    std::lock_guard<std::mutex> lock(shared_mutex);
    shared_platform = platform;
    shared_refusal.clear();
}

void GlContext::refuseShared(std::string reason) {
    std::lock_guard<std::mutex> lock(shared_mutex);
    shared_refusal = std::move(reason);
}

Result<std::shared_ptr<GlContext>> GlContext::shared() {
    static std::weak_ptr<GlContext> current;
    std::lock_guard<std::mutex> lock(shared_mutex);
    if (!shared_refusal.empty())
        return Result<std::shared_ptr<GlContext>>::failure(shared_refusal);
    if (std::shared_ptr<GlContext> context = current.lock()) {
        context->makeCurrent();
        return {context, ""};
    }
    Result<std::shared_ptr<GlContext>> created = create(shared_platform);
    if (created)
        current = *created.value;
    return created;
}

} // namespace vissort
