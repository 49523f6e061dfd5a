#pragma once
// The process's one Embree device and an owner for Embree's handles: shared by the exact ray
// caster and the volume ray caster (src/volume/), which reaches this header through
// vissort_internal_headers(... SHARED). Internal.

#include <embree3/rtcore.h>

namespace vissort::detail {

// Owns one Embree handle (device or scene) and releases it once: non-copyable RAII.
template <class Handle, void (*release)(Handle)> class EmbreeHandle {
public:
    explicit EmbreeHandle(Handle handle) : handle_(handle) {}
    ~EmbreeHandle() {
        if (handle_)
            release(handle_);
    }
    EmbreeHandle(const EmbreeHandle&) = delete;
    EmbreeHandle& operator=(const EmbreeHandle&) = delete;

    Handle get() const { return handle_; }

private:
    Handle handle_;
};

using EmbreeDevice = EmbreeHandle<RTCDevice, rtcReleaseDevice>;
using EmbreeScene = EmbreeHandle<RTCScene, rtcReleaseScene>;

/// One device for the process: creating one starts Embree's thread pool, too costly per frame.
/// Throws std::runtime_error when no device can be created.
RTCDevice sharedEmbreeDevice();

} // namespace vissort::detail
