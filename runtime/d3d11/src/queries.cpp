// ID3D11Query over the device core's GPU queries: an event or timestamp query is a timestamp the
// GPU writes at End (ready once the GPU has passed it); an occlusion query (and its predicate)
// counts the samples passing the depth and stencil tests between Begin and End; a disjoint query
// answers GL's timestamps' frequency (nanoseconds) and never disjoint. GetData answers S_FALSE
// until the result is there, as D3D does.
#include "context.h"
#include "guarded.h"

namespace fxport::d3d11 {

namespace {

bool countsSamples(D3D11_QUERY q) { return q == D3D11_QUERY_OCCLUSION || q == D3D11_QUERY_OCCLUSION_PREDICATE; }
bool bracketed(D3D11_QUERY q) { return countsSamples(q) || q == D3D11_QUERY_TIMESTAMP_DISJOINT; }

}  // namespace

Query::Query(Device* device, const D3D11_QUERY_DESC& d) : Object(device), desc(d) {
    if (desc.Query != D3D11_QUERY_TIMESTAMP_DISJOINT)
        gpu = std::make_unique<core::GpuQuery>(device->core(), countsSamples(desc.Query) ? core::GpuQuery::Kind::SamplesPassed
                                                                                         : core::GpuQuery::Kind::Timestamp);
}

UINT Query::GetDataSize() {
    switch (desc.Query) {
    case D3D11_QUERY_EVENT:
    case D3D11_QUERY_OCCLUSION_PREDICATE: return sizeof(BOOL);
    case D3D11_QUERY_TIMESTAMP_DISJOINT: return sizeof(D3D11_QUERY_DATA_TIMESTAMP_DISJOINT);
    default: return sizeof(UINT64);
    }
}

HRESULT Device::CreateQuery(const D3D11_QUERY_DESC* d, ID3D11Query** pp) {
    if (!d) return fail(E_INVALIDARG, "CreateQuery: pQueryDesc is null");
    const std::string at = "CreateQuery: D3D11_QUERY_DESC.";
    if (d->Query > D3D11_QUERY_SO_OVERFLOW_PREDICATE) return fail(E_INVALIDARG, at + "Query = " + std::to_string(d->Query) + " (not a D3D11_QUERY value)");
    const bool predicate = d->Query == D3D11_QUERY_OCCLUSION_PREDICATE || d->Query == D3D11_QUERY_SO_OVERFLOW_PREDICATE;
    if (d->MiscFlags & ~D3D11_QUERY_MISC_PREDICATEHINT || (d->MiscFlags && !predicate))
        return fail(E_INVALIDARG, at + "MiscFlags = " + std::to_string(d->MiscFlags) + " (0, or D3D11_QUERY_MISC_PREDICATEHINT for a predicate)");
    if (d->Query == D3D11_QUERY_PIPELINE_STATISTICS || d->Query >= D3D11_QUERY_SO_STATISTICS)
        return fail(E_NOTIMPL, at + "Query = " + std::to_string(d->Query) +
                                   ": fxport has event, occlusion, occlusion-predicate, timestamp and timestamp-disjoint queries");
    if (!pp) return S_FALSE;  // D3D: the description is valid
    return guarded("CreateQuery", [&] {
        *pp = new Query(this, *d);
        return succeed();
    });
}

void Context::Begin(ID3D11Asynchronous* async) {
    Query* q = own<Query>(async, device_);
    if (!q) return note("Begin: pAsync is null or not a query of this device");
    if (!bracketed(q->desc.Query)) return note("Begin: an event or timestamp query has no Begin (D3D ignores it); call End alone");
    if (counting_ && counting_.Get() != q && countsSamples(q->desc.Query))
        return note("Begin: another occlusion query is counting; fxport counts one at a time (End it first)");
    guarded("Begin", [&] {
        if (q->begun && q->gpu) q->gpu->end();  // a second Begin starts again
        q->begun = true;
        q->ended = false;
        if (q->gpu) {
            q->gpu->begin();
            counting_ = q;
        }
        return succeed();
    });
}

void Context::End(ID3D11Asynchronous* async) {
    Query* q = own<Query>(async, device_);
    if (!q) return note("End: pAsync is null or not a query of this device");
    if (bracketed(q->desc.Query) && !q->begun) return note("End: the query was not begun (an occlusion or disjoint query needs Begin first)");
    guarded("End", [&] {
        if (q->gpu) q->gpu->end();
        if (counting_.Get() == q) counting_ = nullptr;
        q->begun = false;
        q->ended = true;
        return succeed();
    });
}

HRESULT Context::GetData(ID3D11Asynchronous* async, void* data, UINT size, UINT flags) {
    Query* q = own<Query>(async, device_);
    if (!q) return fail(E_INVALIDARG, "GetData: pAsync is null or not a query of this device");
    if (flags & ~D3D11_ASYNC_GETDATA_DONOTFLUSH)
        return fail(E_INVALIDARG, "GetData: GetDataFlags = " + std::to_string(flags) + " (0 or D3D11_ASYNC_GETDATA_DONOTFLUSH)");
    if (size != 0 && size != q->GetDataSize())
        return fail(E_INVALIDARG, "GetData: DataSize = " + std::to_string(size) + " (the query's GetDataSize() " + std::to_string(q->GetDataSize()) + ", or 0)");
    if (size != 0 && !data) return fail(E_INVALIDARG, "GetData: pData is null with DataSize " + std::to_string(size));
    if (!q->ended) return fail(DXGI_ERROR_INVALID_CALL, "GetData: End has not been called on the query since it was begun or made");
    return guarded("GetData", [&]() -> HRESULT {
        if (q->gpu && !q->gpu->ready()) return S_FALSE;
        const UINT64 value = q->gpu ? q->gpu->result() : 0;
        if (size == 0) return succeed();
        switch (q->desc.Query) {
        case D3D11_QUERY_EVENT: *static_cast<BOOL*>(data) = TRUE; break;
        case D3D11_QUERY_OCCLUSION_PREDICATE: *static_cast<BOOL*>(data) = value != 0; break;
        case D3D11_QUERY_TIMESTAMP_DISJOINT: *static_cast<D3D11_QUERY_DATA_TIMESTAMP_DISJOINT*>(data) = {1000000000u, FALSE}; break;
        default: *static_cast<UINT64*>(data) = value; break;
        }
        return succeed();
    });
}

}  // namespace fxport::d3d11
