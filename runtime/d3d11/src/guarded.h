// INTERNAL: exceptions from the device core (ArgumentError, InvalidOperation, bad_alloc) turned into
// HRESULTs at the D3D boundary, with their message kept for GetLastErrorMessage().
#pragma once

#include <new>
#include <stdexcept>
#include <string>

#include "d3d11_impl.h"
#include "fxport/graphics/errors.h"

namespace fxport::d3d11 {

// Runs `body`, turning an exception thrown below (the device core's ArgumentError and
// InvalidOperation, std::bad_alloc) into E_INVALIDARG / E_FAIL / E_OUTOFMEMORY with its message.
template <class F>
HRESULT guarded(const char* call, F&& body) {
    try {
        return body();
    } catch (const ArgumentError& e) {
        return fail(E_INVALIDARG, std::string(call) + ": " + e.what());
    } catch (const std::bad_alloc&) {
        return fail(E_OUTOFMEMORY, std::string(call) + ": out of memory");
    } catch (const std::exception& e) {
        return fail(E_FAIL, std::string(call) + ": " + e.what());
    }
}

}  // namespace fxport::d3d11
