// The value operand of the Interlocked* intrinsics (xlate's rewrite/interlocked_values.h): a float
// value reaches InterlockedMax/Min as fxc's saturating ftoi, and every other Interlocked* as
// ftou, whatever the destination's type. The shaders, the initial elements and the expected ones
// are vkd3d's uav-atomics (sections at lines 177 and 219 of its file), dispatched on R32_UINT and
// R32_SINT RWBuffers and read back.
#include <cstring>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

struct Values {
    std::uint32_t i;
    float a;
    float pad[2];
};

// Runs `text` (numthreads(3, 1, 1), u at u1, s at u2, i and a in b0) once on `u` and `s`.
void dispatch(Device& d, const char* text, const Values& values, std::vector<std::uint32_t>& u, std::vector<std::int32_t>& s) {
    ComPtr<ID3D11Buffer> ub = makeBuffer(d, u.data(), UINT(u.size() * 4), D3D11_BIND_UNORDERED_ACCESS);
    ComPtr<ID3D11Buffer> sb = makeBuffer(d, s.data(), UINT(s.size() * 4), D3D11_BIND_UNORDERED_ACCESS);
    ComPtr<ID3D11Buffer> cb = makeBuffer(d, &values, sizeof values, D3D11_BIND_CONSTANT_BUFFER);
    ASSERT_TRUE(ub && sb && cb);
    D3D11_UNORDERED_ACCESS_VIEW_DESC desc = {};
    desc.ViewDimension = D3D11_UAV_DIMENSION_BUFFER;
    desc.Format = DXGI_FORMAT_R32_UINT;
    desc.Buffer.NumElements = UINT(u.size());
    ComPtr<ID3D11UnorderedAccessView> uv, sv;
    ASSERT_EQ(d.device->CreateUnorderedAccessView(ub.Get(), &desc, uv.GetAddressOf()), S_OK) << lastError();
    desc.Format = DXGI_FORMAT_R32_SINT;
    desc.Buffer.NumElements = UINT(s.size());
    ASSERT_EQ(d.device->CreateUnorderedAccessView(sb.Get(), &desc, sv.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3DBlob> code = compile(text, "main", "cs_5_0");
    ASSERT_TRUE(code);
    ComPtr<ID3D11ComputeShader> cs;
    ASSERT_EQ(d.device->CreateComputeShader(code->GetBufferPointer(), code->GetBufferSize(), nullptr, cs.GetAddressOf()), S_OK) << lastError();
    d.context->CSSetShader(cs.Get(), nullptr, 0);
    d.context->CSSetConstantBuffers(0, 1, cb.GetAddressOfConst());
    ID3D11UnorderedAccessView* views[2] = {uv.Get(), sv.Get()};
    d.context->CSSetUnorderedAccessViews(1, 2, views, nullptr);
    d.context->Dispatch(1, 1, 1);
    ASSERT_EQ(lastError(), "");
    u = readBuffer<std::uint32_t>(d, ub.Get());
    s = readBuffer<std::int32_t>(d, sb.Get());
}

// uav-atomics L177: 2147483648.0 is 0x7fffffff to InterlockedMax on a uint and on an int (ftoi
// saturates; GLSL's uint() of it would be 0x80000000, its int() undefined); a uint value takes the
// int destination's type (0xffffffff is -1 to InterlockedMin).
TEST(D3D11InterlockedValues, MaxAndMinTakeASaturatedInt) {
    Device d;
    std::vector<std::uint32_t> u = {1, 1, 1};
    std::vector<std::int32_t> s = {1, 1, 1};
    dispatch(d, R"(
RWBuffer<uint> u : register(u1);
RWBuffer<int> s : register(u2);
cbuffer Values : register(b0) { uint i; float a; };
[numthreads(3, 1, 1)]
void main()
{
    InterlockedMax(u[0], i);
    InterlockedMin(u[1], i);
    InterlockedMax(u[2], a);
    InterlockedMax(s[0], i);
    InterlockedMin(s[1], i);
    InterlockedMax(s[2], a);
})",
             {0xffffffffu, 2147483648.0f, {}}, u, s);
    EXPECT_EQ(u, (std::vector<std::uint32_t>{0xffffffffu, 1, 0x7fffffffu}));
    EXPECT_EQ(s, (std::vector<std::int32_t>{1, -1, 0x7fffffff}));
}

// uav-atomics L219: -1.0 is 0 to the other Interlocked* (ftou saturates), on an int destination
// too: adding it changes nothing, and-ing it clears, and it matches no comparand of -1.
TEST(D3D11InterlockedValues, OthersTakeASaturatedUint) {
    Device d;
    std::vector<std::uint32_t> u = {0, 0, 0xffffffffu, 0, 0xffffffffu};
    std::vector<std::int32_t> s = {0, 0, -1, 0, -1};
    dispatch(d, R"(
RWBuffer<uint> u : register(u1);
RWBuffer<int> s : register(u2);
cbuffer Values : register(b0) { uint i; float a; };
[numthreads(3, 1, 1)]
void main()
{
    uint old;
    InterlockedAdd(u[1], a);
    InterlockedAnd(u[2], a);
    InterlockedExchange(u[3], i, old);
    InterlockedCompareStore(u[4], a, 0);
    InterlockedAdd(s[1], a);
    InterlockedAnd(s[2], a);
    InterlockedExchange(s[3], i, old);
    InterlockedCompareStore(s[4], a, 0);
})",
             {0xffffffffu, -1.0f, {}}, u, s);
    EXPECT_EQ(u, (std::vector<std::uint32_t>{0, 0, 0, 0xffffffffu, 0xffffffffu}));
    EXPECT_EQ(s, (std::vector<std::int32_t>{0, 0, 0, -1, -1}));
}

}  // namespace
}  // namespace d3d11test
