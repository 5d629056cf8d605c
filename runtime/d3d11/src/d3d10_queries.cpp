// See d3d10_queries.h. D3D10's pipeline statistics are D3D11's first eight counters (D3D10 has no
// hull, domain or compute stage); every other query's data is D3D11's, byte for byte.
#include "d3d10_queries.h"

#include <atomic>

#include "d3d11_impl.h"

namespace fxport::d3d10 {

namespace {

class Query10 final : public ID3D10Predicate {
public:
    Query10(ComPtr<ID3D11Predicate> query, ComPtr<ID3D11DeviceContext> context, const D3D10_QUERY_DESC& desc)
        : query_(std::move(query)), context_(std::move(context)), desc_(desc) {}
    ULONG AddRef() override { return ++references_; }
    ULONG Release() override {
        const ULONG left = --references_;
        if (left == 0) delete this;
        return left;
    }
    void GetDevice(ID3D11Device** ppDevice) override { query_->GetDevice(ppDevice); }
    void Begin() override { context_->Begin(query_.Get()); }
    void End() override { context_->End(query_.Get()); }
    UINT GetDataSize() override {
        return statistics() ? UINT(sizeof(D3D10_QUERY_DATA_PIPELINE_STATISTICS)) : query_->GetDataSize();
    }
    HRESULT GetData(void* pData, UINT DataSize, UINT GetDataFlags) override {
        if (!statistics()) return context_->GetData(query_.Get(), pData, DataSize, GetDataFlags);
        if (DataSize != 0 && DataSize != sizeof(D3D10_QUERY_DATA_PIPELINE_STATISTICS))
            return d3d11::fail(E_INVALIDARG, "ID3D10Query::GetData: DataSize = " + std::to_string(DataSize) + " (the query's GetDataSize() " +
                                                 std::to_string(sizeof(D3D10_QUERY_DATA_PIPELINE_STATISTICS)) + ", or 0)");
        if (DataSize != 0 && !pData) return d3d11::fail(E_INVALIDARG, "ID3D10Query::GetData: pData is null with DataSize " + std::to_string(DataSize));
        D3D11_QUERY_DATA_PIPELINE_STATISTICS s;
        const HRESULT hr = context_->GetData(query_.Get(), DataSize ? &s : nullptr, DataSize ? UINT(sizeof s) : 0, GetDataFlags);
        if (hr == S_OK && DataSize)
            *static_cast<D3D10_QUERY_DATA_PIPELINE_STATISTICS*>(pData) = {s.IAVertices,   s.IAPrimitives, s.VSInvocations, s.GSInvocations,
                                                                          s.GSPrimitives, s.CInvocations, s.CPrimitives,   s.PSInvocations};
        return hr;
    }
    void GetDesc(D3D10_QUERY_DESC* pDesc) override {
        if (pDesc) *pDesc = desc_;
    }
    ID3D11Predicate* query11() const { return query_.Get(); }

private:
    bool statistics() const { return desc_.Query == D3D10_QUERY_PIPELINE_STATISTICS; }
    ComPtr<ID3D11Predicate> query_;  // the D3D11 query (an ID3D11Predicate is one, whatever its kind)
    ComPtr<ID3D11DeviceContext> context_;
    D3D10_QUERY_DESC desc_;
    std::atomic<ULONG> references_{1};
};

}  // namespace

HRESULT createQuery10(ID3D11Device* device, ID3D11DeviceContext* context, const D3D10_QUERY_DESC* desc, bool predicate,
                      ID3D10Predicate** out) {
    ComPtr<ID3D11Predicate> made;
    HRESULT hr = S_OK;
    if (predicate) {
        hr = device->CreatePredicate(desc, out ? made.GetAddressOf() : nullptr);
    } else {
        ComPtr<ID3D11Query> query;
        hr = device->CreateQuery(desc, out ? query.GetAddressOf() : nullptr);
        // fxport's queries are all ID3D11Predicate objects (d3d11_impl.h's Query): keep that interface.
        if (query) made = dynamic_cast<ID3D11Predicate*>(query.Get());
    }
    if (FAILED(hr) || !out) return hr;
    if (!made) return d3d11::fail(E_FAIL, "CreateQuery: the D3D11 query is not fxport's");
    *out = new Query10(made, context, *desc);
    return d3d11::succeed();
}

ID3D11Predicate* predicate11(ID3D10Predicate* predicate) {
    auto* q = dynamic_cast<Query10*>(predicate);
    return q ? q->query11() : nullptr;
}

}  // namespace fxport::d3d10
