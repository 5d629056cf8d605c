// The fixed-function state shadow (state_shadow.h): one comparison per state, then the backend.
#include "device/state_shadow.h"

namespace fxport {

void StateShadow::setBlend(const BlendState& wanted) {
    if (!unknown_ && wanted == blend_) return;
    backend_.setBlend(wanted, unknown_ ? nullptr : &blend_);
    blend_ = wanted;
}

void StateShadow::setDepthStencil(const DepthStencilState& wanted) {
    if (!unknown_ && wanted == depthStencil_) return;
    backend_.setDepthStencil(wanted, unknown_ ? nullptr : &depthStencil_);
    depthStencil_ = wanted;
}

void StateShadow::setRasterizer(const RasterizerState& wanted) {
    if (!unknown_ && wanted == rasterizer_) return;
    backend_.setRasterizer(wanted, unknown_ ? nullptr : &rasterizer_);
    rasterizer_ = wanted;
}

bool StateShadow::setViewport(const Viewport& wanted, ViewportShift shift, const std::vector<Viewport>& more) {
    if (!unknown_ && wanted == viewport_ && shift == viewportShift_ && more == moreViewports_) return false;
    backend_.setViewport(wanted, shift);
    if (!more.empty()) backend_.setMoreViewports(more, shift);
    viewport_ = wanted;
    viewportShift_ = shift;
    moreViewports_ = more;
    return true;
}

void StateShadow::setScissor(const Rectangle& wanted, const std::vector<Rectangle>& more) {
    if (!unknown_ && wanted == scissor_ && more == moreScissors_) return;
    backend_.setScissor(wanted);
    if (!more.empty()) backend_.setMoreScissors(more);
    scissor_ = wanted;
    moreScissors_ = more;
}

void StateShadow::setSrgbWrite(bool wanted) {
    if (!unknown_ && wanted == srgbWrite_) return;
    backend_.setSrgbWrite(wanted);
    srgbWrite_ = wanted;
}

void StateShadow::setClipPlanes(int wanted) {
    if (!unknown_ && wanted == clipPlanes_) return;
    backend_.setClipPlanes(wanted);
    clipPlanes_ = wanted;
}

void StateShadow::setPointSize(float size, bool fromShader) {
    if (!unknown_ && size == pointSize_ && fromShader == pointSizeFromShader_) return;
    backend_.setPointSize(size, fromShader);
    pointSize_ = size;
    pointSizeFromShader_ = fromShader;
}

void StateShadow::reapply() {
    backend_.setBlend(blend_, nullptr);
    backend_.setDepthStencil(depthStencil_, nullptr);
    backend_.setRasterizer(rasterizer_, nullptr);
    backend_.setScissor(scissor_);
    if (!moreScissors_.empty()) backend_.setMoreScissors(moreScissors_);
}

}  // namespace fxport
