// GameWindow: ClientBounds and handing Title / AllowUserResizing to the platform's window.
#include "fxport/framework/game_window.h"

#include "fxport/framework/game.h"
#include "fxport/graphics/graphics_device.h"
#include "fxport/platform/graphics_context.h"

namespace fxport {

Rectangle GameWindow::ClientBounds() const {
    fxport::GraphicsDevice* device = game_->GraphicsDevice;
    if (!device) return Rectangle::Empty;
    platform::GraphicsContext& context = device->context();
    if (context.platform() != platform::Platform::GLFW) {
        // Headless the back buffer is all there is (the context's own buffer keeps its first size).
        const PresentationParameters& p = device->PresentationParameters();
        return Rectangle(0, 0, p.BackBufferWidth, p.BackBufferHeight);
    }
    const platform::WindowBounds b = context.clientBounds();
    return Rectangle(b.x, b.y, b.width, b.height);
}

void GameWindow::applyChanges() {
    fxport::GraphicsDevice* device = game_->GraphicsDevice;
    if (!device) return;
    // Only on change: a title set every frame must not cost a window-system call every frame.
    if (appliedTitle_ != Title) {
        device->context().setTitle(Title);
        appliedTitle_ = Title;
    }
    if (appliedResizing_ != AllowUserResizing) {
        device->context().setResizable(AllowUserResizing);
        appliedResizing_ = AllowUserResizing;
    }
}

}  // namespace fxport
