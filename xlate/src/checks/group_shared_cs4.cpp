// Thread-group shared memory at cs_4_0/cs_4_1 is a narrower thing than at cs_5_0: each thread
// owns one element and writes only it. fxc therefore wants every groupshared variable a cs_4_x
// shader uses to be an array of as many elements as the group has threads, and every store to
// index it by SV_GroupIndex (vkd3d's tgsm: `groupshared uint m;` and `m[1]` with 4 threads are
// refused, `m[0] = 0` into `m[4]` is not implemented; `m[local_idx] = ...` compiles). glslang
// knows no such limit. Judged on the entries compiled for cs_4_x and the functions they reach.
#include <algorithm>
#include <cstdlib>

#include "checks/fxc_checks.h"
#include "fx/text_util.h"

namespace fxport::xlate {

namespace {

bool has(const std::vector<std::string>& modifiers, const char* m) {
    return std::find(modifiers.begin(), modifiers.end(), m) != modifiers.end();
}

// The product of [numthreads(x, y, z)] written with literals, 0 when not.
long threadsOf(const std::string& attributes) {
    const size_t at = attributes.find("numthreads");
    if (at == std::string::npos) return 0;
    const char* p = attributes.c_str() + attributes.find('(', at) + 1;
    long product = 1;
    for (int k = 0; k < 3; ++k) {
        char* end = nullptr;
        const long v = std::strtol(p, &end, 0);
        if (end == p || v <= 0) return 0;
        product *= v;
        while (*end == ' ') ++end;
        if (*end != (k < 2 ? ',' : ')')) return 0;
        p = end + 1;
    }
    return product;
}

bool isWrite(const Token& t) {
    for (const char* op : {"=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "++", "--"})
        if (t.is(op)) return true;
    return false;
}

class GroupSharedCs4 : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (const auto& e : compiledEntries()) {
            if (e.profile.stage != ShaderStage::Compute || e.profile.major != 4) continue;
            const long threads = threadsOf(e.function->attributes);
            std::string groupIndex;
            for (const auto& p : e.function->parameters)
                if (iequals(p.semantic, "SV_GroupIndex")) groupIndex = p.name;
            const auto reached = reachableFrom(*e.function);
            for (const auto& g : syntax_.globals) {
                if (!has(g.modifiers, "groupshared") || !mentionedIn(reached, g.name)) continue;
                if (threads && (g.arrayDims.size() != 1 || g.arrayDims[0] != threads))
                    report("groupshared '" + g.name + "' must be an array of " + std::to_string(threads) +
                               " elements at cs_4_x, one per thread of the group",
                           g.token);
                else
                    stores(reached, g.name, groupIndex);
            }
        }
    }

private:
    // Each store to `name` must be `name[groupIndex]`.
    void stores(const std::vector<const FxFunction*>& functions, const std::string& name, const std::string& groupIndex) {
        for (const FxFunction* f : functions)
            for (size_t i = f->body.begin; i + 1 < f->body.end; ++i) {
                if (!t_[i].is(name) || (i > 0 && t_[i - 1].is(".")) || !t_[i + 1].is("[")) continue;
                const size_t close = closing(i + 1);
                size_t after = close + 1;
                if (tok(after).is(".")) after += 2;  // a member of the element
                if (!isWrite(tok(after)) && !(i > 0 && (t_[i - 1].is("++") || t_[i - 1].is("--")))) continue;
                if (!groupIndex.empty() && close == i + 3 && t_[i + 2].is(groupIndex)) continue;
                report("cs_4_x writes groupshared '" + name + "' only at SV_GroupIndex, each thread its own element (not implemented otherwise)", i + 2);
            }
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findGroupSharedCs4Errors(const EffectSyntax& syntax, const SourceMap& map) {
    GroupSharedCs4 check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
