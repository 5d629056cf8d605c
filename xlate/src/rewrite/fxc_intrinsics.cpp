// See fxc_intrinsics.h. The coefficients and the order of operations are those of fxc's expansions
// (as its SM4 output shows them: mad chains, a reciprocal for the ratio, masks for the quadrants).
#include "rewrite/fxc_intrinsics.h"

#include <algorithm>
#include <string>

namespace fxport::xlate {

namespace {

const char* const kIntrinsics[] = {"asin", "acos", "atan", "atan2", "lit"};

// The helpers for one vector width T (float, float2, float3, float4); comparisons are cast to T,
// the masks fxc's code uses.
std::string helpersFor(const std::string& T) {
    const std::string poly = "((-0.0187292993 * a + 0.0742610022) * a - 0.212114394) * a + 1.57072878";
    const std::string atanPoly =
        "(((0.0208350997 * t2 - 0.0851330012) * t2 + 0.180141002) * t2 - 0.330299497) * t2 + 0.999866009";
    std::string s;
    s += T + " fxport_acos(" + T + " x) { " + T + " a = abs(x); " + T + " r = (" + poly + ") * sqrt(1.0 - a); " + T +
         " n = (" + T + ")(x < 0.0); return r + n * (r * -2.0 + 3.14159274); } ";
    s += T + " fxport_asin(" + T + " x) { " + T + " a = abs(x); " + T + " r = 1.57079637 - (" + poly + ") * sqrt(1.0 - a); " +
         T + " n = (" + T + ")(x < 0.0); return r - 2.0 * n * r; } ";
    s += T + " fxport_atan(" + T + " x) { " + T + " a = abs(x); " + T + " t = min(a, 1.0) * (1.0 / max(a, 1.0)); " + T +
         " t2 = t * t; " + T + " r = t * (" + atanPoly + "); " + T + " big = (" + T + ")(1.0 < a); r = r + big * (r * -2.0 + 1.57079637); " +
         T + " n = (" + T + ")(x < 0.0); return r - 2.0 * n * r; } ";
    s += T + " fxport_atan2(" + T + " y, " + T + " x) { " + T + " ax = abs(x); " + T + " ay = abs(y); " + T +
         " t = min(ax, ay) * (1.0 / max(ax, ay)); " + T + " t2 = t * t; " + T + " r = t * (" + atanPoly + "); " + T +
         " steep = (" + T + ")(ax < ay); r = r + steep * (r * -2.0 + 1.57079637); " + T +
         " back = (" + T + ")(x < 0.0); r = r - back * 3.14159274; " + T + " flip = (" + T +
         ")(min(y, x) < 0.0) * (" + T + ")(max(y, x) >= 0.0); return r - 2.0 * flip * r; } ";
    return s;
}

bool isIntrinsicCall(const std::vector<Token>& t, size_t i) {
    if (!t[i].isIdent() || i + 1 >= t.size() || !t[i + 1].is("(")) return false;
    if (i > 0 && t[i - 1].is(".")) return false;
    for (const char* name : kIntrinsics)
        if (t[i].text == name) return true;
    return false;
}

}  // namespace

std::vector<TextEdit> intrinsicsAsFxc(const EffectSyntax& syntax) {
    std::vector<TextEdit> edits;
    if (syntax.functions.empty()) return edits;
    for (const char* name : kIntrinsics)
        if (syntax.findFunction(name)) return edits;  // the effect's own asin(): its calls are its own
    const std::vector<Token>& t = syntax.tokens;
    size_t first = syntax.functions.front().declaration.begin;
    for (const auto& f : syntax.functions) first = std::min(first, f.declaration.begin);
    for (size_t i = first; i < t.size(); ++i)
        if (isIntrinsicCall(t, i)) edits.push_back({t[i].offset, t[i].end, "fxport_" + t[i].text});
    if (edits.empty()) return edits;
    std::string helpers;
    for (const char* T : {"float", "float2", "float3", "float4"}) helpers += helpersFor(T);
    helpers += "float4 fxport_lit(float l, float h, float m) { float s = (l < 0.0 || h < 0.0) ? 0.0 : pow(h, m); "
               "return float4(1.0, max(l, 0.0), s, 1.0); } ";
    edits.push_back({t[first].offset, t[first].offset, helpers});
    return edits;
}

}  // namespace fxport::xlate
