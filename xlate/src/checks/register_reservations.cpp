// fxc's rules for `register(...)` reservations that glslang does not check (fxc X3530 and the
// overlap error; vkd3d's register-reservations-profile and -numeric pin them):
//  - `register(profile, r)`: the profile is a stage (vs, ps, gs, hs, ds, cs), optionally indexed
//    (`ps[5]`), or a profile fxc knows up to SM 5 (ps_4_0, vs_3_0 ...); `ps_4`, `PS`, `ps.4.0`,
//    `register(t1, ps_4_0)` are not;
//  - two reservations of one register class that both apply to a shader the effect compiles (no
//    profile, its stage, or its exact profile) must name the same register; two with the same
//    profile must always;
//  - a sampler takes an s or t register, a cbuffer `bN` and nothing after the number, a number at
//    SM 2-3 a register letter followed by its index (`register(banana)` is none);
//  - two $Globals numbers reserved at overlapping c registers: at SM 4-5 when either is used, at
//    SM 2-3 when both are (SM 6 aliases them; fxport compiles up to SM 5).
// "Used" is judged per compiled shader: the name appears in a function its entry reaches.
#include <algorithm>
#include <cstdlib>
#include <cctype>
#include <set>

#include "checks/fxc_checks.h"
#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

namespace {

// One `register(...)` clause of a declaration.
struct Reservation {
    size_t token = 0;         // `register`
    std::string profile;      // empty: for every shader
    size_t profileToken = 0;
    std::string reg;          // t1, c4, s0, b2 (its first token's text)
    size_t regToken = 0;
};

bool isStage(const std::string& s) {
    return s == "vs" || s == "ps" || s == "gs" || s == "hs" || s == "ds" || s == "cs";
}

class RegisterReservations : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        entries_ = compiledEntries();
        for (const auto& g : syntax_.globals) declaration(g.token, Kind::Number);
        for (const auto& s : syntax_.samplers) declaration(s.token, Kind::Sampler);
        for (const auto& x : syntax_.textures) declaration(x.token, Kind::Other);
        for (size_t i = 0; i + 1 < t_.size(); ++i)
            if (t_[i].is("cbuffer") && t_[i + 1].isIdent()) declaration(i + 1, Kind::Buffer);  // a tbuffer takes a t register
        overlappingConstants();
    }

private:
    enum class Kind { Number, Sampler, Buffer, Other };
    std::vector<CompiledEntry> entries_;
    std::set<size_t> seen_;  // name tokens already checked (a global is listed once per declarator)

    // The `register(...)` clauses after the name at `nameToken`: `name[2] : SEM : register(ps, c1)`.
    std::vector<Reservation> reservations(size_t nameToken) const {
        std::vector<Reservation> out;
        size_t i = nameToken + 1;
        while (tok(i).is("[")) i = closing(i) + 1;
        while (tok(i).is(":") && tok(i + 1).isIdent()) {
            if (!tok(i + 2).is("(")) {
                i += 2;
                continue;
            }
            size_t close = closing(i + 2);
            if (tok(i + 1).is("register")) {
                Reservation r;
                r.token = i + 1;
                size_t comma = i + 3;
                int depth = 0;
                for (; comma < close; ++comma) {
                    depth += opensGroup(t_[comma]) ? 1 : closesGroup(t_[comma]) ? -1 : 0;
                    if (depth == 0 && t_[comma].is(",")) break;
                }
                size_t regBegin = i + 3;
                if (comma < close) {
                    for (size_t k = i + 3; k < comma; ++k) r.profile += t_[k].text;
                    r.profileToken = i + 3;
                    regBegin = comma + 1;
                }
                r.reg = tok(regBegin).text;
                r.regToken = regBegin;
                out.push_back(r);
            }
            i = close + 1;
        }
        return out;
    }
    static bool opensGroup(const Token& t) { return t.is("(") || t.is("["); }
    static bool closesGroup(const Token& t) { return t.is(")") || t.is("]"); }

    // `ps`, `ps[5]`, `ps_4_0`: what fxc takes before the register.
    static bool validProfile(const std::string& p) {
        std::string name = p.substr(0, p.find('['));
        if (isStage(name)) return true;
        auto profile = parseShaderProfile(name);
        return profile && profile->major <= 5 && name.find('[') == std::string::npos && p == name;
    }
    // Whether a reservation with `profile` applies to a shader compiled with `target`.
    static bool appliesTo(const std::string& profile, const ShaderProfile& target) {
        if (profile.empty()) return true;
        std::string name = profile.substr(0, profile.find('['));
        if (isStage(name)) return name == target.name.substr(0, 2);
        return name == target.name;
    }

    void declaration(size_t nameToken, Kind kind) {
        if (!seen_.insert(nameToken).second) return;
        std::vector<Reservation> list = reservations(nameToken);
        for (const auto& r : list) {
            if (!r.profile.empty() && !validProfile(r.profile)) {
                report("'" + r.profile + "' in register(" + r.profile + ", ...) is not a shader profile fxc knows (vs, ps, gs, ps_4_0 ...) (fxc X3530)",
                       r.profileToken);
                return;
            }
            registerName(r, kind);
        }
        for (size_t a = 0; a < list.size(); ++a)
            for (size_t b = 0; b < a; ++b) contradiction(list[b], list[a]);
    }

    void registerName(const Reservation& r, Kind kind) {
        const std::string& s = r.reg;
        if (s.empty() || !std::isalpha(static_cast<unsigned char>(s[0]))) return;
        char letter = char(std::tolower(static_cast<unsigned char>(s[0])));
        bool digitFollows = s.size() > 1 && std::isdigit(static_cast<unsigned char>(s[1]));
        bool indexed = s.size() == 1 && tok(r.regToken + 1).is("[");
        bool bare = s.size() == 1 && !indexed;
        if (kind == Kind::Sampler && (letter != 's' && letter != 't' ? true : !(digitFollows || indexed)))
            report("register(" + s + ") is not a sampler register: a sampler requires an 's' or 't' register (fxc X3530)", r.regToken);
        // Before SM 5.1 fxc takes a constant buffer's slot as c# too (the D3D12 HLSL docs: "in
        // previous versions it could be c or b"); AMD's ShadowFX ships fxc 6.3's output of one.
        else if (kind == Kind::Buffer && ((letter != 'b' && letter != 'c') || !digitFollows || s.find_first_not_of("0123456789", 1) != std::string::npos))
            report("register(" + s + ") is not a constant buffer register like b0 (fxc X3530)", r.regToken);
        else if (kind == Kind::Number && !digitFollows && !indexed && !bare && anyEntryBelow4())
            report("register(" + s + ") is not a register name (a letter and its index, like c4) (fxc X3530)", r.regToken);
    }
    bool anyEntryBelow4() const {
        for (const auto& e : entries_)
            if (e.profile.major < 4) return true;
        return false;
    }

    void contradiction(const Reservation& a, const Reservation& b) {
        if (std::tolower(static_cast<unsigned char>(a.reg[0])) != std::tolower(static_cast<unsigned char>(b.reg[0]))) return;
        if (registerText(a) == registerText(b)) return;  // the same reservation twice is fine
        bool clash = !a.profile.empty() && a.profile == b.profile;
        for (const auto& e : entries_) clash |= appliesTo(a.profile, e.profile) && appliesTo(b.profile, e.profile);
        if (clash)
            report("register(" + b.reg + ") contradicts the earlier register(" + a.reg + ") for the same shader profile (fxc X3530)", b.regToken);
    }
    std::string registerText(const Reservation& r) const {
        std::string s;
        for (size_t k = r.regToken; k < t_.size() && !t_[k].is(")"); ++k) s += t_[k].text;
        return s;
    }

    // --- overlapping register(cN) in $Globals --------------------------------------------------
    struct Placed {
        const FxGlobal* global;
        long long first, count;  // 64-bit: sizes and register numbers come from the source
    };
    void overlappingConstants() {
        std::vector<Placed> placed;
        for (const auto& g : syntax_.globals) {
            if (!g.cbuffer.empty() || std::find(g.modifiers.begin(), g.modifiers.end(), "static") != g.modifiers.end()) continue;
            long long size = registersOf(g);
            if (size <= 0) continue;
            for (const auto& r : reservations(g.token)) {
                if (!r.profile.empty() || r.reg.size() < 2 || (r.reg[0] != 'c' && r.reg[0] != 'C')) continue;
                if (r.reg.find_first_not_of("0123456789", 1) != std::string::npos || tok(r.regToken + 1).is("[")) continue;
                placed.push_back({&g, std::min(std::strtoll(r.reg.c_str() + 1, nullptr, 10), kRegisterCap), size});
            }
        }
        for (size_t a = 0; a < placed.size(); ++a)
            for (size_t b = 0; b < a; ++b) {
                const Placed &x = placed[b], &y = placed[a];
                if (x.first >= y.first + y.count || y.first >= x.first + x.count) continue;
                for (const auto& e : entries_) {
                    auto functions = reachableFrom(*e.function);
                    bool xUsed = mentionedIn(functions, x.global->name), yUsed = mentionedIn(functions, y.global->name);
                    bool sm4 = e.profile.major >= 4;
                    bool arrays = !x.global->arrayDims.empty() || !y.global->arrayDims.empty();  // SM 2-3 counts used elements only
                    if (sm4 ? (xUsed || yUsed) : (xUsed && yUsed && !arrays)) {
                        report("'" + y.global->name + "' is reserved at c" + std::to_string(y.first) + ", which overlaps '" + x.global->name +
                                   "' (c" + std::to_string(x.first) + "): fxc refuses overlapping register reservations",
                               y.global->token);
                        return;
                    }
                }
            }
    }
    // c registers a number takes (columns of a column-major matrix, rows of a row-major one); 0
    // when unknown (a struct): not judged.
    // Capped (an array of 2^31 - 1 matrices is refused elsewhere; here it must not overflow).
    long long registersOf(const FxGlobal& g) const {
        BasicType b = describeBasicType(syntax_.resolveType(g.type));
        if (!b.ok) return 0;
        auto has = [&](const char* m) { return std::find(g.modifiers.begin(), g.modifiers.end(), m) != g.modifiers.end(); };
        // Without a modifier the majority may come from a pragma: the smaller count, so never too strict.
        long long count = !b.isMatrix ? 1 : has("row_major") ? b.rows : has("column_major") ? b.columns : std::min(b.rows, b.columns);
        for (int d : g.arrayDims) count = std::min(count * std::max(d, 1), kRegisterCap);
        return count;
    }
    static constexpr long long kRegisterCap = 1LL << 30;
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findRegisterReservationErrors(const EffectSyntax& syntax, const SourceMap& map) {
    RegisterReservations check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
