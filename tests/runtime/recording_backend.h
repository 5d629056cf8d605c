// A Backend (runtime/graphics/src/device/backend.h) that does nothing but write down each call, one
// line each ("setBlend whole", "bindTexture 3 7"), for tests of the device core's semantics with no
// GL context (in the manner of bgfx's renderer_noop.cpp).
#pragma once

#include <string>
#include <vector>

#include "device/backend.h"

namespace fxport::test {

class RecordingBackend final : public Backend {
public:
    std::vector<std::string> calls;
    // The states of the last set* calls, to check what was sent.
    BlendState blend;
    DepthStencilState depthStencil;
    RasterizerState rasterizer;
    Viewport viewport;
    Rectangle scissor;
    BlendState hadBlend;  // what the last "changed" setBlend said the backend had
    BackendObject nextSampler = 1;
    BackendObject nextObject = 100;  // pipelines and vertex arrays

    void setBlend(const BlendState& state, const BlendState* had) override {
        note("setBlend", had);
        if (had) hadBlend = *had;
        blend = state;
    }
    void setDepthStencil(const DepthStencilState& state, const DepthStencilState* had) override {
        note("setDepthStencil", had);
        depthStencil = state;
    }
    void setRasterizer(const RasterizerState& state, const RasterizerState* had) override {
        note("setRasterizer", had);
        rasterizer = state;
    }
    void setViewport(const Viewport& v) override {
        calls.push_back("setViewport " + std::to_string(v.Width) + "x" + std::to_string(v.Height));
        viewport = v;
    }
    void setScissor(const Rectangle& r) override {
        calls.push_back("setScissor " + std::to_string(r.Width) + "x" + std::to_string(r.Height));
        scissor = r;
    }
    void setSrgbWrite(bool enabled) override { calls.push_back(std::string("setSrgbWrite ") + (enabled ? "on" : "off")); }
    BackendObject createSampler(const SamplerState&) override {
        calls.push_back("createSampler " + std::to_string(nextSampler));
        return nextSampler++;
    }
    void deleteSampler(BackendObject sampler) override { calls.push_back("deleteSampler " + std::to_string(sampler)); }
    void bindTexture(int unit, BackendObject texture) override {
        calls.push_back("bindTexture " + std::to_string(unit) + " " + std::to_string(texture));
    }
    void bindSampler(int unit, BackendObject sampler) override {
        calls.push_back("bindSampler " + std::to_string(unit) + " " + std::to_string(sampler));
    }
    void writeBuffer(BackendObject buffer, std::size_t offset, std::size_t bytes, const void*) override {
        calls.push_back("writeBuffer " + std::to_string(buffer) + " " + std::to_string(offset) + " " + std::to_string(bytes));
    }
    void bindUniformBuffer(int binding, BackendObject buffer) override {
        calls.push_back("bindUniformBuffer " + std::to_string(binding) + " " + std::to_string(buffer));
    }
    int uniformLocation(BackendObject, const char* name) override {
        calls.push_back(std::string("uniformLocation ") + name);
        return 0;
    }
    void setUniform(BackendObject, int location, int value) override {
        calls.push_back("setUniform " + std::to_string(location) + " " + std::to_string(value));
    }
    void setUniform(BackendObject, int location, float value) override {
        calls.push_back("setUniform " + std::to_string(location) + " " + std::to_string(value));
    }
    BackendObject createPipeline(const std::array<BackendObject, 5>&) override {
        calls.push_back("createPipeline " + std::to_string(nextObject));
        return nextObject++;
    }
    void bindPipeline(BackendObject pipeline) override { calls.push_back("bindPipeline " + std::to_string(pipeline)); }
    BackendObject createVertexArray(const std::vector<VertexAttribute>& attributes) override {
        calls.push_back("createVertexArray " + std::to_string(attributes.size()) + " attributes");
        return nextObject++;
    }
    void bindVertexArray(BackendObject vertexArray) override {
        calls.push_back("bindVertexArray " + std::to_string(vertexArray));
    }

    // The calls so far, and forgets them.
    std::vector<std::string> take() {
        std::vector<std::string> taken;
        taken.swap(calls);
        return taken;
    }

private:
    // "whole": every field to be set (the shadow did not know); "changed": only what differs from `had`.
    template <typename State>
    void note(const char* what, const State* had) {
        calls.push_back(std::string(what) + (had ? " changed" : " whole"));
    }
};

}  // namespace fxport::test
