// The process's Embree device (embree_device.h).
#include "exact/embree_device.h"

#include <stdexcept>
#include <string>

namespace vissort::detail {

RTCDevice sharedEmbreeDevice() {
    static const EmbreeDevice device(rtcNewDevice(nullptr));
    if (!device.get()) {
        throw std::runtime_error("cannot create an Embree device (error " +
                                 std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
    }
    return device.get();
}

} // namespace vissort::detail
