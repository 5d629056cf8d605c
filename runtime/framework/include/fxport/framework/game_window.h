// GameWindow: XNA's Game.Window. Its settable members are fields a game assigns at any time; the
// game hands them to the window at the next tick (and when the device is made). Headless there is
// no window: ClientBounds() is the back buffer, the fields only keep what was assigned.
#pragma once

#include <optional>
#include <string>

#include "fxport/math/rectangle.h"

namespace fxport {

class Game;

class GameWindow {
public:
    // The window's caption (XNA's default is the assembly name; fxport's is "fxport").
    std::string Title = "fxport";
    // XNA's default: the window keeps its size. A resized window shows the back buffer scaled into
    // it (fxport does not remake the back buffer: GraphicsDeviceManager.ApplyChanges does that).
    bool AllowUserResizing = false;

    // The client area: in a window its position on the desktop and size (screen units); headless
    // {0, 0, back buffer width, height}. Empty before the game has started.
    Rectangle ClientBounds() const;

private:
    friend class Game;
    explicit GameWindow(Game& game) : game_(&game) {}
    // Hands the fields that changed since the last call to the window (all of them the first time).
    void applyChanges();

    Game* game_;
    std::optional<std::string> appliedTitle_;
    std::optional<bool> appliedResizing_;
};

}  // namespace fxport
