// glslang needs one process-wide initialisation; every user calls this first (thread-safe, once).
#pragma once

namespace fxport::xlate {
void ensureGlslangInitialized();
}
