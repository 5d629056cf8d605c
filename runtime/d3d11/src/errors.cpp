// HRESULTs with a sentence: the last failure's message per thread (GetLastErrorMessage).
#include <string>

#include "d3d11_impl.h"

namespace fxport::d3d11 {

namespace {
thread_local std::string lastMessage;
}

const char* GetLastErrorMessage() { return lastMessage.c_str(); }

HRESULT fail(HRESULT code, const std::string& message) {
    lastMessage = message;
    return code;
}

HRESULT succeed() {
    lastMessage.clear();
    return S_OK;
}

void note(const std::string& message) { lastMessage = message; }

}  // namespace fxport::d3d11
