// fxc's rules for InputPatch<T, N> and OutputPatch<T, N> (vkd3d's patch-syntax pins them). Outside
// a tessellation signature a patch is a read-only array; glslang's HLSL front end takes it as a
// plain array, so what fxc refuses is judged here:
//  - N is at least 1, and at most 32 in a hull or domain shader's signature;
//  - a local patch has an initial value, and no element of a patch is assigned;
//  - as an entry parameter: InputPatch in a hull shader (and its patch-constant function) or a
//    gs_5_0 geometry shader, OutputPatch in a domain shader or a hull shader's patch-constant
//    function, one of each kind at most;
//  - a hull shader's patch-constant function takes the InputPatch of its entry (same T and N), and
//    its OutputPatch holds the entry's output type, [outputcontrolpoints] of them.
#include <algorithm>
#include <cctype>
#include <optional>

#include "checks/fxc_checks.h"
#include "entry/stage_attributes.h"

namespace fxport::xlate {

namespace {

struct PatchType {
    bool input = false;     // InputPatch, else OutputPatch
    std::string element;    // T, spaces removed
    int size = -1;          // N; -1 when not a literal
};

std::string withoutSpaces(std::string s) {
    s.erase(std::remove_if(s.begin(), s.end(), [](unsigned char c) { return std::isspace(c); }), s.end());
    return s;
}

// `InputPatch<T, N>` as the parser writes a parameter's type.
std::optional<PatchType> parsePatchType(const std::string& type) {
    std::string t = withoutSpaces(type);
    PatchType p;
    if (t.rfind("InputPatch<", 0) == 0) p.input = true;
    else if (t.rfind("OutputPatch<", 0) != 0) return std::nullopt;
    size_t open = t.find('<'), comma = t.rfind(','), close = t.rfind('>');
    if (comma == std::string::npos || close == std::string::npos || comma < open || close < comma) return std::nullopt;
    p.element = t.substr(open + 1, comma - open - 1);
    std::string n = t.substr(comma + 1, close - comma - 1);
    if (!n.empty() && std::all_of(n.begin(), n.end(), [](unsigned char c) { return std::isdigit(c); })) p.size = std::stoi(n);
    return p;
}

const char* kindName(bool input) { return input ? "InputPatch" : "OutputPatch"; }

bool isAssignment(const Token& t) {
    for (const char* op : {"=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<=", ">>=", "++", "--"})
        if (t.is(op)) return true;
    return false;
}

class PatchObjects : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (size_t i = 0; i + 1 < t_.size(); ++i)
            if (t_[i].is("InputPatch") || t_[i].is("OutputPatch")) declaration(i);
        for (const auto& f : syntax_.functions)
            for (const auto& p : f.parameters)
                if (parsePatchType(p.type)) writes(f, p.name);
        for (const auto& e : compiledEntries()) entryParameters(e);
    }

private:
    // `InputPatch<T, N> name` anywhere: N >= 1; a local one is initialised; its elements are not written.
    void declaration(size_t at) {
        if (!tok(at + 1).is("<")) return;
        size_t close = closing(at + 1);
        if (tok(close - 1).kind == Token::Kind::Number && tok(close - 2).is(",") && tok(close - 1).text == "0")
            report(std::string(kindName(t_[at].is("InputPatch"))) + " needs at least one control point, not 0", close - 1);
        const FxFunction* f = functionAt(at);
        if (!f || at < f->body.begin || !tok(close + 1).isIdent()) return;
        size_t name = close + 1;
        if (tok(name + 1).is(";") || tok(name + 1).is(","))
            report("patch variable '" + t_[name].text + "' needs an initial value: patches are read-only", name);
        writes(*f, t_[name].text);
    }

    // `name[i] = ...`, `name[i].member += ...`, `++name[i]`: patches are read-only.
    void writes(const FxFunction& f, const std::string& name) {
        for (size_t i = f.body.begin; i < f.body.end; ++i) {
            if (!t_[i].is(name) || !tok(i + 1).is("[") || (i > 0 && t_[i - 1].is("."))) continue;
            size_t j = closing(i + 1) + 1;
            while (tok(j).is(".") && tok(j + 1).isIdent()) j += 2;
            bool pre = i > 0 && (t_[i - 1].is("++") || t_[i - 1].is("--"));
            if (isAssignment(tok(j)) || pre) report("patch '" + name + "' is read-only: its control points cannot be assigned", i);
        }
    }

    void entryParameters(const CompiledEntry& e) {
        const ShaderStage stage = e.profile.stage;
        int inputs = 0, outputs = 0;
        for (const auto& p : e.function->parameters) {
            auto patch = parsePatchType(p.type);
            if (!patch) continue;
            (patch->input ? inputs : outputs)++;
            if ((patch->input ? inputs : outputs) == 2)
                report("'" + e.function->name + "' takes a second " + kindName(patch->input) + " ('" + p.name + "'): one is allowed", p.typeToken);
            if ((stage == ShaderStage::Hull || stage == ShaderStage::Domain) && patch->size > 32)
                report(std::string(kindName(patch->input)) + " '" + p.name + "' of a tessellation shader holds at most 32 control points, not " +
                           std::to_string(patch->size),
                       p.typeToken);
            bool allowed = patch->input ? stage == ShaderStage::Hull || (stage == ShaderStage::Geometry && e.profile.major >= 5)
                                        : stage == ShaderStage::Domain;
            if (!allowed && (stage == ShaderStage::Hull || stage == ShaderStage::Domain || stage == ShaderStage::Geometry))
                report(std::string(kindName(patch->input)) + " parameter '" + p.name + "' cannot be an input of " + e.profile.name +
                           (patch->input ? " (hull shaders and gs_5_0 geometry shaders take InputPatch)"
                                         : " (domain shaders and patch-constant functions take OutputPatch)"),
                       p.typeToken);
        }
        if (stage == ShaderStage::Hull) patchConstantFunction(e);
    }

    // The patch-constant function sees the entry's InputPatch and its output points.
    void patchConstantFunction(const CompiledEntry& e) {
        Tessellation tess;
        if (!checkStageAttributes(syntax_, *e.function, e.profile, tess).empty() || tess.patchConstantFunction.empty()) return;
        const FxFunction* pcf = nullptr;  // fxc takes the last definition of an overloaded name
        for (const auto& f : syntax_.functions)
            if (f.name == tess.patchConstantFunction) pcf = &f;
        if (!pcf) return;
        std::optional<PatchType> entryInput;
        for (const auto& p : e.function->parameters)
            if (auto patch = parsePatchType(p.type); patch && patch->input) entryInput = patch;
        const std::string entryOutput = withoutSpaces(syntax_.resolveType(e.function->returnType));
        for (const auto& p : pcf->parameters) {
            auto patch = parsePatchType(p.type);
            if (!patch) continue;
            if (patch->input && entryInput && (patch->element != entryInput->element || patch->size != entryInput->size))
                report("InputPatch '" + p.name + "' of patch-constant function '" + pcf->name + "' differs from the InputPatch of hull shader '" +
                           e.function->name + "': they must be the same type",
                       p.typeToken);
            if (!patch->input && (withoutSpaces(syntax_.resolveType(patch->element)) != entryOutput ||
                                  (tess.outputControlPoints > 0 && patch->size >= 0 && patch->size != tess.outputControlPoints)))
                report("OutputPatch '" + p.name + "' of patch-constant function '" + pcf->name + "' must hold the output of hull shader '" +
                           e.function->name + "' (" + e.function->returnType + "), [outputcontrolpoints] of them",
                       p.typeToken);
        }
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findPatchObjectErrors(const EffectSyntax& syntax, const SourceMap& map) {
    PatchObjects check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
