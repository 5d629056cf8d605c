#include "gl_link_check.h"

#include <dlfcn.h>
#include <link.h>

#include <cctype>
#include <cstdio>
#include <memory>
#include <regex>

#include "fxport/platform/gl.h"

namespace fxport::test {
namespace {

GLenum glStage(GlslStageSource::Stage stage) {
    switch (stage) {
        case GlslStageSource::Vertex: return GL_VERTEX_SHADER;
        case GlslStageSource::Fragment: return GL_FRAGMENT_SHADER;
        case GlslStageSource::Geometry: return GL_GEOMETRY_SHADER;
    }
    return GL_NONE;
}

std::string shaderLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
    glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
    return log.c_str();  // drop the terminating zero(s)
}

std::string programLog(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
    glGetProgramInfoLog(program, static_cast<GLsizei>(log.size()), nullptr, log.data());
    return log.c_str();
}

// Links `shaders` into a new program; returns the program's info log if linking failed, else "".
// The program is deleted before returning (which detaches the shaders: it is not in use).
std::string link(const std::vector<GLuint>& shaders, bool separable) {
    GLuint program = glCreateProgram();
    if (separable) glProgramParameteri(program, GL_PROGRAM_SEPARABLE, GL_TRUE);
    for (GLuint shader : shaders) glAttachShader(program, shader);
    glLinkProgram(program);
    GLint linked = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    std::string log = linked ? "" : programLog(program);
    if (!linked && log.empty()) log = "(the driver gave no info log)";
    glDeleteProgram(program);
    return log;
}

bool isIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Where `word` occurs as a whole identifier in `text`; `afterDot` selects member accesses (x.word)
// or, when false, direct uses.
bool usesIdentifier(const std::string& text, const std::string& word, bool afterDot) {
    for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
        const std::size_t end = at + word.size();
        if ((at > 0 && isIdentifierChar(text[at - 1])) || (end < text.size() && isIdentifierChar(text[end]))) continue;
        std::size_t before = at;
        while (before > 0 && std::isspace(static_cast<unsigned char>(text[before - 1]))) --before;
        if ((before > 0 && text[before - 1] == '.') == afterDot) return true;
    }
    return false;
}

// NVIDIA's driver (seen with 580.159 on an H100) refuses separable programs of #version 410 and up
// whose vertex or geometry shader touches gl_Position, gl_PointSize, gl_ClipDistance or
// gl_CullDistance without redeclaring the gl_PerVertex block listing each of them (C7592/C7593);
// a geometry shader reading gl_in[] must redeclare the input block too. Mesa accepts all of this, so
// without this check a test on OSMesa passes shaders that fail on the GPU.
std::string perVertexPortabilityProblems(const GlslStageSource& stage) {
    if (stage.stage == GlslStageSource::Fragment) return "";
    static const std::regex comments(R"(//[^\n]*|/\*[\s\S]*?\*/)");
    std::string body = std::regex_replace(stage.source, comments, " ");
    std::smatch match;
    static const std::regex version(R"(#\s*version\s+(\d+))");
    if (!std::regex_search(body, match, version) || std::stoi(match[1]) < 410) return "";

    // Take the redeclared blocks out of the body, keeping their member lists.
    static const std::regex outBlock(R"(\bout\s+gl_PerVertex\s*\{([^}]*)\}\s*;)");
    static const std::regex inBlock(R"(\bin\s+gl_PerVertex\s*\{([^}]*)\}\s*gl_in\s*\[\s*\]\s*;)");
    std::string outMembers, inMembers;
    bool hasOut = false, hasIn = false;
    if (std::regex_search(body, match, outBlock)) {
        hasOut = true;
        outMembers = match[1];
        body = match.prefix().str() + " " + match.suffix().str();
    }
    if (std::regex_search(body, match, inBlock)) {
        hasIn = true;
        inMembers = match[1];
        body = match.prefix().str() + " " + match.suffix().str();
    }

    std::string problems;
    const std::string name = stageName(stage.stage);
    for (const char* member : {"gl_Position", "gl_PointSize", "gl_ClipDistance", "gl_CullDistance"}) {
        if (usesIdentifier(body, member, false) && !usesIdentifier(outMembers, member, false)) {
            problems += name + " shader: portability: uses " + member + (hasOut ? " but the" : " without an") +
                        " `out gl_PerVertex { ... };` redeclaration listing it; NVIDIA rejects this in separable "
                        "programs (C7592/C7593), Mesa does not\n";
        }
        if (stage.stage == GlslStageSource::Geometry && usesIdentifier(body, member, true) &&
            usesIdentifier(body, "gl_in", false) && !usesIdentifier(inMembers, member, false)) {
            problems += name + " shader: portability: reads gl_in[]." + member + (hasIn ? " but the" : " without an") +
                        " `in gl_PerVertex { ... } gl_in[];` redeclaration listing it; NVIDIA rejects this in "
                        "separable programs (C7592/C7593), Mesa does not\n";
        }
    }
    return problems;
}

}  // namespace

const char* stageName(GlslStageSource::Stage stage) {
    switch (stage) {
        case GlslStageSource::Vertex: return "vertex";
        case GlslStageSource::Fragment: return "fragment";
        case GlslStageSource::Geometry: return "geometry";
    }
    return "unknown";
}

std::string compileAndLinkSeparable(const std::vector<GlslStageSource>& stages) {
    std::string report;
    std::vector<GLuint> shaders;
    bool compiled = true;
    for (const GlslStageSource& stage : stages) {
        GLuint shader = glCreateShader(glStage(stage.stage));
        shaders.push_back(shader);
        const char* text = stage.source.c_str();
        glShaderSource(shader, 1, &text, nullptr);
        glCompileShader(shader);
        GLint ok = GL_FALSE;
        glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
        if (!ok) {
            compiled = false;
            report += std::string(stageName(stage.stage)) + " shader: compile failed:\n" + shaderLog(shader) + "\n";
        } else {
            report += perVertexPortabilityProblems(stage);
        }
    }
    if (compiled) {
        for (std::size_t i = 0; i < stages.size(); ++i) {
            std::string log = link({shaders[i]}, true);
            if (!log.empty()) {
                report += std::string(stageName(stages[i].stage)) + " shader: separable link failed:\n" + log + "\n";
            }
        }
        std::string names;
        for (const GlslStageSource& stage : stages) {
            if (!names.empty()) names += '+';
            names += stageName(stage.stage);
        }
        std::string log = link(shaders, false);
        if (!log.empty()) report += "program (" + names + "): link failed:\n" + log + "\n";
    }
    for (GLuint shader : shaders) glDeleteShader(shader);
    // An error here would be a bug in this function, not in the shader: say so rather than hide it.
    if (GLenum error = glGetError(); error != GL_NO_ERROR) {
        char hex[16];
        std::snprintf(hex, sizeof hex, "0x%04X", error);
        report += std::string("compileAndLinkSeparable: GL error ") + hex + " while checking\n";
    }
    return report;
}

#ifdef FXPORT_LSAN_SUPPRESSIONS
void keepGraphicsDriversMapped() {
    dl_iterate_phdr(
        [](dl_phdr_info* info, size_t, void*) {
            const std::string path = info->dlpi_name ? info->dlpi_name : "";
            // RTLD_NOLOAD: only a driver already loaded; RTLD_NODELETE: never unmapped after this.
            if (path.find("/dri/") != std::string::npos && path.ends_with("_dri.so"))
                dlopen(path.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
            return 0;
        },
        nullptr);
}
#else
void keepGraphicsDriversMapped() {}
#endif

#ifdef FXPORT_LSAN_SUPPRESSIONS
// LeakSanitizer's built-in defaults for every binary linking this library (FXPORT_SANITIZE builds):
// suppress Mesa's own leaks via lsan.supp. LSAN_OPTIONS in the environment still takes precedence.
extern "C" const char* __lsan_default_options() {
    return "suppressions=" FXPORT_LSAN_SUPPRESSIONS ":print_suppressions=0";
}
#endif

platform::GraphicsContext& sharedTestContext() {
    // Function-local static: its destructor is registered after the exit handlers Mesa registers
    // while the context is made, so it runs before them (Mesa's threads are still there).
    static std::unique_ptr<platform::GraphicsContext> context = platform::GraphicsContext::create({});
    context->makeCurrent();
    return *context;
}

}  // namespace fxport::test
