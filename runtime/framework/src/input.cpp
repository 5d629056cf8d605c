#include "fxport/framework/input.h"

#include "fxport/graphics/errors.h"
#include "fxport/graphics/graphics_device.h"
#include "fxport/platform/graphics_context.h"

namespace fxport {

KeyboardState Keyboard::GetState() {
    GraphicsDevice* device = GraphicsDevice::current();
    if (!device) throw InvalidOperation("Keyboard::GetState: no GraphicsDevice exists");
    KeyboardState state;
    for (int key = 1; key < 256; ++key)
        if (device->context().isKeyDown(key)) state.down_.set(std::size_t(key));
    return state;
}

std::vector<Keys> KeyboardState::GetPressedKeys() const {
    std::vector<Keys> keys;
    for (std::size_t k = 1; k < down_.size(); ++k)
        if (down_[k]) keys.push_back(Keys(k));
    return keys;
}

MouseState Mouse::GetState() {
    GraphicsDevice* device = GraphicsDevice::current();
    if (!device) throw InvalidOperation("Mouse::GetState: no GraphicsDevice exists");
    platform::MouseInput m = device->context().mouse();
    MouseState s;
    s.X = m.x;
    s.Y = m.y;
    s.ScrollWheelValue = m.scrollWheel;
    s.LeftButton = m.left ? ButtonState::Pressed : ButtonState::Released;
    s.RightButton = m.right ? ButtonState::Pressed : ButtonState::Released;
    s.MiddleButton = m.middle ? ButtonState::Pressed : ButtonState::Released;
    return s;
}

void Mouse::SetPosition(int x, int y) {
    GraphicsDevice* device = GraphicsDevice::current();
    if (!device) throw InvalidOperation("Mouse::SetPosition: no GraphicsDevice exists");
    device->context().setMousePosition(x, y);
}

}  // namespace fxport
