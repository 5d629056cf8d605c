// See length_property.h.
#include "rewrite/length_property.h"

#include <algorithm>
#include <set>
#include <string>

#include "checks/fxc_checks.h"

namespace fxport::xlate {

namespace {

struct LengthShape {
    int size = 0;       // components of Length (0: the type has none)
    int arguments = 0;  // GetDimensions' out arguments (Length is the first `size` of them)
};

LengthShape lengthShape(const std::string& written) {
    const std::string type = written.substr(0, written.find('<'));
    if (type == "Texture1D" || type == "RWTexture1D" || type == "Buffer" || type == "RWBuffer") return {1, 1};
    if (type == "StructuredBuffer" || type == "RWStructuredBuffer") return {1, 2};
    if (type == "Texture1DArray" || type == "RWTexture1DArray" || type == "Texture2D" || type == "RWTexture2D") return {2, 2};
    if (type == "Texture2DMS") return {2, 3};
    if (type == "Texture2DArray" || type == "RWTexture2DArray" || type == "Texture3D" || type == "RWTexture3D") return {3, 3};
    if (type == "Texture2DMSArray") return {3, 4};
    return {};
}

// The declared type of the global object `name`, or empty.
std::string objectType(const EffectSyntax& syntax, const std::string& name) {
    if (const FxTexture* t = syntax.findTexture(name)) return t->type;
    for (const auto& g : syntax.globals)
        if (g.name == name && g.arrayDims.empty()) return g.type;
    return {};
}

// `name . Length` at i (the name's token) of a global object that has a Length.
bool lengthAt(const EffectSyntax& syntax, size_t i, LengthShape& shape) {
    const auto& t = syntax.tokens;
    if (i + 2 >= t.size() || !t[i].isIdent() || !t[i + 1].is(".") || !t[i + 2].is("Length") || (i > 0 && t[i - 1].is("."))) return false;
    shape = lengthShape(objectType(syntax, t[i].text));
    return shape.size > 0;
}

std::string helper(const std::string& object, const LengthShape& shape) {
    const std::string type = shape.size == 1 ? "uint" : "uint" + std::to_string(shape.size);
    std::string declared, passed, returned;
    for (int k = 0; k < shape.arguments; ++k) {
        const std::string a = "a" + std::to_string(k);
        declared += (k ? ", " : "") + a;
        passed += (k ? ", " : "") + a;
        if (k < shape.size) returned += (k ? ", " : "") + a;
    }
    return type + " fxport_Length_" + object + "() { uint " + declared + "; " + object + ".GetDimensions(" + passed + "); return " + type + "(" +
           returned + "); } ";
}

class LengthPropertyRules : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (const auto& e : compiledEntries()) {
            if (e.profile.major >= 4) continue;
            for (const FxFunction* f : reachableFrom(*e.function))
                for (size_t i = f->body.begin; i < f->body.end; ++i)
                    if (LengthShape shape; lengthAt(syntax_, i, shape))
                        report("invalid subscript 'Length': textures and buffers have no Length in " + e.profile.name + " (fxc X3018)", i + 2);
        }
    }
};

}  // namespace

std::vector<TextEdit> lengthPropertiesAsCalls(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<const FxFunction*> functions;
    for (const auto& f : syntax.functions)
        if (!f.body.empty() && !f.declaration.empty()) functions.push_back(&f);
    std::sort(functions.begin(), functions.end(), [](const FxFunction* a, const FxFunction* b) { return a->declaration.begin < b->declaration.begin; });
    std::vector<TextEdit> edits;
    std::set<std::string> defined;
    for (const FxFunction* f : functions) {
        std::string helpers;
        for (size_t i = f->body.begin; i < f->body.end; ++i) {
            LengthShape shape;
            if (!lengthAt(syntax, i, shape)) continue;
            if (defined.insert(t[i].text).second) helpers += helper(t[i].text, shape);
            edits.push_back({t[i].offset, t[i + 2].end, "fxport_Length_" + t[i].text + "()"});
        }
        if (!helpers.empty()) edits.push_back({t[f->declaration.begin].offset, t[f->declaration.begin].offset, helpers});
    }
    return edits;
}

std::vector<std::pair<size_t, Diagnostic>> findLengthPropertyErrors(const EffectSyntax& syntax, const SourceMap& map) {
    LengthPropertyRules check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
