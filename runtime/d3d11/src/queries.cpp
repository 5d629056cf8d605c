// ID3D11Query over the device core's GPU queries: an event or timestamp query is a timestamp the
// GPU writes at End (ready once the GPU has passed it); an occlusion query (and its predicate)
// counts the samples passing the depth and stencil tests between Begin and End; a disjoint query
// answers GL's timestamps' frequency (nanoseconds) and never disjoint; a pipeline-statistics query
// reads GL_ARB_pipeline_statistics_query's eleven counters (the same ones as D3D's; E_NOTIMPL where
// the driver lacks them); a stream-output statistics query (or overflow predicate) is the
// difference of the core's stream-output counts at Begin and End, which each streaming draw has
// already waited for (stream 0: the one fxport captures). GetData answers S_FALSE until the result
// is there, as D3D does.
// SetPredication skips the predicated calls while an occlusion predicate's result equals the value
// given: the context waits for the result at each such call (GL's conditional rendering would
// cover draws and clears only, not the copies and updates D3D predicates too).
#include "context.h"
#include "guarded.h"

namespace fxport::d3d11 {

namespace {

bool countsSamples(D3D11_QUERY q) { return q == D3D11_QUERY_OCCLUSION || q == D3D11_QUERY_OCCLUSION_PREDICATE; }
// SO_STATISTICS(_STREAMn) and SO_OVERFLOW_PREDICATE(_STREAMn): 6, 7 and 8..15, statistics even.
bool streamOutput(D3D11_QUERY q) { return q >= D3D11_QUERY_SO_STATISTICS; }
bool overflowPredicate(D3D11_QUERY q) { return streamOutput(q) && q % 2 == 1; }
bool bracketed(D3D11_QUERY q) {
    return countsSamples(q) || q == D3D11_QUERY_TIMESTAMP_DISJOINT || q == D3D11_QUERY_PIPELINE_STATISTICS || streamOutput(q);
}
bool isPredicate(D3D11_QUERY q) { return q == D3D11_QUERY_OCCLUSION_PREDICATE || overflowPredicate(q); }

core::GpuQuery::Kind kindOf(D3D11_QUERY q) {
    if (countsSamples(q)) return core::GpuQuery::Kind::SamplesPassed;
    if (q == D3D11_QUERY_PIPELINE_STATISTICS) return core::GpuQuery::Kind::PipelineStatistics;
    return core::GpuQuery::Kind::Timestamp;
}

// The query desc's checks shared by CreateQuery and CreatePredicate (`call` names which).
HRESULT checkQuery(Device& device, const char* call, const D3D11_QUERY_DESC* d) {
    if (!d) return fail(E_INVALIDARG, std::string(call) + ": the D3D11_QUERY_DESC pointer is null");
    const std::string at = std::string(call) + ": D3D11_QUERY_DESC.";
    if (d->Query > D3D11_QUERY_SO_OVERFLOW_PREDICATE_STREAM3)
        return fail(E_INVALIDARG, at + "Query = " + std::to_string(d->Query) + " (not a D3D11_QUERY value)");
    const bool predicate = isPredicate(d->Query);
    if (d->MiscFlags & ~D3D11_QUERY_MISC_PREDICATEHINT || (d->MiscFlags && !predicate))
        return fail(E_INVALIDARG, at + "MiscFlags = " + std::to_string(d->MiscFlags) + " (0, or D3D11_QUERY_MISC_PREDICATEHINT for a predicate)");
    if (d->Query >= D3D11_QUERY_SO_STATISTICS_STREAM1)
        return fail(E_NOTIMPL, at + "Query = " + std::to_string(d->Query) + ": fxport captures stream 0 only (the _STREAM0 and all-streams queries count it)");
    if (d->Query == D3D11_QUERY_PIPELINE_STATISTICS && !core::pipelineStatisticsAvailable(device.core()))
        return fail(E_NOTIMPL, at + "Query = D3D11_QUERY_PIPELINE_STATISTICS: the GL driver lacks GL_ARB_pipeline_statistics_query, "
                                    "which counts what D3D's statistics count");
    return S_OK;
}

// An SO query's answer from its two readings: D3D11_QUERY_DATA_SO_STATISTICS, or whether some
// primitive found no room (the overflow predicate's BOOL).
D3D11_QUERY_DATA_SO_STATISTICS streamOutputStatistics(const Query& q) {
    return {q.atEnd.written - q.atBegin.written, q.atEnd.needed - q.atBegin.needed};
}
void writeStreamOutputData(const Query& q, void* data) {
    const D3D11_QUERY_DATA_SO_STATISTICS s = streamOutputStatistics(q);
    if (overflowPredicate(q.desc.Query)) *static_cast<BOOL*>(data) = s.PrimitivesStorageNeeded > s.NumPrimitivesWritten;
    else *static_cast<D3D11_QUERY_DATA_SO_STATISTICS*>(data) = s;
}

}  // namespace

Query::Query(Device* device, const D3D11_QUERY_DESC& d) : Object(device), desc(d) {
    if (desc.Query != D3D11_QUERY_TIMESTAMP_DISJOINT && !streamOutput(desc.Query))
        gpu = std::make_unique<core::GpuQuery>(device->core(), kindOf(desc.Query));
}

UINT Query::GetDataSize() {
    switch (desc.Query) {
    case D3D11_QUERY_EVENT:
    case D3D11_QUERY_OCCLUSION_PREDICATE: return sizeof(BOOL);
    case D3D11_QUERY_TIMESTAMP_DISJOINT: return sizeof(D3D11_QUERY_DATA_TIMESTAMP_DISJOINT);
    case D3D11_QUERY_PIPELINE_STATISTICS: return sizeof(D3D11_QUERY_DATA_PIPELINE_STATISTICS);
    default:
        if (overflowPredicate(desc.Query)) return sizeof(BOOL);
        return streamOutput(desc.Query) ? UINT(sizeof(D3D11_QUERY_DATA_SO_STATISTICS)) : UINT(sizeof(UINT64));
    }
}

HRESULT Device::CreateQuery(const D3D11_QUERY_DESC* d, ID3D11Query** pp) {
    if (HRESULT hr = checkQuery(*this, "CreateQuery", d); FAILED(hr)) return hr;
    if (!pp) return S_FALSE;  // D3D: the description is valid
    return guarded("CreateQuery", [&] {
        *pp = new Query(this, *d);
        return succeed();
    });
}

HRESULT Device::CreatePredicate(const D3D11_QUERY_DESC* d, ID3D11Predicate** pp) {
    if (HRESULT hr = checkQuery(*this, "CreatePredicate", d); FAILED(hr)) return hr;
    if (!isPredicate(d->Query))
        return fail(E_INVALIDARG, "CreatePredicate: D3D11_QUERY_DESC.Query = " + std::to_string(d->Query) +
                                      " (a predicate is D3D11_QUERY_OCCLUSION_PREDICATE or SO_OVERFLOW_PREDICATE)");
    if (!pp) return S_FALSE;
    return guarded("CreatePredicate", [&] {
        *pp = new Query(this, *d);
        return succeed();
    });
}

void Context::Begin(ID3D11Asynchronous* async) {
    Query* q = own<Query>(async, device_);
    if (!q) return note("Begin: pAsync is null or not a query of this device");
    if (!bracketed(q->desc.Query)) return note("Begin: an event or timestamp query has no Begin (D3D ignores it); call End alone");
    if (predicate_.Get() == q) return note("Begin: the query is the one SetPredication set (D3D: Begin and End are invalid on it meanwhile)");
    if (counting_ && counting_.Get() != q && countsSamples(q->desc.Query))
        return note("Begin: another occlusion query is counting; fxport counts one at a time (End it first)");
    const bool statistics = q->desc.Query == D3D11_QUERY_PIPELINE_STATISTICS;
    if (statistics_ && statistics_.Get() != q && statistics)
        return note("Begin: another pipeline-statistics query is counting; fxport counts one at a time (End it first)");
    guarded("Begin", [&] {
        if (q->begun && q->gpu) q->gpu->end();  // a second Begin starts again
        q->begun = true;
        q->ended = false;
        if (q->gpu) {
            q->gpu->begin();
            (statistics ? statistics_ : counting_) = q;
        }
        if (streamOutput(q->desc.Query)) q->atBegin = core::streamOutputCounts(device_->core());
        return succeed();
    });
}

void Context::End(ID3D11Asynchronous* async) {
    Query* q = own<Query>(async, device_);
    if (!q) return note("End: pAsync is null or not a query of this device");
    if (predicate_.Get() == q) return note("End: the query is the one SetPredication set (D3D: Begin and End are invalid on it meanwhile)");
    if (bracketed(q->desc.Query) && !q->begun)
        return note("End: the query was not begun (an occlusion, pipeline-statistics or disjoint query needs Begin first)");
    guarded("End", [&] {
        if (q->gpu) q->gpu->end();
        if (streamOutput(q->desc.Query)) q->atEnd = core::streamOutputCounts(device_->core());
        if (counting_.Get() == q) counting_ = nullptr;
        if (statistics_.Get() == q) statistics_ = nullptr;
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
        case D3D11_QUERY_PIPELINE_STATISTICS: {
            const core::StatisticCounts s = q->gpu->statistics();
            auto& out = *static_cast<D3D11_QUERY_DATA_PIPELINE_STATISTICS*>(data);
            out = {s[0], s[1], s[2], s[3], s[4], s[5], s[6], s[7], s[8], s[9], s[10]};
            break;
        }
        default:
            if (streamOutput(q->desc.Query)) writeStreamOutputData(*q, data);
            else *static_cast<UINT64*>(data) = value;
            break;
        }
        return succeed();
    });
}

void Context::SetPredication(ID3D11Predicate* pPredicate, BOOL PredicateValue) {
    Query* q = own<Query>(pPredicate, device_);
    if (pPredicate && !q) return note("SetPredication: pPredicate was not made by this device");
    if (q && !isPredicate(q->desc.Query))
        return note("SetPredication: the query is D3D11_QUERY " + std::to_string(q->desc.Query) + ", not an OCCLUSION_PREDICATE or SO_OVERFLOW_PREDICATE");
    predicate_ = q;
    predicateValue_ = PredicateValue;
    succeed();
}

void Context::GetPredication(ID3D11Predicate** ppPredicate, BOOL* pPredicateValue) {
    if (ppPredicate) {
        *ppPredicate = predicate_.Get();
        if (*ppPredicate) (*ppPredicate)->AddRef();
    }
    if (pPredicateValue) *pPredicateValue = predicateValue_;
}

// D3D skips a predicated call when the predicate's data (some sample passed) equals the value set.
// A predicate not yet issued (no End since Begin) decides nothing: the call runs.
bool Context::predicatedAway() {
    if (!predicate_ || !predicate_->ended) return false;
    if (overflowPredicate(predicate_->desc.Query)) {
        const D3D11_QUERY_DATA_SO_STATISTICS s = streamOutputStatistics(*predicate_.Get());
        const bool skip = (s.PrimitivesStorageNeeded > s.NumPrimitivesWritten) == (predicateValue_ != FALSE);
        if (skip) succeed();
        return skip;
    }
    if (!predicate_->gpu) return false;
    bool skip = false;
    guarded("SetPredication", [&] {
        skip = (predicate_->gpu->result() != 0) == (predicateValue_ != FALSE);
        return S_OK;
    });
    if (skip) succeed();  // a skipped call is no error
    return skip;
}

}  // namespace fxport::d3d11
