// The platform layer: contexts report what they are, GLSL compile/link checking works and cleans up,
// and every failure comes with a message that says what to do.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>

#include "fxport/platform/gl.h"
#include "fxport/platform/graphics_context.h"
#include "gl_link_check.h"

namespace fxport::test {
namespace {

using platform::ContextDesc;
using platform::GraphicsContext;
using platform::Platform;

// Portable separable shaders redeclare gl_PerVertex (NVIDIA requires it; see gl_link_check.h).
const char* const kVertexShader = R"(#version 450
out gl_PerVertex { vec4 gl_Position; };
layout(location = 0) in vec3 position;
layout(location = 0) out vec2 uv;
void main() {
    uv = position.xy * 0.5 + 0.5;
    gl_Position = vec4(position, 1.0);
}
)";

const char* const kFragmentShader = R"(#version 450
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
layout(binding = 0) uniform sampler2D image;
void main() { color = texture(image, uv); }
)";

const char* const kGeometryShader = R"(#version 450
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in gl_PerVertex { vec4 gl_Position; } gl_in[];
out gl_PerVertex { vec4 gl_Position; };
layout(location = 0) in vec2 uvIn[];
layout(location = 0) out vec2 uv;
void main() {
    for (int i = 0; i < 3; ++i) {
        uv = uvIn[i];
        gl_Position = gl_in[i].gl_Position;
        EmitVertex();
    }
}
)";

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

struct GLVersion {
    GLint major = 0, minor = 0, profileMask = 0;
};
GLVersion currentVersion() {
    GLVersion v;
    glGetIntegerv(GL_MAJOR_VERSION, &v.major);
    glGetIntegerv(GL_MINOR_VERSION, &v.minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &v.profileMask);
    return v;
}

// Runs `f` and returns the message of the std::runtime_error it throws (fails the test if none).
template <typename F>
std::string runtimeErrorOf(F f) {
    try {
        f();
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    ADD_FAILURE() << "expected a std::runtime_error";
    return "";
}

// Sets an environment variable for one scope and restores it afterwards.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        setenv(name, value, 1);
    }
    ~ScopedEnv() {
        if (old_) setenv(name_, old_->c_str(), 1);
        else unsetenv(name_);
    }

private:
    const char* name_;
    std::optional<std::string> old_;
};

TEST(GlContext, OSMesaGivesOpenGL45Core) {
    ContextDesc desc;
    desc.width = 32;
    desc.height = 16;
    auto context = GraphicsContext::create(desc);
    EXPECT_EQ(context->platform(), Platform::OSMesa);
    EXPECT_EQ(context->width(), 32);
    EXPECT_EQ(context->height(), 16);
    const GLVersion v = currentVersion();
    EXPECT_GE(v.major * 10 + v.minor, 45) << "got OpenGL " << v.major << "." << v.minor;
    EXPECT_NE(v.profileMask & GL_CONTEXT_CORE_PROFILE_BIT, 0) << "not a core profile";
    EXPECT_TRUE(contains(context->rendererName(), " / ")) << context->rendererName();
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    std::printf("OSMesa: %s (GL_MAJOR/MINOR_VERSION %d.%d)\n", context->rendererName().c_str(), v.major, v.minor);
}

TEST(GlContext, DefaultFramebufferHoldsWhatWasCleared) {
    sharedTestContext();
    glClearColor(1.0f, 0.5f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    unsigned char pixel[4] = {};
    glReadPixels(3, 5, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
    EXPECT_EQ(pixel[0], 255);
    EXPECT_NEAR(pixel[1], 128, 1);
    EXPECT_EQ(pixel[2], 0);
    EXPECT_EQ(pixel[3], 255);
}

TEST(GlLinkCheck, TrivialVertexAndFragmentShaderLink) {
    sharedTestContext();
    EXPECT_EQ(compileAndLinkSeparable({{GlslStageSource::Vertex, kVertexShader},
                                       {GlslStageSource::Fragment, kFragmentShader}}),
              "");
}

TEST(GlLinkCheck, GeometryStageLinks) {
    sharedTestContext();
    EXPECT_EQ(compileAndLinkSeparable({{GlslStageSource::Vertex, kVertexShader},
                                       {GlslStageSource::Geometry, kGeometryShader},
                                       {GlslStageSource::Fragment, kFragmentShader}}),
              "");
}

TEST(GlLinkCheck, BrokenFragmentShaderReportsTheFragmentStage) {
    sharedTestContext();
    const std::string log = compileAndLinkSeparable(
        {{GlslStageSource::Vertex, kVertexShader},
         {GlslStageSource::Fragment, "#version 450\nout vec4 color;\nvoid main() { color = undefinedThing; }\n"}});
    EXPECT_TRUE(contains(log, "fragment shader: compile failed")) << log;
    EXPECT_TRUE(contains(log, "undefinedThing")) << "the driver's own log should follow:\n" << log;
    EXPECT_FALSE(contains(log, "vertex shader")) << log;
}

// Separable programs link stage by stage, so only the combined link sees a vec2/vec4 mismatch.
TEST(GlLinkCheck, InterfaceMismatchIsCaughtByTheCombinedLink) {
    sharedTestContext();
    const std::string log = compileAndLinkSeparable(
        {{GlslStageSource::Vertex, "#version 450\nout gl_PerVertex { vec4 gl_Position; };\nout vec2 v;\n"
                                   "void main() { v = vec2(0); gl_Position = vec4(0); }\n"},
         {GlslStageSource::Fragment, "#version 450\nin vec4 v;\nout vec4 c;\nvoid main() { c = v; }\n"}});
    EXPECT_TRUE(contains(log, "program (vertex+fragment): link failed")) << log;
    EXPECT_FALSE(contains(log, "separable link failed")) << log;
}

// Mesa links these; NVIDIA's driver does not (C7592/C7593), so the check reports them on OSMesa too.
TEST(GlLinkCheck, BuiltinsWithoutPerVertexRedeclarationAreReported) {
    sharedTestContext();
    const char* plainVertex = "#version 450\nvoid main() { gl_Position = vec4(0); }\n";
    const std::string vertexLog = compileAndLinkSeparable({{GlslStageSource::Vertex, plainVertex}});
    EXPECT_TRUE(contains(vertexLog, "vertex shader: portability: uses gl_Position without an `out gl_PerVertex"))
        << vertexLog;

    const char* pointSizeMissing =
        "#version 450\nout gl_PerVertex { vec4 gl_Position; };\n"
        "void main() { gl_Position = vec4(0); gl_PointSize = 1.0; }\n";
    // Mesa rejects this one itself (gl_PointSize is not in the redeclared block): a compile error.
    EXPECT_TRUE(contains(compileAndLinkSeparable({{GlslStageSource::Vertex, pointSizeMissing}}), "vertex shader"));

    const char* geometryWithoutInputBlock = R"(#version 450
layout(points) in;
layout(points, max_vertices = 1) out;
out gl_PerVertex { vec4 gl_Position; };
void main() { gl_Position = gl_in[0].gl_Position; EmitVertex(); }
)";
    const std::string geometryLog = compileAndLinkSeparable(
        {{GlslStageSource::Vertex, kVertexShader}, {GlslStageSource::Geometry, geometryWithoutInputBlock}});
    EXPECT_TRUE(contains(geometryLog, "geometry shader: portability: reads gl_in[].gl_Position")) << geometryLog;
    EXPECT_FALSE(contains(geometryLog, "vertex shader")) << geometryLog;

    // Before 4.10 NVIDIA accepts the implicit block, and so does the check.
    const char* glsl330 = "#version 330\nvoid main() { gl_Position = vec4(0); }\n";
    EXPECT_EQ(compileAndLinkSeparable({{GlslStageSource::Vertex, glsl330}}), "");
}

// GL has no count of live objects to read, so: note the next free program name, run the check, then
// ask whether any name from there on is still a shader or program. glIsShader stays true for a shader
// flagged for deletion while a live program holds it, so a leaked program shows up twice. This relies
// on names being handed out at or above a just-freed name (lowest free, or increasing), as Mesa does;
// the last assertion checks that the window really covers freshly made names.
TEST(GlLinkCheck, LeavesNoShaderOrProgramAlive) {
    sharedTestContext();
    const GLuint first = glCreateProgram();
    glDeleteProgram(first);
    for (int round = 0; round < 2; ++round) {  // a passing and a failing check
        compileAndLinkSeparable({{GlslStageSource::Vertex, kVertexShader},
                                 {GlslStageSource::Geometry, kGeometryShader},
                                 {GlslStageSource::Fragment, round == 0 ? kFragmentShader : "#version 450\nbroken"}});
    }
    constexpr GLuint kWindow = 64;  // far more than the 7 objects one call makes
    for (GLuint name = first; name < first + kWindow; ++name) {
        EXPECT_FALSE(glIsShader(name)) << "shader " << name << " is still alive";
        EXPECT_FALSE(glIsProgram(name)) << "program " << name << " is still alive";
    }
    const GLuint next = glCreateProgram();
    EXPECT_GE(next, first);
    EXPECT_LT(next, first + kWindow);
    glDeleteProgram(next);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(Platform, NamesRoundTrip) {
    for (Platform p : {Platform::OSMesa, Platform::EGL, Platform::GLFW}) {
        EXPECT_EQ(platform::platformFromString(platform::platformName(p)), p);
    }
    EXPECT_EQ(platform::platformFromString("EGL"), Platform::EGL);
    const auto available = platform::availablePlatforms();
    EXPECT_NE(std::find(available.begin(), available.end(), Platform::OSMesa), available.end());
}

TEST(Platform, UnknownNameListsTheValidOnes) {
    const std::string message = runtimeErrorOf([] { platform::platformFromString("vulkan"); });
    EXPECT_TRUE(contains(message, "'vulkan'")) << message;
    EXPECT_TRUE(contains(message, "osmesa, egl, glfw")) << message;
}

TEST(Platform, DefaultPlatformReadsFxportPlatform) {
    {
        ScopedEnv env("FXPORT_PLATFORM", "");
        EXPECT_EQ(platform::defaultPlatform(), Platform::OSMesa);
    }
    {
        ScopedEnv env("FXPORT_PLATFORM", "egl");
        EXPECT_EQ(platform::defaultPlatform(), Platform::EGL);
    }
    {
        ScopedEnv env("FXPORT_PLATFORM", "metal");
        const std::string message = runtimeErrorOf([] { platform::defaultPlatform(); });
        EXPECT_TRUE(contains(message, "FXPORT_PLATFORM")) << message;
        EXPECT_TRUE(contains(message, "'metal'")) << message;
    }
}

// A platform missing from the build must be named in the error with the ones that exist. In a full
// build every platform exists, and then the list itself is what we can check.
TEST(Platform, PlatformNotBuiltInNamesItAndTheAvailableOnes) {
    const auto available = platform::availablePlatforms();
    ASSERT_FALSE(available.empty());
    EXPECT_EQ(available.front(), Platform::OSMesa);  // OSMesa is never optional
    for (Platform p : {Platform::EGL, Platform::GLFW}) {
        if (std::find(available.begin(), available.end(), p) != available.end()) continue;
        ContextDesc desc;
        desc.platform = p;
        const std::string message = runtimeErrorOf([&] { GraphicsContext::create(desc); });
        EXPECT_TRUE(contains(message, std::string("'") + platform::platformName(p) + "'")) << message;
        EXPECT_TRUE(contains(message, "available: osmesa")) << message;
    }
}

// A context that cannot be made carries the platform's own error. Without a display, GLFW is such
// a case on any machine.
TEST(Platform, GlfwWithoutDisplayGivesGlfwError) {
    const auto available = platform::availablePlatforms();
    if (std::find(available.begin(), available.end(), Platform::GLFW) == available.end()) return;  // covered above
    if (std::getenv("DISPLAY") != nullptr || std::getenv("WAYLAND_DISPLAY") != nullptr) {
        ContextDesc desc;  // with a display the window must open instead
        desc.platform = Platform::GLFW;
        EXPECT_NO_THROW(GraphicsContext::create(desc));
        return;
    }
    ContextDesc desc;
    desc.platform = Platform::GLFW;
    const std::string message = runtimeErrorOf([&] { GraphicsContext::create(desc); });
    EXPECT_TRUE(contains(message, "glfw:")) << message;
    EXPECT_TRUE(contains(message, "DISPLAY")) << message;
}

// EGL succeeds where there is a GPU, or Mesa's software device; otherwise it must say why.
TEST(Platform, EglGivesOpenGL45CoreOrSaysWhy) {
    const auto available = platform::availablePlatforms();
    if (std::find(available.begin(), available.end(), Platform::EGL) == available.end()) return;  // covered above
    ContextDesc desc;
    desc.platform = Platform::EGL;
    std::unique_ptr<GraphicsContext> context;
    try {
        context = GraphicsContext::create(desc);
    } catch (const std::runtime_error& e) {
        EXPECT_TRUE(contains(e.what(), "egl:")) << e.what();  // no device here: the error must say so
        return;
    }
    keepGraphicsDriversMapped();
    const GLVersion v = currentVersion();
    EXPECT_GE(v.major * 10 + v.minor, 45);
    EXPECT_NE(v.profileMask & GL_CONTEXT_CORE_PROFILE_BIT, 0);
    EXPECT_EQ(compileAndLinkSeparable({{GlslStageSource::Vertex, kVertexShader},
                                       {GlslStageSource::Fragment, kFragmentShader}}),
              "");
    std::printf("EGL: %s\n", context->rendererName().c_str());
}

// GL function pointers are process-wide; switching between an OSMesa and an EGL context must reach
// the right context each time (each keeps its own clear colour in its own default framebuffer).
TEST(Platform, SwitchingBetweenOSMesaAndEglReachesTheRightContext) {
    const auto available = platform::availablePlatforms();
    if (std::find(available.begin(), available.end(), Platform::EGL) == available.end()) return;  // covered above
    ContextDesc desc;
    desc.platform = Platform::EGL;
    std::unique_ptr<GraphicsContext> egl;
    try {
        egl = GraphicsContext::create(desc);
    } catch (const std::runtime_error& e) {
        EXPECT_TRUE(contains(e.what(), "egl:")) << e.what();  // no device here: the error must say so
        return;
    }
    keepGraphicsDriversMapped();
    auto red = [](GraphicsContext& context) {
        context.makeCurrent();
        unsigned char pixel[4] = {};
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
        return int(pixel[0]);
    };
    egl->makeCurrent();
    glClearColor(0.2f, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    GraphicsContext& osmesa = sharedTestContext();
    glClearColor(0.8f, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    for (int round = 0; round < 2; ++round) {
        EXPECT_NEAR(red(*egl), 51, 1);
        EXPECT_NEAR(red(osmesa), 204, 1);
    }
    egl.reset();  // destroying the non-current context leaves the current one working
    EXPECT_NEAR(red(sharedTestContext()), 204, 1);
}

}  // namespace
}  // namespace fxport::test
