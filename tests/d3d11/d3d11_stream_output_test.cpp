// Stream output (issue 24/25) through the D3D11 and D3D10 front ends, headless on OSMesa: a geometry
// shader's vertices written to a buffer (read back with a staging copy and compared exactly with a
// CPU computation of the same math), appends at offset -1, DrawAuto drawing exactly what was
// written, D3D11_SO_NO_RASTERIZED_STREAM, bad declarations refused, and a D3D10 effect whose pass
// streams through ConstructGSWithSO.
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include <unistd.h>

#include "d3d11_test_support.h"
#include "fxport/d3d10.h"

using namespace d3d11test;

namespace {

// Each input point becomes two vertices: position*2+1 (w 1), counter + k, id = 10*counter + k.
const char* kShaders = R"(
struct Point { float3 pos : PTPOS; float counter : COUNTER; };  // a user semantic: a loose VS's POSITION is GL's position
struct Streamed { float4 pos : POSITION; float counter : COUNTER; uint id : ID; };
Point VS(Point p) { return p; }
[maxvertexcount(2)]
void GS(point Point input[1], inout PointStream<Streamed> stream) {
    for (int k = 0; k < 2; ++k) {
        Streamed o;
        o.pos = float4(input[0].pos * 2 + 1, 1);
        o.counter = input[0].counter + k;
        o.id = (uint)input[0].counter * 10 + k;
        stream.Append(o);
    }
}
// Drawing what was streamed: each vertex a point at its position, coloured by its counter and id.
struct Drawn { float4 pos : SV_Position; float counter : COUNTER; nointerpolation uint id : ID; };
Drawn DrawVS(Streamed v) { Drawn d; d.pos = v.pos; d.counter = v.counter; d.id = v.id; return d; }
float4 DrawPS(Drawn d) : SV_Target { return float4(d.counter / 255.0, d.id / 255.0, 0, 1); }
)";

struct Point {
    float pos[3];
    float counter;
};
struct Streamed {  // what the declaration "POSITION.xyzw; COUNTER.x; ID.x" writes: 24 bytes
    float pos[4];
    float counter;
    std::uint32_t id;
};

const D3D11_SO_DECLARATION_ENTRY kDeclaration[] = {
    {0, "POSITION", 0, 0, 4, 0},
    {0, "COUNTER", 0, 0, 1, 0},
    {0, "ID", 0, 0, 1, 0},
};

// The CPU's version of the geometry shader.
std::vector<Streamed> expectedOf(const std::vector<Point>& points) {
    std::vector<Streamed> out;
    for (const Point& p : points)
        for (int k = 0; k < 2; ++k)
            out.push_back({{p.pos[0] * 2 + 1, p.pos[1] * 2 + 1, p.pos[2] * 2 + 1, 1}, p.counter + float(k), std::uint32_t(p.counter) * 10 + std::uint32_t(k)});
    return out;
}

void expectStreamed(const std::vector<Streamed>& got, const std::vector<Streamed>& want, std::size_t from = 0) {
    ASSERT_GE(got.size(), from + want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
        SCOPED_TRACE("vertex " + std::to_string(from + i));
        const Streamed& g = got[from + i];
        for (int c = 0; c < 4; ++c) EXPECT_EQ(g.pos[c], want[i].pos[c]);
        EXPECT_EQ(g.counter, want[i].counter);
        EXPECT_EQ(g.id, want[i].id);
    }
}

// The input position whose streamed position (2p + 1) is the centre of pixel (x, y) of a size x size target.
Point pointAtPixel(int x, int y, int size, float counter) {
    const float ndcX = (float(x) + 0.5f) / float(size) * 2 - 1, ndcY = 1 - (float(y) + 0.5f) / float(size) * 2;
    return {{(ndcX - 1) / 2, (ndcY - 1) / 2, -0.25f}, counter};  // z: 2 * -0.25 + 1 = 0.5
}

struct Pipeline {
    Device d;
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11GeometryShader> gs;
    ComPtr<ID3D11InputLayout> layout;
    ComPtr<ID3D11Buffer> input;

    explicit Pipeline(const std::vector<Point>& points, UINT rasterizedStream = 0) {
        auto vsCode = compile(kShaders, "VS", "vs_4_0");
        auto gsCode = compile(kShaders, "GS", "gs_4_0");
        EXPECT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
        const UINT stride = sizeof(Streamed);
        EXPECT_EQ(d.device->CreateGeometryShaderWithStreamOutput(gsCode->GetBufferPointer(), gsCode->GetBufferSize(), kDeclaration, 3, &stride, 1,
                                                                 rasterizedStream, nullptr, gs.GetAddressOf()),
                  S_OK)
            << lastError();
        const D3D11_INPUT_ELEMENT_DESC elements[] = {{"PTPOS", 0, DXGI_FORMAT_R32G32B32_FLOAT, 0, 0, D3D11_INPUT_PER_VERTEX_DATA, 0},
                                                     {"COUNTER", 0, DXGI_FORMAT_R32_FLOAT, 0, 12, D3D11_INPUT_PER_VERTEX_DATA, 0}};
        EXPECT_EQ(d.device->CreateInputLayout(elements, 2, vsCode->GetBufferPointer(), vsCode->GetBufferSize(), layout.GetAddressOf()), S_OK)
            << lastError();
        input = makeBuffer(d, points.data(), UINT(points.size() * sizeof(Point)), D3D11_BIND_VERTEX_BUFFER);
    }
    // Draws the points through VS and GS with `target` at `offset` (-1: append).
    void stream(ID3D11Buffer* target, UINT offset, UINT points) {
        const UINT stride = sizeof(Point), zero = 0;
        d.context->IASetInputLayout(layout.Get());
        d.context->IASetVertexBuffers(0, 1, input.GetAddressOfConst(), &stride, &zero);
        d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_POINTLIST);
        d.context->VSSetShader(vs.Get(), nullptr, 0);
        d.context->GSSetShader(gs.Get(), nullptr, 0);
        d.context->PSSetShader(nullptr, nullptr, 0);
        d.context->SOSetTargets(1, &target, &offset);
        d.context->Draw(points, 0);
        ID3D11Buffer* none = nullptr;
        d.context->SOSetTargets(1, &none, &zero);
    }
};

// A stream-output buffer of `vertices` vertices, every byte 0xCD (what must stay where nothing is written).
ComPtr<ID3D11Buffer> soBuffer(Device& d, std::size_t vertices, UINT extraBind = 0) {
    std::vector<std::uint8_t> fill(vertices * sizeof(Streamed), 0xCD);
    return makeBuffer(d, fill.data(), UINT(fill.size()), D3D11_BIND_STREAM_OUTPUT | extraBind);
}

}  // namespace

TEST(StreamOutput, GeometryShaderVerticesAreWrittenExactlyAndAppendContinues) {
    const std::vector<Point> points = {{{0.5f, -1, 2}, 1}, {{3, 0.25f, -4}, 2}, {{-7, 8, 0}, 3}};
    Pipeline p(points);
    auto target = soBuffer(p.d, 16);
    p.stream(target.Get(), 0, 3);
    const std::vector<Streamed> want = expectedOf(points);
    std::vector<Streamed> got = readBuffer<Streamed>(p.d, target.Get());
    expectStreamed(got, want);
    std::uint32_t untouched = 0;
    std::memcpy(&untouched, &got[want.size()], 4);
    EXPECT_EQ(untouched, 0xCDCDCDCDu) << "bytes past the six vertices were written";

    // Offset -1 appends after what the last stream output left; an offset starts over there.
    p.stream(target.Get(), 0xffffffffu, 2);
    got = readBuffer<Streamed>(p.d, target.Get());
    expectStreamed(got, want);
    expectStreamed(got, expectedOf({points[0], points[1]}), want.size());
    p.stream(target.Get(), sizeof(Streamed), 1);  // from vertex 1
    got = readBuffer<Streamed>(p.d, target.Get());
    expectStreamed(got, {want[0]});
    expectStreamed(got, expectedOf({points[0]}), 1);  // vertices 1 and 2
    expectStreamed(got, {want[3]}, 3);                // the first run's, untouched
}

TEST(StreamOutput, AFullBufferTakesWhatFitsAndNoMore) {
    const std::vector<Point> points = {{{0, 0, 0}, 1}, {{1, 1, 1}, 2}, {{2, 2, 2}, 3}};
    Pipeline p(points);
    auto target = soBuffer(p.d, 3);  // room for three of the six vertices
    p.stream(target.Get(), 0, 3);
    std::vector<Streamed> got = readBuffer<Streamed>(p.d, target.Get());
    const std::vector<Streamed> all = expectedOf(points);
    expectStreamed(got, {all.begin(), all.begin() + 3});
}

TEST(StreamOutput, DrawAutoDrawsExactlyTheVerticesWrittenAndNoRasterizedStreamDrawsNothing) {
    constexpr int kSize = 8;
    const std::vector<Point> points = {pointAtPixel(1, 2, kSize, 10), pointAtPixel(5, 6, kSize, 20)};
    Pipeline p(points);
    // Past what is written, the buffer holds a vertex at pixel (7, 7): drawn only if DrawAuto drew too many.
    std::vector<Streamed> initial(8);
    for (Streamed& s : initial) s = expectedOf({pointAtPixel(7, 7, kSize, 99)})[0];
    auto target = makeBuffer(p.d, initial.data(), UINT(initial.size() * sizeof(Streamed)), D3D11_BIND_STREAM_OUTPUT | D3D11_BIND_VERTEX_BUFFER);
    p.stream(target.Get(), 0, 2);

    auto rt = makeTexture(p.d, kSize, kSize, D3D11_BIND_RENDER_TARGET);
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(p.d.device->CreateRenderTargetView(rt.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    const FLOAT black[4] = {0, 0, 0, 0};
    p.d.context->ClearRenderTargetView(rtv.Get(), black);
    p.d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    const D3D11_VIEWPORT viewport{0, 0, kSize, kSize, 0, 1};
    p.d.context->RSSetViewports(1, &viewport);
    auto drawVs = compile(kShaders, "DrawVS", "vs_4_0");
    auto drawPs = compile(kShaders, "DrawPS", "ps_4_0");
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> ps;
    ComPtr<ID3D11InputLayout> layout;
    ASSERT_EQ(p.d.device->CreateVertexShader(drawVs->GetBufferPointer(), drawVs->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK);
    ASSERT_EQ(p.d.device->CreatePixelShader(drawPs->GetBufferPointer(), drawPs->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK);
    const D3D11_INPUT_ELEMENT_DESC elements[] = {{"POSITION", 0, DXGI_FORMAT_R32G32B32A32_FLOAT, 0, 0, D3D11_INPUT_PER_VERTEX_DATA, 0},
                                                 {"COUNTER", 0, DXGI_FORMAT_R32_FLOAT, 0, 16, D3D11_INPUT_PER_VERTEX_DATA, 0},
                                                 {"ID", 0, DXGI_FORMAT_R32_UINT, 0, 20, D3D11_INPUT_PER_VERTEX_DATA, 0}};
    ASSERT_EQ(p.d.device->CreateInputLayout(elements, 3, drawVs->GetBufferPointer(), drawVs->GetBufferSize(), layout.GetAddressOf()), S_OK)
        << lastError();
    const UINT stride = sizeof(Streamed), zero = 0;
    p.d.context->IASetInputLayout(layout.Get());
    p.d.context->IASetVertexBuffers(0, 1, target.GetAddressOfConst(), &stride, &zero);
    p.d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_POINTLIST);
    p.d.context->VSSetShader(vs.Get(), nullptr, 0);
    p.d.context->GSSetShader(nullptr, nullptr, 0);
    p.d.context->PSSetShader(ps.Get(), nullptr, 0);
    p.d.context->DrawAuto();

    // The CPU's image: each streamed vertex (four: two per point, the later one on top) at its pixel.
    std::vector<std::array<std::uint8_t, 4>> want(kSize * kSize, {0, 0, 0, 0});
    for (const Streamed& s : expectedOf(points)) {
        const int x = int(std::floor((s.pos[0] + 1) / 2 * kSize)), y = int(std::floor((1 - s.pos[1]) / 2 * kSize));
        want[std::size_t(y * kSize + x)] = {std::uint8_t(s.counter), std::uint8_t(s.id), 0, 255};
    }
    const auto got = readPixels(p.d, rt.Get());
    for (int i = 0; i < kSize * kSize; ++i) {
        SCOPED_TRACE("pixel " + std::to_string(i % kSize) + "," + std::to_string(i / kSize));
        EXPECT_EQ(got[std::size_t(i)], want[std::size_t(i)]);
    }

    // The same streaming with no rasterized stream: the buffer is written, the target is not.
    Pipeline hidden(points, D3D11_SO_NO_RASTERIZED_STREAM);
    auto rt2 = makeTexture(hidden.d, kSize, kSize, D3D11_BIND_RENDER_TARGET);
    ComPtr<ID3D11RenderTargetView> rtv2;
    ASSERT_EQ(hidden.d.device->CreateRenderTargetView(rt2.Get(), nullptr, rtv2.GetAddressOf()), S_OK);
    hidden.d.context->ClearRenderTargetView(rtv2.Get(), black);
    hidden.d.context->OMSetRenderTargets(1, rtv2.GetAddressOfConst(), nullptr);
    hidden.d.context->RSSetViewports(1, &viewport);
    auto hiddenTarget = soBuffer(hidden.d, 8);
    auto colourPs = compile("float4 main() : SV_Target { return 1; }", "main", "ps_4_0");
    ComPtr<ID3D11PixelShader> white;
    ASSERT_EQ(hidden.d.device->CreatePixelShader(colourPs->GetBufferPointer(), colourPs->GetBufferSize(), nullptr, white.GetAddressOf()), S_OK);
    const UINT pointStride = sizeof(Point);
    hidden.d.context->IASetInputLayout(hidden.layout.Get());
    hidden.d.context->IASetVertexBuffers(0, 1, hidden.input.GetAddressOfConst(), &pointStride, &zero);
    hidden.d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_POINTLIST);
    hidden.d.context->VSSetShader(hidden.vs.Get(), nullptr, 0);
    hidden.d.context->GSSetShader(hidden.gs.Get(), nullptr, 0);
    hidden.d.context->PSSetShader(white.Get(), nullptr, 0);
    ID3D11Buffer* so = hiddenTarget.Get();
    hidden.d.context->SOSetTargets(1, &so, &zero);
    hidden.d.context->Draw(2, 0);
    expectStreamed(readBuffer<Streamed>(hidden.d, hiddenTarget.Get()), expectedOf(points));
    for (const auto& pixel : readPixels(hidden.d, rt2.Get())) EXPECT_EQ(pixel, (std::array<std::uint8_t, 4>{0, 0, 0, 0}));
}

TEST(StreamOutput, BadDeclarationsAndBuffersAreRefused) {
    Device d;
    auto gsCode = compile(kShaders, "GS", "gs_4_0");
    auto create = [&](std::vector<D3D11_SO_DECLARATION_ENTRY> entries, UINT stride) {
        ComPtr<ID3D11GeometryShader> gs;
        return d.device->CreateGeometryShaderWithStreamOutput(gsCode->GetBufferPointer(), gsCode->GetBufferSize(), entries.data(), UINT(entries.size()),
                                                              &stride, 1, 0, nullptr, gs.GetAddressOf());
    };
    EXPECT_EQ(create({{0, "POSITION", 0, 0, 4, 0}, {0, "ID", 0, 0, 1, 0}}, 20), S_OK) << lastError();
    EXPECT_EQ(create({{0, "NOSUCH", 0, 0, 1, 0}}, 4), E_INVALIDARG);
    EXPECT_NE(lastError().find("NOSUCH0"), std::string::npos) << lastError();
    EXPECT_EQ(create({{0, "COUNTER", 0, 0, 2, 0}}, 8), E_INVALIDARG);  // a float has one component
    EXPECT_EQ(create({{0, "POSITION", 0, 2, 3, 0}}, 12), E_INVALIDARG);  // z..(w+1)
    EXPECT_EQ(create({{0, "POSITION", 0, 0, 4, 5}}, 16), E_INVALIDARG);  // slot 5
    EXPECT_EQ(create({{0, "POSITION", 0, 0, 4, 0}}, 8), E_INVALIDARG);   // stride under 16 bytes

    D3D11_BUFFER_DESC desc{};
    desc.ByteWidth = 64;
    desc.Usage = D3D11_USAGE_DYNAMIC;
    desc.BindFlags = D3D11_BIND_STREAM_OUTPUT;
    desc.CPUAccessFlags = D3D11_CPU_ACCESS_WRITE;
    ComPtr<ID3D11Buffer> buffer;
    EXPECT_EQ(d.device->CreateBuffer(&desc, nullptr, buffer.GetAddressOf()), E_INVALIDARG);
}

TEST(StreamOutput, D3D10EffectPassStreamsThroughConstructGSWithSO) {
    namespace d10 = fxport::d3d10;
    const std::string fx = std::string(kShaders) +
                           "GeometryShader gsSO = ConstructGSWithSO(CompileShader(gs_4_0, GS()), \"POSITION.xyzw; COUNTER.x; ID.x\");\n"
                           "VertexShader vsPoint = CompileShader(vs_4_0, VS());\n"
                           "GeometryShader vsSO = ConstructGSWithSO(vsPoint, \"PTPOS.xyz; COUNTER.x\");\n"
                           "DepthStencilState NoDepth { DepthEnable = false; DepthWriteMask = ZERO; };\n"
                           "technique10 Advance { pass P { SetVertexShader(vsPoint); SetGeometryShader(gsSO); SetPixelShader(NULL);\n"
                           "                               SetDepthStencilState(NoDepth, 0); } }\n"
                           "technique10 CopyVertices { pass P { SetVertexShader(vsPoint); SetGeometryShader(vsSO); SetPixelShader(NULL); } }\n";
    const std::filesystem::path path = std::filesystem::temp_directory_path() / ("fxport_so_" + std::to_string(::getpid()) + ".fx");
    std::ofstream(path) << fx;
    ComPtr<d10::ID3D10Device> device;
    ASSERT_EQ(d10::D3D10CreateDevice(nullptr, d10::D3D10_DRIVER_TYPE_HARDWARE, nullptr, 0, d10::D3D10_SDK_VERSION, device.GetAddressOf()), S_OK);
    ComPtr<d10::ID3D10Effect> effect;
    ComPtr<ID3DBlob> errors;
    ASSERT_EQ(d10::D3DX10CreateEffectFromFile(path.string().c_str(), nullptr, nullptr, "fx_4_0", 0, 0, device.Get(), nullptr, nullptr,
                                              effect.GetAddressOf(), errors.GetAddressOf(), nullptr),
              S_OK)
        << (errors ? static_cast<const char*>(errors->GetBufferPointer()) : lastError());
    std::filesystem::remove(path);

    const std::vector<Point> points = {{{1, 2, 3}, 4}, {{-0.5f, 0, 0.5f}, 5}};
    D3D11_BUFFER_DESC vb{};
    vb.ByteWidth = UINT(points.size() * sizeof(Point));
    vb.BindFlags = D3D11_BIND_VERTEX_BUFFER;
    D3D11_SUBRESOURCE_DATA init{points.data(), 0, 0};
    ComPtr<ID3D11Buffer> input, target;
    ASSERT_EQ(device->CreateBuffer(&vb, &init, input.GetAddressOf()), S_OK) << lastError();
    std::vector<std::uint8_t> fill(8 * sizeof(Streamed), 0xCD);
    D3D11_BUFFER_DESC so{};
    so.ByteWidth = UINT(fill.size());
    so.BindFlags = d10::D3D10_BIND_STREAM_OUTPUT;
    init.pSysMem = fill.data();
    ASSERT_EQ(device->CreateBuffer(&so, &init, target.GetAddressOf()), S_OK) << lastError();

    auto run = [&](const char* technique) {
        d10::ID3D10EffectPass* pass = effect->GetTechniqueByName(technique)->GetPassByIndex(0);
        d10::D3D10_PASS_DESC desc{};
        ASSERT_EQ(pass->GetDesc(&desc), S_OK) << lastError();
        const D3D11_INPUT_ELEMENT_DESC elements[] = {{"PTPOS", 0, DXGI_FORMAT_R32G32B32_FLOAT, 0, 0, D3D11_INPUT_PER_VERTEX_DATA, 0},
                                                     {"COUNTER", 0, DXGI_FORMAT_R32_FLOAT, 0, 12, D3D11_INPUT_PER_VERTEX_DATA, 0}};
        ComPtr<ID3D11InputLayout> layout;
        ASSERT_EQ(device->CreateInputLayout(elements, 2, desc.pIAInputSignature, desc.IAInputSignatureSize, layout.GetAddressOf()), S_OK) << lastError();
        const UINT stride = sizeof(Point), zero = 0;
        device->IASetInputLayout(layout.Get());
        device->IASetVertexBuffers(0, 1, input.GetAddressOfConst(), &stride, &zero);
        device->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_POINTLIST);
        ID3D11Buffer* t = target.Get();
        device->SOSetTargets(1, &t, &zero);
        ASSERT_EQ(pass->Apply(0), S_OK) << lastError();
        device->Draw(UINT(points.size()), 0);
        ID3D11Buffer* none = nullptr;
        device->SOSetTargets(1, &none, &zero);
    };
    auto read = [&] {
        ComPtr<ID3D11Buffer> staging;
        D3D11_BUFFER_DESC s{};
        s.ByteWidth = UINT(fill.size());
        s.Usage = D3D11_USAGE_STAGING;
        s.CPUAccessFlags = D3D11_CPU_ACCESS_READ;
        EXPECT_EQ(device->CreateBuffer(&s, nullptr, staging.GetAddressOf()), S_OK) << lastError();
        device->CopyResource(staging.Get(), target.Get());
        D3D11_MAPPED_SUBRESOURCE mapped{};
        EXPECT_EQ(device->GetD3D11Context()->Map(staging.Get(), 0, D3D11_MAP_READ, 0, &mapped), S_OK) << lastError();
        std::vector<std::uint8_t> bytes(fill.size());
        std::memcpy(bytes.data(), mapped.pData, bytes.size());
        device->GetD3D11Context()->Unmap(staging.Get(), 0);
        return bytes;
    };
    run("Advance");
    std::vector<std::uint8_t> bytes = read();
    std::vector<Streamed> got(bytes.size() / sizeof(Streamed));
    std::memcpy(got.data(), bytes.data(), got.size() * sizeof(Streamed));
    expectStreamed(got, expectedOf(points));

    // ConstructGSWithSO of the vertex shader: its own outputs, 16 bytes a vertex (POSITION.xyz, COUNTER.x).
    run("CopyVertices");
    bytes = read();
    std::vector<float> floats(bytes.size() / 4);
    std::memcpy(floats.data(), bytes.data(), floats.size() * 4);
    for (std::size_t i = 0; i < points.size(); ++i) {
        SCOPED_TRACE(i);
        for (int c = 0; c < 3; ++c) EXPECT_EQ(floats[i * 4 + std::size_t(c)], points[i].pos[c]);
        EXPECT_EQ(floats[i * 4 + 3], points[i].counter);
    }

    // D3D10's SOGetTargets answers the buffers and the offsets SOSetTargets was given.
    ID3D11Buffer* t = target.Get();
    const UINT append = 0xffffffffu;
    device->SOSetTargets(1, &t, &append);
    ID3D11Buffer* bound[2] = {};
    UINT offsets[2] = {7, 7};
    device->SOGetTargets(2, bound, offsets);
    EXPECT_EQ(bound[0], t);
    EXPECT_EQ(bound[1], nullptr);
    EXPECT_EQ(offsets[0], append);
    EXPECT_EQ(offsets[1], 0u);
    if (bound[0]) bound[0]->Release();
}

namespace {

// GetData of a stream-output query, waiting as D3D code does (S_FALSE until ready).
template <class T>
T queryData(Device& d, ID3D11Query* q) {
    T out{};
    HRESULT hr = S_FALSE;
    for (int tries = 0; tries < 1000 && hr == S_FALSE; ++tries) hr = d.context->GetData(q, &out, sizeof out, 0);
    EXPECT_EQ(hr, S_OK) << lastError();
    return out;
}

ComPtr<ID3D11Query> makeQuery(Device& d, D3D11_QUERY kind) {
    D3D11_QUERY_DESC desc;
    desc.Query = kind;
    ComPtr<ID3D11Query> q;
    EXPECT_EQ(d.device->CreateQuery(&desc, q.GetAddressOf()), S_OK) << lastError();
    return q;
}

}  // namespace

// Each point becomes two point primitives: 3 points into room for 16 vertices write 6, and into
// room for 3 write 3 of the 6 needed, which the overflow predicates report.
TEST(StreamOutput, StatisticsQueriesCountWrittenAndNeededPrimitives) {
    const std::vector<Point> points = {{{0, 0, 0}, 1}, {{1, 1, 1}, 2}, {{2, 2, 2}, 3}};
    Pipeline p(points);
    auto roomy = soBuffer(p.d, 16), tight = soBuffer(p.d, 3);
    for (D3D11_QUERY kind : {D3D11_QUERY_SO_STATISTICS, D3D11_QUERY_SO_STATISTICS_STREAM0}) {
        SCOPED_TRACE("query " + std::to_string(kind));
        ComPtr<ID3D11Query> stats = makeQuery(p.d, kind), overflow = makeQuery(p.d, D3D11_QUERY(kind + 1));
        ASSERT_TRUE(stats && overflow);
        EXPECT_EQ(stats->GetDataSize(), sizeof(D3D11_QUERY_DATA_SO_STATISTICS));
        EXPECT_EQ(overflow->GetDataSize(), sizeof(BOOL));
        p.d.context->Begin(stats.Get());
        p.d.context->Begin(overflow.Get());
        p.stream(roomy.Get(), 0, 3);
        p.d.context->End(stats.Get());
        p.d.context->End(overflow.Get());
        D3D11_QUERY_DATA_SO_STATISTICS s = queryData<D3D11_QUERY_DATA_SO_STATISTICS>(p.d, stats.Get());
        EXPECT_EQ(s.NumPrimitivesWritten, 6u);
        EXPECT_EQ(s.PrimitivesStorageNeeded, 6u);
        EXPECT_EQ(queryData<BOOL>(p.d, overflow.Get()), FALSE);

        p.d.context->Begin(stats.Get());
        p.d.context->Begin(overflow.Get());
        p.stream(tight.Get(), 0, 3);
        p.stream(roomy.Get(), 0, 1);
        p.d.context->End(stats.Get());
        p.d.context->End(overflow.Get());
        s = queryData<D3D11_QUERY_DATA_SO_STATISTICS>(p.d, stats.Get());
        EXPECT_EQ(s.NumPrimitivesWritten, 3u + 2u);
        EXPECT_EQ(s.PrimitivesStorageNeeded, 6u + 2u);
        EXPECT_EQ(queryData<BOOL>(p.d, overflow.Get()), TRUE);
    }
}

TEST(StreamOutput, AnOverflowPredicatePredicatesAndOtherStreamsAreNotImplemented) {
    const std::vector<Point> points = {{{0, 0, 0}, 1}, {{1, 1, 1}, 2}};
    Pipeline p(points);
    auto tight = soBuffer(p.d, 1);
    D3D11_QUERY_DESC desc;
    desc.Query = D3D11_QUERY_SO_OVERFLOW_PREDICATE;
    ComPtr<ID3D11Predicate> overflowed;
    ASSERT_EQ(p.d.device->CreatePredicate(&desc, overflowed.GetAddressOf()), S_OK) << lastError();
    p.d.context->Begin(overflowed.Get());
    p.stream(tight.Get(), 0, 2);
    p.d.context->End(overflowed.Get());
    // A clear predicated on "overflowed is TRUE" is skipped; on FALSE it runs.
    ComPtr<ID3D11Texture2D> colour = makeTexture(p.d, 2, 2, D3D11_BIND_RENDER_TARGET);
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(p.d.device->CreateRenderTargetView(colour.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    const float black[4] = {0, 0, 0, 0}, white[4] = {1, 1, 1, 1};
    p.d.context->ClearRenderTargetView(rtv.Get(), black);
    p.d.context->SetPredication(overflowed.Get(), TRUE);
    p.d.context->ClearRenderTargetView(rtv.Get(), white);
    p.d.context->SetPredication(nullptr, FALSE);
    EXPECT_EQ(readPixels(p.d, colour.Get())[0][0], 0) << "the predicated clear ran although the stream overflowed";
    p.d.context->SetPredication(overflowed.Get(), FALSE);
    p.d.context->ClearRenderTargetView(rtv.Get(), white);
    p.d.context->SetPredication(nullptr, FALSE);
    EXPECT_EQ(readPixels(p.d, colour.Get())[0][0], 255);

    desc.Query = D3D11_QUERY_SO_STATISTICS_STREAM1;
    ComPtr<ID3D11Query> q;
    EXPECT_EQ(p.d.device->CreateQuery(&desc, q.GetAddressOf()), E_NOTIMPL);
    EXPECT_NE(lastError().find("stream 0"), std::string::npos) << lastError();
}
