// ComPtr: a holder of one reference to a D3D object (Microsoft::WRL::ComPtr's names): copies add a
// reference, destruction releases it. `device->CreateBuffer(&desc, &data, buffer.GetAddressOf())`.
#pragma once

#include <cstddef>
#include <utility>

#include "fxport/d3d11/com_identity.h"

namespace fxport::d3d11 {

template <class T>
class ComPtr {
public:
    ComPtr() = default;
    ComPtr(std::nullptr_t) {}
    ComPtr(T* p) : p_(p) { if (p_) p_->AddRef(); }
    ComPtr(const ComPtr& o) : p_(o.p_) { if (p_) p_->AddRef(); }
    ComPtr(ComPtr&& o) noexcept : p_(std::exchange(o.p_, nullptr)) {}
    ~ComPtr() { Reset(); }
    ComPtr& operator=(ComPtr o) noexcept { std::swap(p_, o.p_); return *this; }
    T* Get() const { return p_; }
    T* operator->() const { return p_; }
    explicit operator bool() const { return p_ != nullptr; }
    // For a Create* call's out parameter: releases what it held first.
    T** GetAddressOf() { Reset(); return &p_; }
    T** ReleaseAndGetAddressOf() { return GetAddressOf(); }
    T* const* GetAddressOfConst() const { return &p_; }  // for Set* calls taking arrays of one
    unsigned Reset() {
        unsigned left = 0;
        if (p_) left = p_->Release();
        p_ = nullptr;
        return left;
    }
    // WRL's As: the object's interface U through QueryInterface (`device.As(&dxgiDevice)`).
    template <class U>
    auto As(ComPtr<U>* other) const {
        return p_->QueryInterface(uuidOf<U>(), reinterpret_cast<void**>(other->ReleaseAndGetAddressOf()));
    }
    // Takes over a reference the caller owns (no AddRef).
    void Attach(T* p) { Reset(); p_ = p; }
    T* Detach() { return std::exchange(p_, nullptr); }

private:
    T* p_ = nullptr;
};

}  // namespace fxport::d3d11
