// EffectParameter::SetValue / GetValue: type-checked writes into the effect's constant-buffer
// shadow, laid out as the reflection says (HLSL packing, column_major or row_major).
#include <algorithm>
#include <cstdint>
#include <span>

#include "effect/effect_impl.h"
#include "fxport/graphics/errors.h"
#include "fxport/graphics/texture.h"

namespace fxport {

namespace {

using xlate::ParameterClass;
using xlate::ParameterType;

struct Access {
    Effect::Impl& e;
    const xlate::Parameter& p;
    int index;
    bool view;  // a struct member or an array element (StructureMembers / Elements)
    // "Effect 'GBuffer.fx' parameter 'World' (float4x4): ..." -- built only when failing, so the
    // SetValue fast path allocates nothing.
    [[noreturn]] void fail(const std::string& what) const {
        throw ArgumentError("Effect '" + e.displayName + "' parameter '" + p.name + "' (" +
                            Effect::Impl::hlslTypeName(p) + "): " + what);
    }

    bool numeric() const {
        return p.parameterClass == ParameterClass::Scalar || p.parameterClass == ParameterClass::Vector ||
               p.parameterClass == ParameterClass::Matrix;
    }
    int scalarsPerElement() const { return p.rows * p.columns; }
    int elementCount() const { return std::max(1, p.elements); }

    void requireSettable(const char* call) const {
        if (p.isStatic) fail(std::string(call) + ": the parameter is static/const, not settable (as in XNA)");
    }

    ConstantBlock& block() const { return e.blocks[std::size_t(p.block)].constants; }

    // A parameter no shader reads keeps its scalars in e.unread, as its type stores them.
    std::vector<double>& unreadValues() const {
        std::vector<double>& values = e.unread[std::size_t(index)];
        if (values.empty()) {
            values = p.defaultValue;
            values.resize(std::size_t(scalarsPerElement() * elementCount()), 0.0);
        }
        return values;
    }
    double asStored(double v) const {
        if (p.type == xlate::ParameterType::Float) return double(float(v));
        if (p.type == xlate::ParameterType::Bool) return v != 0 ? 1.0 : 0.0;
        if (p.type == xlate::ParameterType::Int) return double(std::int32_t(v));
        return double(std::uint32_t(v));
    }
    // Writes value(scalar) into the scalars of the first `elements` elements whose index (row by
    // row, element by element) is below `count`.
    template <class Value>
    void write(int elements, int count, Value&& value) const {
        if (p.offset >= 0) {
            block().store(p, elements, value, [&](const ConstantBlock::Scalar& s) { return s.index < count; });
            return;
        }
        if (view) return;  // a member or element of a parameter no shader reads: nothing holds it
        std::vector<double>& values = unreadValues();
        int k = 0;
        for (int el = 0; el < elements; ++el)
            for (int r = 0; r < p.rows; ++r)
                for (int c = 0; c < p.columns; ++c, ++k)
                    if (k < count && std::size_t(k) < values.size()) values[std::size_t(k)] = asStored(value(ConstantBlock::Scalar{k, el, r, c, -1}));
    }
    // Writes values[k] into scalar k (row by row, element by element) for the first n scalars.
    template <class T>
    void writeFirst(std::span<const T> values) const {
        write(elementCount(), int(values.size()), [&](const ConstantBlock::Scalar& s) { return double(values[std::size_t(s.index)]); });
    }
    double read(int k) const {
        if (!view) return e.parameterScalar(index, k);
        int per = std::max(1, scalarsPerElement());
        int at = ConstantBlock::offsetOf(p, k / per, k % per / p.columns, k % per % p.columns);
        const ConstantBlock& b = block();
        return p.offset >= 0 && b.holds(at) ? b.decode(p, at) : 0.0;
    }

    // SetValue of `count` elements each of `rows`x`cols` scalars given by get(element, r, c).
    template <class Get>
    void set(const char* call, ParameterClass cls, int rows, int cols, int count, bool isArray, Get get) const {
        bool ok = numeric() && p.parameterClass == cls;
        if (cls == ParameterClass::Matrix) ok = ok && p.rows <= rows && p.columns <= cols;
        else ok = ok && p.rows == rows && p.columns == cols;
        if (!ok) fail(std::string(call) + " does not fit this parameter");
        if (isArray ? count > elementCount() : p.elements > 0)
            fail(std::string(call) + (isArray ? " with " + std::to_string(count) + " elements overruns the array"
                                              : " on an array: pass an array of values"));
        requireSettable(call);
        write(count, count * scalarsPerElement(), [&](const ConstantBlock::Scalar& s) { return double(get(s.element, s.row, s.column)); });
    }

    void requireFloat(const char* call) const {
        if (p.type != ParameterType::Float) fail(std::string(call) + ": the parameter is not float-typed");
    }
};

}  // namespace

struct ParameterAccess {
    static Access of(const EffectParameter& parameter) {
        return Access{effectImpl(*parameter.effect_), parameter.desc(), parameter.index_, parameter.view_ != nullptr};
    }
};

namespace {

Access access(const EffectParameter& parameter) { return ParameterAccess::of(parameter); }

float matrixAt(const Matrix& m, int r, int c) { return m.data()[r * 4 + c]; }

bool isTextureType(ParameterType t) {
    return t == ParameterType::Texture || t == ParameterType::Texture1D || t == ParameterType::Texture2D ||
           t == ParameterType::Texture3D || t == ParameterType::TextureCube;
}

}  // namespace

const std::string& EffectParameter::Name() const { return desc().name; }
const std::string& EffectParameter::Semantic() const {
    return desc().semantic;
}
EffectParameterClass EffectParameter::ParameterClass() const {
    return EffectParameterClass(desc().parameterClass);
}
EffectParameterType EffectParameter::ParameterType() const {
    switch (desc().type) {
    case xlate::ParameterType::Void: return EffectParameterType::Void;
    case xlate::ParameterType::Bool: return EffectParameterType::Bool;
    case xlate::ParameterType::Int: case xlate::ParameterType::UInt: return EffectParameterType::Int32;
    case xlate::ParameterType::Float: return EffectParameterType::Single;
    case xlate::ParameterType::String: return EffectParameterType::String;
    case xlate::ParameterType::Texture: return EffectParameterType::Texture;
    case xlate::ParameterType::Texture1D: return EffectParameterType::Texture1D;
    case xlate::ParameterType::Texture2D: return EffectParameterType::Texture2D;
    case xlate::ParameterType::Texture3D: return EffectParameterType::Texture3D;
    case xlate::ParameterType::TextureCube: return EffectParameterType::TextureCube;
    default: return EffectParameterType::Sampler;
    }
}
int EffectParameter::RowCount() const { return desc().rows; }
int EffectParameter::ColumnCount() const { return desc().columns; }
int EffectParameter::ElementCount() const { return desc().elements; }
const std::vector<EffectAnnotation>& EffectParameter::Annotations() const {
    // Built on first use; parameters rarely have annotations.
    static thread_local std::vector<EffectAnnotation> out;
    out.clear();
    for (const xlate::Annotation& a : desc().annotations)
        out.push_back({a.name, a.type, a.value});
    return out;
}

// Scalars convert between bool, int and float as D3DX's SetBool/SetInt/SetFloat do (the deferred
// tutorial sets its float shadowMapSize from an int); vectors, matrices and class mismatches throw.
void EffectParameter::SetValue(bool value) {
    Access a = access(*this);
    a.set("SetValue(bool)", xlate::ParameterClass::Scalar, 1, 1, 1, false, [&](int, int, int) { return value ? 1.0 : 0.0; });
}
void EffectParameter::SetValue(int value) {
    Access a = access(*this);
    a.set("SetValue(int)", xlate::ParameterClass::Scalar, 1, 1, 1, false, [&](int, int, int) { return double(value); });
}
void EffectParameter::SetValue(float value) {
    Access a = access(*this);
    a.set("SetValue(float)", xlate::ParameterClass::Scalar, 1, 1, 1, false, [&](int, int, int) { return double(value); });
}
void EffectParameter::SetValue(const Vector2& v) {
    Access a = access(*this);
    a.requireFloat("SetValue(Vector2)");
    const float f[2] = {v.X, v.Y};
    a.set("SetValue(Vector2)", xlate::ParameterClass::Vector, 1, 2, 1, false, [&](int, int, int c) { return double(f[c]); });
}
void EffectParameter::SetValue(const Vector3& v) {
    Access a = access(*this);
    a.requireFloat("SetValue(Vector3)");
    const float f[3] = {v.X, v.Y, v.Z};
    a.set("SetValue(Vector3)", xlate::ParameterClass::Vector, 1, 3, 1, false, [&](int, int, int c) { return double(f[c]); });
}
void EffectParameter::SetValue(const Vector4& v) {
    Access a = access(*this);
    a.requireFloat("SetValue(Vector4)");
    const float f[4] = {v.X, v.Y, v.Z, v.W};
    a.set("SetValue(Vector4)", xlate::ParameterClass::Vector, 1, 4, 1, false, [&](int, int, int c) { return double(f[c]); });
}
void EffectParameter::SetValue(const Quaternion& q) { SetValue(Vector4(q.X, q.Y, q.Z, q.W)); }
void EffectParameter::SetValue(const Matrix& m) {
    Access a = access(*this);
    a.requireFloat("SetValue(Matrix)");
    a.set("SetValue(Matrix)", xlate::ParameterClass::Matrix, 4, 4, 1, false,
          [&](int, int r, int c) { return double(matrixAt(m, r, c)); });
}
void EffectParameter::SetValueTranspose(const Matrix& m) {
    Access a = access(*this);
    a.requireFloat("SetValueTranspose(Matrix)");
    a.set("SetValueTranspose(Matrix)", xlate::ParameterClass::Matrix, 4, 4, 1, false,
          [&](int, int r, int c) { return double(matrixAt(m, c, r)); });
}

void EffectParameter::SetValue(std::span<const float> values) {
    Access a = access(*this);
    if (!a.numeric()) a.fail("SetValue(float[]): the parameter is not numeric");
    int total = a.scalarsPerElement() * a.elementCount();
    if (int(values.size()) > total)
        a.fail("SetValue(float[]) with " + std::to_string(values.size()) + " values; the parameter holds " + std::to_string(total));
    a.requireSettable("SetValue(float[])");
    a.writeFirst(values);
}
void EffectParameter::SetValue(std::span<const int> values) {
    Access a = access(*this);
    if (!a.numeric() || a.p.type == xlate::ParameterType::Float) a.fail("SetValue(int[]): the parameter is not int-typed");
    int total = a.scalarsPerElement() * a.elementCount();
    if (int(values.size()) > total)
        a.fail("SetValue(int[]) with " + std::to_string(values.size()) + " values; the parameter holds " + std::to_string(total));
    a.requireSettable("SetValue(int[])");
    a.writeFirst(values);
}
void EffectParameter::SetValue(std::span<const Vector2> values) {
    Access a = access(*this);
    a.requireFloat("SetValue(Vector2[])");
    a.set("SetValue(Vector2[])", xlate::ParameterClass::Vector, 1, 2, int(values.size()), true,
          [&](int e, int, int c) { return double(c == 0 ? values[std::size_t(e)].X : values[std::size_t(e)].Y); });
}
void EffectParameter::SetValue(std::span<const Vector3> values) {
    Access a = access(*this);
    a.requireFloat("SetValue(Vector3[])");
    a.set("SetValue(Vector3[])", xlate::ParameterClass::Vector, 1, 3, int(values.size()), true, [&](int e, int, int c) {
        const Vector3& v = values[std::size_t(e)];
        return double(c == 0 ? v.X : c == 1 ? v.Y : v.Z);
    });
}
void EffectParameter::SetValue(std::span<const Vector4> values) {
    Access a = access(*this);
    a.requireFloat("SetValue(Vector4[])");
    a.set("SetValue(Vector4[])", xlate::ParameterClass::Vector, 1, 4, int(values.size()), true, [&](int e, int, int c) {
        const Vector4& v = values[std::size_t(e)];
        return double(c == 0 ? v.X : c == 1 ? v.Y : c == 2 ? v.Z : v.W);
    });
}
void EffectParameter::SetValue(std::span<const Matrix> values) {
    Access a = access(*this);
    a.requireFloat("SetValue(Matrix[])");
    a.set("SetValue(Matrix[])", xlate::ParameterClass::Matrix, 4, 4, int(values.size()), true,
          [&](int e, int r, int c) { return double(matrixAt(values[std::size_t(e)], r, c)); });
}

void EffectParameter::SetValue(Texture* texture) {
    Access a = access(*this);
    if (a.p.parameterClass != xlate::ParameterClass::Object || !isTextureType(a.p.type))
        a.fail("SetValue(Texture) on a parameter that is not a texture");
    if (texture) {
        if (texture->IsDisposed()) a.fail("SetValue(Texture): the texture was disposed");
        bool cube = texture->kind() == Texture::Kind::TextureCube;
        if ((a.p.type == xlate::ParameterType::TextureCube && !cube) || (a.p.type == xlate::ParameterType::Texture2D && cube))
            a.fail(std::string("SetValue(Texture): got a ") + (cube ? "cube" : "2D") + " texture");
    }
    if (a.view) a.fail("SetValue(Texture) on a struct member or array element");
    a.e.textures[std::size_t(index_)] = texture;
}

bool EffectParameter::GetValueBoolean() const { return access(*this).read(0) != 0; }
int EffectParameter::GetValueInt32() const { return int(access(*this).read(0)); }
float EffectParameter::GetValueSingle() const { return float(access(*this).read(0)); }
Vector2 EffectParameter::GetValueVector2() const {
    Access a = access(*this);
    return Vector2(float(a.read(0)), float(a.read(1)));
}
Vector3 EffectParameter::GetValueVector3() const {
    Access a = access(*this);
    return Vector3(float(a.read(0)), float(a.read(1)), float(a.read(2)));
}
Vector4 EffectParameter::GetValueVector4() const {
    Access a = access(*this);
    return Vector4(float(a.read(0)), float(a.read(1)), float(a.read(2)), float(a.read(3)));
}
Matrix EffectParameter::GetValueMatrix() const {
    Access a = access(*this);
    if (a.p.parameterClass != xlate::ParameterClass::Matrix) a.fail("GetValueMatrix: the parameter is not a matrix");
    Matrix m = Matrix::Identity;
    for (int r = 0; r < a.p.rows; ++r)
        for (int c = 0; c < a.p.columns; ++c) m.data()[r * 4 + c] = float(a.read(r * a.p.columns + c));
    return m;
}
std::vector<float> EffectParameter::GetValueSingleArray() const {
    Access a = access(*this);
    std::vector<float> out;
    for (int k = 0; k < a.scalarsPerElement() * a.elementCount(); ++k) out.push_back(float(a.read(k)));
    return out;
}
std::vector<Matrix> EffectParameter::GetValueMatrixArray(int count) const {
    Access a = access(*this);
    if (a.p.parameterClass != xlate::ParameterClass::Matrix) a.fail("GetValueMatrixArray: the parameter is not a matrix");
    std::vector<Matrix> out;
    for (int e = 0; e < std::min(count, a.elementCount()); ++e) {
        Matrix m = Matrix::Identity;
        for (int r = 0; r < a.p.rows; ++r)
            for (int c = 0; c < a.p.columns; ++c)
                m.data()[r * 4 + c] = float(a.read(e * a.scalarsPerElement() + r * a.p.columns + c));
        out.push_back(m);
    }
    return out;
}
std::string EffectParameter::GetValueString() const {
    Access a = access(*this);
    if (a.p.type != xlate::ParameterType::String) a.fail("GetValueString: the parameter is not a string");
    return a.p.defaultString;
}
Texture* EffectParameter::GetValueTexture() const { return view_ ? nullptr : effectImpl(*effect_).textures[std::size_t(index_)]; }
Texture2D* EffectParameter::GetValueTexture2D() const {
    Texture* t = GetValueTexture();
    return t && t->kind() == Texture::Kind::Texture2D ? static_cast<Texture2D*>(t) : nullptr;
}
TextureCube* EffectParameter::GetValueTextureCube() const {
    Texture* t = GetValueTexture();
    return t && t->kind() == Texture::Kind::TextureCube ? static_cast<TextureCube*>(t) : nullptr;
}

}  // namespace fxport
