// vkd3d's qualifier arguments: `fail(sm>=2 & sm<4 | d3d12)`, `if(sm<4)`, `todo(glsl)` ...
// Shader models are numbers ten times the version (20, 30, 40, 41, 50, 51, 60, 62).
#pragma once

#include <string>

namespace conformance {

// "4.1" -> 41, "4" -> 40; -1 when it is no model vkd3d knows.
int parseShaderModel(const std::string& text);
std::string shaderModelName(int model);  // 40 -> "4.0"

// What a shader section's header qualifiers say at one model. As in vkd3d, only the `sm` terms pick
// the models of fail/todo/notimpl; backend tags (d3d12, glsl, msl ...) do not narrow them.
struct SectionExpectation {
    bool fail = false;     // fail(...): a conforming compiler rejects the section
    bool notImpl = false;  // notimpl(...): fxc returns E_NOTIMPL (also a rejection)
    bool todo = false;     // todo(...): vkd3d itself differs here; the reference still stands
    bool expectsReject() const { return fail || notImpl; }
};
SectionExpectation sectionExpectation(const std::string& qualifiers, int model);

// A [test] line's prefixes (`todo(...)`, `bug(...)`, `if(...)`), evaluated at `model` as a native
// D3D runner would: no vkd3d backend tag holds. `rest` is the directive after the prefixes.
struct TestLinePrefix {
    bool runs = true;  // false: an if(...) does not hold at this model
    bool todo = false;
    std::string rest;
};
TestLinePrefix parseTestLinePrefix(const std::string& line, int model);

}  // namespace conformance
