// INTERNAL, GL-free: the device's shadow of the fixed-function state a Backend has (sokol/FNA style):
// a state equal to what the backend was last given is not sent again. After invalidate() (and at
// first) the shadow is a guess, and every state is sent whole, until the draw that set them all
// calls settle(). Texture and sampler bindings (draw_state.cpp) follow the same unknown() flag.
#pragma once

#include <vector>

#include "device/backend.h"

namespace fxport {

class StateShadow {
public:
    explicit StateShadow(Backend& backend) : backend_(backend) {}

    // Something changed the backend's state behind the shadow (a raw measurement, a front end's
    // clear): the next draw sends everything.
    void invalidate() { unknown_ = true; }
    // A draw sent every state (flush's last step): from now on only differences are sent.
    void settle() { unknown_ = false; }
    bool unknown() const { return unknown_; }

    void setBlend(const BlendState& wanted);
    void setDepthStencil(const DepthStencilState& wanted);
    void setRasterizer(const RasterizerState& wanted);
    // Returns whether the viewport was sent (it changed, or the shadow is unknown). `more`: D3D10/11's
    // viewports 1.. (none for XNA); any change sends them all again, since viewport 0 resets them.
    bool setViewport(const Viewport& wanted, ViewportShift shift = {}, const std::vector<Viewport>& more = {});
    void setScissor(const Rectangle& wanted, const std::vector<Rectangle>& more = {});
    void setSrgbWrite(bool wanted);
    void setClipPlanes(int wanted);
    void setPointSize(float size, bool fromShader);
    // Sends blend, depth/stencil, rasterizer and scissor again, whole, as the shadow has them: after
    // a clear, which sets write masks and the scissor test for itself. Leaves unknown() as it is.
    void reapply();

    const BlendState& blend() const { return blend_; }
    const DepthStencilState& depthStencil() const { return depthStencil_; }
    const RasterizerState& rasterizer() const { return rasterizer_; }
    const Viewport& viewport() const { return viewport_; }
    const Rectangle& scissor() const { return scissor_; }

private:
    Backend& backend_;
    bool unknown_ = true;
    BlendState blend_;
    DepthStencilState depthStencil_;
    RasterizerState rasterizer_;
    Viewport viewport_;
    ViewportShift viewportShift_;
    std::vector<Viewport> moreViewports_;
    Rectangle scissor_;
    std::vector<Rectangle> moreScissors_;
    bool srgbWrite_ = false;
    int clipPlanes_ = 0;
    float pointSize_ = 1;
    bool pointSizeFromShader_ = false;
};

}  // namespace fxport
