// See matrix_rows_intrinsics.h.
#include "rewrite/matrix_rows_intrinsics.h"

#include <algorithm>
#include <map>
#include <string>

#include "hlsl/call_arguments.h"
#include "hlsl/expression_types.h"

namespace fxport::xlate {

namespace {

bool isRowwise(const std::string& s) {
    return s == "all" || s == "any" || s == "asint" || s == "asuint" || s == "asfloat" || s == "sign";
}

std::string helperCode(const std::string& intrinsic, const std::string& name, const BasicType& m) {
    const std::string from = spellType(m);
    std::string code;
    if (intrinsic == "all" || intrinsic == "any") {
        code = "bool " + name + "(" + from + " v) { return ";
        for (int r = 0; r < m.rows; ++r) code += std::string(r ? (intrinsic == "all" ? " && " : " || ") : "") + intrinsic + "(v[" + std::to_string(r) + "])";
        return code + "; } ";
    }
    BasicType to = m;
    // sign's int matrix is made a float one: glslang writes int matrices as SPIR-V no GLSL has (imat2).
    to.scalar = intrinsic == "asint" ? "int" : intrinsic == "asuint" ? "uint" : "float";
    code = spellType(to) + " " + name + "(" + from + " v) { return " + spellType(to) + "(";
    for (int r = 0; r < m.rows; ++r) code += std::string(r ? ", " : "") + intrinsic + "(v[" + std::to_string(r) + "])";
    return code + "); } ";
}

}  // namespace

std::vector<TextEdit> matrixIntrinsicsByRow(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<const FxFunction*> functions;
    for (const auto& f : syntax.functions)
        if (!f.body.empty() && !f.declaration.empty()) functions.push_back(&f);
    std::sort(functions.begin(), functions.end(), [](const FxFunction* a, const FxFunction* b) { return a->declaration.begin < b->declaration.begin; });
    std::vector<TextEdit> edits;
    std::map<std::string, bool> defined;
    for (const FxFunction* f : functions) {
        std::string helpers;
        for (size_t i = f->body.begin; i + 1 < f->body.end; ++i) {
            if (!t[i].isIdent() || !isRowwise(t[i].text) || !t[i + 1].is("(") || (i > 0 && t[i - 1].is(".")) || syntax.findFunction(t[i].text)) continue;
            auto spans = callArgumentSpans(t, i + 1, f->body.end);
            if (spans.size() != 1) continue;
            auto type = expressionType(syntax, *f, spans[0].first, spans[0].second);
            if (!type || !type->isNumeric() || type->keptMatrix || !type->basic.isMatrix || type->basic.rows < 2 || type->basic.columns < 2) continue;
            const std::string name = "fxport_" + t[i].text + "_" + spellType(type->basic);
            if (!defined[name]) helpers += helperCode(t[i].text, name, type->basic);
            defined[name] = true;
            edits.push_back({t[i].offset, t[i].end, name});
        }
        if (!helpers.empty()) edits.push_back({t[f->declaration.begin].offset, t[f->declaration.begin].offset, helpers});
    }
    return edits;
}

}  // namespace fxport::xlate
