// COM's interface identifiers with D3D's names: GUID/IID/REFIID, the IID_ constants, and
// __uuidof(T) for compilers other than MSVC, so D3D code's `__uuidof(ID3D11Texture2D)` and
// `QueryInterface(__uuidof(IDXGIDevice), ...)` compile unchanged. An interface gets its identifier
// with FXPORT_INTERFACE_ID next to its declaration (d3d11_interfaces.h, dxgi.h); __uuidof of one
// without an identifier does not compile.
#pragma once

#include <cstdint>
#include <type_traits>

namespace fxport::d3d11 {

struct GUID {
    std::uint32_t Data1 = 0;
    std::uint16_t Data2 = 0, Data3 = 0;
    std::uint8_t Data4[8] = {};
};
using IID = GUID;
using REFIID = const IID&;
using REFGUID = const GUID&;
constexpr bool operator==(const GUID& a, const GUID& b) {
    if (a.Data1 != b.Data1 || a.Data2 != b.Data2 || a.Data3 != b.Data3) return false;
    for (int i = 0; i < 8; ++i)
        if (a.Data4[i] != b.Data4[i]) return false;
    return true;
}
constexpr bool IsEqualGUID(REFGUID a, REFGUID b) { return a == b; }
constexpr bool IsEqualIID(REFIID a, REFIID b) { return a == b; }

// The identifier of interface T (InterfaceId<T>::value), for __uuidof.
template <class T>
struct InterfaceId;
template <class T>
constexpr const IID& uuidOf() {
    return InterfaceId<std::remove_cvref_t<T>>::value;
}

}  // namespace fxport::d3d11

// IID_<Interface> and InterfaceId<Interface>, at namespace fxport::d3d11's scope.
#define FXPORT_INTERFACE_ID(Interface, d1, d2, d3, ...)                                   \
    inline constexpr ::fxport::d3d11::IID IID_##Interface = {d1, d2, d3, {__VA_ARGS__}}; \
    template <>                                                                          \
    struct InterfaceId<Interface> {                                                      \
        static constexpr const IID& value = IID_##Interface;                             \
    };

// MSVC has __uuidof built in; elsewhere it is the type's (or an expression's type's) InterfaceId,
// as MinGW's headers do it for GCC. __typeof__ takes both, so IID_PPV_ARGS's `__uuidof(**(pp))` works.
#if !defined(_MSC_VER) && !defined(__uuidof)
#define __uuidof(T) ::fxport::d3d11::uuidOf<__typeof__(T)>()
#endif
// `QueryInterface(IID_PPV_ARGS(&p))` for a raw interface pointer p (ComPtr: use As).
#ifndef IID_PPV_ARGS
#define IID_PPV_ARGS(pp) __uuidof(**(pp)), reinterpret_cast<void**>(pp)
#endif
