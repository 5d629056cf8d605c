#include "frontend/glslang_process.h"

#include <glslang/Public/ShaderLang.h>

#include <mutex>

namespace fxport::xlate {

void ensureGlslangInitialized() {
    // glslang's process state is global; InitializeProcess is reference-counted and we never
    // finalize (the OS reclaims it), so shader compiles stay cheap for the whole run.
    static std::once_flag once;
    std::call_once(once, [] { glslang::InitializeProcess(); });
}

}  // namespace fxport::xlate
