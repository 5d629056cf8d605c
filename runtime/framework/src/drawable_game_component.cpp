// DrawableGameComponent: its device, and LoadContent at most once.
#include "fxport/framework/drawable_game_component.h"

#include "fxport/framework/game.h"

namespace fxport {

fxport::GraphicsDevice* DrawableGameComponent::GraphicsDevice() const { return Game() ? Game()->GraphicsDevice : nullptr; }

void DrawableGameComponent::Initialize() {
    GameComponent::Initialize();
    // XNA's DrawableGameComponent loads once even if Initialize runs again, and only with a device.
    if (contentLoaded_ || !GraphicsDevice()) return;
    contentLoaded_ = true;
    LoadContent();
}

}  // namespace fxport
