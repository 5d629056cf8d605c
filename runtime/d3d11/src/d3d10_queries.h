// INTERNAL: D3D10's queries and predicates (ID3D10Query, ID3D10Predicate) over D3D11's: Begin, End
// and GetData on the query run the immediate context's calls on the D3D11 query inside
// (d3d10_queries.cpp).
#pragma once

#include "fxport/d3d10/d3d10_interfaces.h"

namespace fxport::d3d10 {

// CreateQuery (predicate false) or CreatePredicate (true) on D3D11's `device`, the result wrapped
// for D3D10; `out` null: only checks the description (S_FALSE when valid, as D3D does).
HRESULT createQuery10(ID3D11Device* device, ID3D11DeviceContext* context, const D3D10_QUERY_DESC* desc, bool predicate,
                      ID3D10Predicate** out);
// The D3D11 predicate inside a D3D10 one made above (null for null or a foreign object).
ID3D11Predicate* predicate11(ID3D10Predicate* predicate);

}  // namespace fxport::d3d10
