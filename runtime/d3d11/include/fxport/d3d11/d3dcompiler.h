// D3DCompile, D3DCompileFromFile (and D3DX11CompileFromFile's spelling), blobs and D3DReflect with
// D3D's names. The "bytecode" in a code blob is fxport's compiled shader (GLSL plus reflection,
// xlate's compiled-effect text), which CreateVertexShader/CreatePixelShader/CreateInputLayout and
// D3DReflect take; an error blob holds fxc-style messages, "file(line,col): error X...: ...".
#pragma once

#include "fxport/d3d11/d3d11_interfaces.h"

namespace fxport::d3d11 {

class ID3DBlob : public IUnknown {
public:
    virtual void* GetBufferPointer() = 0;
    virtual SIZE_T GetBufferSize() = 0;
};
using ID3D10Blob = ID3DBlob;

struct D3D_SHADER_MACRO {
    LPCSTR Name = nullptr;
    LPCSTR Definition = nullptr;
};

// An #include handler, as D3D's: Open is called for each #include the preprocessor reaches (not
// for those in skipped #if branches), with the header as written, D3D_INCLUDE_LOCAL for "x" and
// D3D_INCLUDE_SYSTEM for <x>, and the data Open returned for the including file (null for the
// source itself); it returns the text in *ppData/*pBytes, or a failure (the compile then fails
// naming the header). Close is called once for each successful Open, after preprocessing (D3D
// closes a file when its end is reached; fxport keeps every file open until the last). Null or
// D3D_COMPILE_STANDARD_FILE_INCLUDE: includes resolve beside the source file, as the standard
// handler does.
enum D3D_INCLUDE_TYPE : UINT { D3D_INCLUDE_LOCAL = 0, D3D_INCLUDE_SYSTEM = 1 };
class ID3DInclude {
public:
    virtual HRESULT Open(D3D_INCLUDE_TYPE IncludeType, LPCSTR pFileName, LPCVOID pParentData, LPCVOID* ppData, UINT* pBytes) = 0;
    virtual HRESULT Close(LPCVOID pData) = 0;

protected:
    ~ID3DInclude() = default;
};
inline ID3DInclude* const D3D_COMPILE_STANDARD_FILE_INCLUDE = reinterpret_cast<ID3DInclude*>(std::uintptr_t(1));

// Other flags are accepted and ignored (fxport's translation has no optimisation levels).
// D3DCOMPILE_PACK_MATRIX_ROW_MAJOR / COLUMN_MAJOR set the majority of matrices that name none, until
// a #pragma pack_matrix (fxc's /Zpr, /Zpc); both at once is E_INVALIDARG.
constexpr UINT D3DCOMPILE_DEBUG = 1u << 0;
constexpr UINT D3DCOMPILE_SKIP_OPTIMIZATION = 1u << 2;
constexpr UINT D3DCOMPILE_PACK_MATRIX_ROW_MAJOR = 1u << 3;
constexpr UINT D3DCOMPILE_PACK_MATRIX_COLUMN_MAJOR = 1u << 4;
constexpr UINT D3DCOMPILE_ENABLE_STRICTNESS = 1u << 11;
constexpr UINT D3DCOMPILE_OPTIMIZATION_LEVEL3 = 1u << 15;

// pSourceName names the source in messages and locates its #includes (may be null).
HRESULT D3DCompile(LPCVOID pSrcData, SIZE_T SrcDataSize, LPCSTR pSourceName, const D3D_SHADER_MACRO* pDefines,
                   ID3DInclude* pInclude, LPCSTR pEntrypoint, LPCSTR pTarget, UINT Flags1, UINT Flags2,
                   ID3DBlob** ppCode, ID3DBlob** ppErrorMsgs);
HRESULT D3DCompileFromFile(const wchar_t* pFileName, const D3D_SHADER_MACRO* pDefines, ID3DInclude* pInclude,
                           LPCSTR pEntrypoint, LPCSTR pTarget, UINT Flags1, UINT Flags2, ID3DBlob** ppCode,
                           ID3DBlob** ppErrorMsgs);
// fxport: the same with a narrow path.
HRESULT D3DCompileFromFile(LPCSTR pFileName, const D3D_SHADER_MACRO* pDefines, ID3DInclude* pInclude,
                           LPCSTR pEntrypoint, LPCSTR pTarget, UINT Flags1, UINT Flags2, ID3DBlob** ppCode,
                           ID3DBlob** ppErrorMsgs);
// D3DX11's spelling (the DirectX SDK tutorials'): pPump must be null; *pHResult (if given) gets
// the result too.
HRESULT D3DX11CompileFromFile(LPCSTR pSrcFile, const D3D_SHADER_MACRO* pDefines, ID3DInclude* pInclude,
                              LPCSTR pFunctionName, LPCSTR pProfile, UINT Flags1, UINT Flags2, void* pPump,
                              ID3DBlob** ppShader, ID3DBlob** ppErrorMsgs, HRESULT* pHResult);
HRESULT D3DCreateBlob(SIZE_T Size, ID3DBlob** ppBlob);

// --- reflection (d3d11shader.h)

enum D3D_SHADER_VARIABLE_CLASS : UINT {
    D3D_SVC_SCALAR = 0, D3D_SVC_VECTOR = 1, D3D_SVC_MATRIX_ROWS = 2, D3D_SVC_MATRIX_COLUMNS = 3, D3D_SVC_OBJECT = 4,
    D3D_SVC_STRUCT = 5,
};
enum D3D_SHADER_VARIABLE_TYPE : UINT { D3D_SVT_VOID = 0, D3D_SVT_BOOL = 1, D3D_SVT_INT = 2, D3D_SVT_FLOAT = 3, D3D_SVT_UINT = 19 };
enum D3D_SHADER_INPUT_TYPE : UINT {
    D3D_SIT_CBUFFER = 0, D3D_SIT_TBUFFER = 1, D3D_SIT_TEXTURE = 2, D3D_SIT_SAMPLER = 3, D3D_SIT_UAV_RWTYPED = 4,
    D3D_SIT_STRUCTURED = 5, D3D_SIT_UAV_RWSTRUCTURED = 6, D3D_SIT_BYTEADDRESS = 7, D3D_SIT_UAV_RWBYTEADDRESS = 8,
};
enum D3D_SRV_DIMENSION : UINT { D3D_SRV_DIMENSION_UNKNOWN = 0, D3D_SRV_DIMENSION_BUFFER = 1, D3D_SRV_DIMENSION_TEXTURE1D = 2,
                                D3D_SRV_DIMENSION_TEXTURE2D = 4, D3D_SRV_DIMENSION_TEXTURE2DARRAY = 5, D3D_SRV_DIMENSION_TEXTURE3D = 8, D3D_SRV_DIMENSION_TEXTURECUBE = 9 };
enum D3D_CBUFFER_TYPE : UINT { D3D_CT_CBUFFER = 0, D3D_CT_TBUFFER = 1 };
enum D3D_REGISTER_COMPONENT_TYPE : UINT {
    D3D_REGISTER_COMPONENT_UNKNOWN = 0, D3D_REGISTER_COMPONENT_UINT32 = 1, D3D_REGISTER_COMPONENT_SINT32 = 2,
    D3D_REGISTER_COMPONENT_FLOAT32 = 3,
};
enum D3D_NAME : UINT {
    D3D_NAME_UNDEFINED = 0, D3D_NAME_POSITION = 1, D3D_NAME_CLIP_DISTANCE = 2, D3D_NAME_CULL_DISTANCE = 3, D3D_NAME_VERTEX_ID = 6,
    D3D_NAME_INSTANCE_ID = 8, D3D_NAME_TARGET = 64, D3D_NAME_DEPTH = 65,
};
constexpr UINT D3D_SVF_USED = 2;

struct D3D11_SHADER_DESC {
    UINT Version = 0;  // D3D11_SHVER: program type << 16 | major << 4 | minor
    LPCSTR Creator = nullptr;
    UINT Flags = 0;
    UINT ConstantBuffers = 0;
    UINT BoundResources = 0;
    UINT InputParameters = 0;
    UINT OutputParameters = 0;
};
struct D3D11_SHADER_BUFFER_DESC {
    LPCSTR Name = nullptr;
    D3D_CBUFFER_TYPE Type = D3D_CT_CBUFFER;
    UINT Variables = 0;
    UINT Size = 0;
    UINT uFlags = 0;
};
struct D3D11_SHADER_VARIABLE_DESC {
    LPCSTR Name = nullptr;
    UINT StartOffset = 0;
    UINT Size = 0;
    UINT uFlags = 0;
    void* DefaultValue = nullptr;
    UINT StartTexture = 0xffffffffu;
    UINT TextureSize = 0;
    UINT StartSampler = 0xffffffffu;
    UINT SamplerSize = 0;
};
struct D3D11_SHADER_TYPE_DESC {
    D3D_SHADER_VARIABLE_CLASS Class = D3D_SVC_SCALAR;
    D3D_SHADER_VARIABLE_TYPE Type = D3D_SVT_VOID;
    UINT Rows = 0;
    UINT Columns = 0;
    UINT Elements = 0;
    UINT Members = 0;
    UINT Offset = 0;
    LPCSTR Name = nullptr;
};
struct D3D11_SHADER_INPUT_BIND_DESC {
    LPCSTR Name = nullptr;
    D3D_SHADER_INPUT_TYPE Type = D3D_SIT_CBUFFER;
    UINT BindPoint = 0;
    UINT BindCount = 1;
    UINT uFlags = 0;
    UINT ReturnType = 0;
    D3D_SRV_DIMENSION Dimension = D3D_SRV_DIMENSION_UNKNOWN;
    UINT NumSamples = 0;  // structured buffers: the element's size in bytes (D3D's tight layout)
};
struct D3D11_SIGNATURE_PARAMETER_DESC {
    LPCSTR SemanticName = nullptr;
    UINT SemanticIndex = 0;
    UINT Register = 0;
    D3D_NAME SystemValueType = D3D_NAME_UNDEFINED;
    D3D_REGISTER_COMPONENT_TYPE ComponentType = D3D_REGISTER_COMPONENT_UNKNOWN;
    UINT8 Mask = 0;
    UINT8 ReadWriteMask = 0;
    UINT Stream = 0;
};

// The sub-objects below live as long as the reflection that returned them (no reference counts,
// as in D3D). Asking for an index or name that does not exist returns an object whose GetDesc
// fails with E_FAIL, as D3D's "invalid" objects do.
// A variable's type: Name is HLSL's spelling ("float4", "float3x4", "uint"; a struct's type name is
// not recorded by fxport's compile, so a struct's is empty); Offset is a member's offset in bytes
// from its struct's start, by D3D's packing rules. Members of structs by index or name; IsEqual
// S_OK when both describe the same type (class, base type, shape, elements and members, by name),
// else S_FALSE. A struct inside a struct is not described (fxport's compile records one level of
// members: it reads as a scalar, and the offsets after it are not D3D's). Class linkage
// (GetSubType, GetBaseClass, interfaces) is not there.
class ID3D11ShaderReflectionType {
public:
    virtual HRESULT GetDesc(D3D11_SHADER_TYPE_DESC* pDesc) = 0;
    virtual ID3D11ShaderReflectionType* GetMemberTypeByIndex(UINT Index) = 0;
    virtual ID3D11ShaderReflectionType* GetMemberTypeByName(LPCSTR Name) = 0;
    virtual LPCSTR GetMemberTypeName(UINT Index) = 0;  // the member's name; null past the last
    virtual HRESULT IsEqual(ID3D11ShaderReflectionType* pType) = 0;

protected:
    ~ID3D11ShaderReflectionType() = default;
};
class ID3D11ShaderReflectionVariable {
public:
    virtual HRESULT GetDesc(D3D11_SHADER_VARIABLE_DESC* pDesc) = 0;
    virtual ID3D11ShaderReflectionType* GetType() = 0;

protected:
    ~ID3D11ShaderReflectionVariable() = default;
};
class ID3D11ShaderReflectionConstantBuffer {
public:
    virtual HRESULT GetDesc(D3D11_SHADER_BUFFER_DESC* pDesc) = 0;
    virtual ID3D11ShaderReflectionVariable* GetVariableByIndex(UINT Index) = 0;
    virtual ID3D11ShaderReflectionVariable* GetVariableByName(LPCSTR Name) = 0;

protected:
    ~ID3D11ShaderReflectionConstantBuffer() = default;
};
class ID3D11ShaderReflection : public IUnknown {
public:
    virtual HRESULT GetDesc(D3D11_SHADER_DESC* pDesc) = 0;
    virtual ID3D11ShaderReflectionConstantBuffer* GetConstantBufferByIndex(UINT Index) = 0;
    virtual ID3D11ShaderReflectionConstantBuffer* GetConstantBufferByName(LPCSTR Name) = 0;
    virtual ID3D11ShaderReflectionVariable* GetVariableByName(LPCSTR Name) = 0;
    virtual HRESULT GetResourceBindingDesc(UINT ResourceIndex, D3D11_SHADER_INPUT_BIND_DESC* pDesc) = 0;
    virtual HRESULT GetResourceBindingDescByName(LPCSTR Name, D3D11_SHADER_INPUT_BIND_DESC* pDesc) = 0;
    virtual HRESULT GetInputParameterDesc(UINT ParameterIndex, D3D11_SIGNATURE_PARAMETER_DESC* pDesc) = 0;
    // The output signature: SV_Target0..n and SV_Depth of a pixel shader; SV_Position, each user
    // semantic (Register = its GL location; ComponentType UNKNOWN and Mask 0: not recorded) and the
    // SV_ClipDistance registers of the other stages.
    virtual HRESULT GetOutputParameterDesc(UINT ParameterIndex, D3D11_SIGNATURE_PARAMETER_DESC* pDesc) = 0;
    // Compute shaders: [numthreads(x, y, z)] (each pointer may be null); the product, 0 for other stages.
    virtual UINT GetThreadGroupSize(UINT* pSizeX, UINT* pSizeY, UINT* pSizeZ) = 0;
};

// D3D's D3DReflect(data, size, IID_ID3D11ShaderReflection, (void**)&r), typed.
HRESULT D3DReflect(LPCVOID pSrcData, SIZE_T SrcDataSize, ID3D11ShaderReflection** ppReflector);

}  // namespace fxport::d3d11
