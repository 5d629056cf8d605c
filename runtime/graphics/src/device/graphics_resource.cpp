#include "fxport/graphics/graphics_resource.h"

#include <algorithm>

#include "device/device_impl.h"
#include "fxport/graphics/errors.h"

namespace fxport {

GraphicsResource::GraphicsResource(fxport::GraphicsDevice& device, const char* kind)
    : device_(&device), kind_(kind), serial_(deviceImpl(device).nextSerial++) {
    deviceImpl(device).resources.push_back(this);
}

GraphicsResource::~GraphicsResource() {
    // Derived destructors have released GL objects already (disposeFromDestructor); here the
    // device only forgets the address.
    if (device_) deviceImpl(*device_).forget(this);
}

void GraphicsResource::Dispose() {
    if (disposed_) return;
    releaseGpuObjects();
    disposed_ = true;
}

void GraphicsResource::disposeFromDestructor() { Dispose(); }

void GraphicsResource::throwIfDisposed(const char* operation) const {
    if (disposed_) throw InvalidOperation(describe() + ": " + operation + " after Dispose()");
}

std::string GraphicsResource::describe() const {
    if (!Name.empty()) return std::string(kind_) + " '" + Name + "'";
    return std::string(kind_) + " #" + std::to_string(serial_);
}

}  // namespace fxport
