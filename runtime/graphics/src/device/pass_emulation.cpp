// setPassEmulation (pass_emulation.h).
#include "device/pass_emulation.h"

#include "device/device_impl.h"

namespace fxport {

void setPassEmulation(GraphicsDevice& device, const PassEmulation& emulation) { deviceImpl(device).emulation = emulation; }

}  // namespace fxport
