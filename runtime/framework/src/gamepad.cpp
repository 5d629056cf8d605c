// XNA's GamePad over the platform's gamepads (GLFW's standard mapping), with XNA's default dead
// zone and its button rules; headless, the state a program scripted (or none connected).
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "fxport/graphics/errors.h"
#include "fxport/graphics/graphics_device.h"
#include "fxport/framework/input.h"
#include "fxport/platform/graphics_context.h"

namespace fxport {
namespace {

std::array<std::optional<GamePadState>, 4>& headlessStates() {
    static std::array<std::optional<GamePadState>, 4> states;
    return states;
}

int checkedIndex(PlayerIndex playerIndex, const char* who) {
    const int i = int(playerIndex);
    if (i < 0 || i > 3) throw ArgumentError(std::string(who) + ": PlayerIndex " + std::to_string(i) + " is not One..Four");
    return i;
}

// XNA's GamePadDeadZone.IndependentAxes: each axis within 0.24 of rest is 0, the rest rescaled to [0, 1].
float deadZone(float v) {
    constexpr float kZone = 0.24f;
    const float a = std::fabs(v);
    if (a <= kZone) return 0;
    return std::copysign(std::min(1.0f, (a - kZone) / (1 - kZone)), v);
}

ButtonState pressed(bool down) { return down ? ButtonState::Pressed : ButtonState::Released; }

GamePadState fromPlatform(const platform::GamepadInput& g) {
    GamePadState s;
    s.IsConnected = true;
    enum { A, B, X, Y, LB, RB, Back, Start, Guide, LThumb, RThumb, Up, Right, Down, Left };
    s.Buttons.A = pressed(g.buttons[A]);
    s.Buttons.B = pressed(g.buttons[B]);
    s.Buttons.X = pressed(g.buttons[X]);
    s.Buttons.Y = pressed(g.buttons[Y]);
    s.Buttons.LeftShoulder = pressed(g.buttons[LB]);
    s.Buttons.RightShoulder = pressed(g.buttons[RB]);
    s.Buttons.Back = pressed(g.buttons[Back]);
    s.Buttons.Start = pressed(g.buttons[Start]);
    s.Buttons.BigButton = pressed(g.buttons[Guide]);
    s.Buttons.LeftStick = pressed(g.buttons[LThumb]);
    s.Buttons.RightStick = pressed(g.buttons[RThumb]);
    s.DPad.Up = pressed(g.buttons[Up]);
    s.DPad.Right = pressed(g.buttons[Right]);
    s.DPad.Down = pressed(g.buttons[Down]);
    s.DPad.Left = pressed(g.buttons[Left]);
    // GLFW's y axes point down; XNA's thumbsticks point up. Triggers: GLFW -1..1, XNA 0..1.
    s.ThumbSticks.Left = Vector2(deadZone(g.axes[0]), -deadZone(g.axes[1]));
    s.ThumbSticks.Right = Vector2(deadZone(g.axes[2]), -deadZone(g.axes[3]));
    s.Triggers.Left = std::clamp((g.axes[4] + 1) / 2, 0.0f, 1.0f);
    s.Triggers.Right = std::clamp((g.axes[5] + 1) / 2, 0.0f, 1.0f);
    return s;
}

bool down(ButtonState b) { return b == ButtonState::Pressed; }

}  // namespace

bool GamePadState::IsButtonDown(fxport::Buttons buttons) const {
    const std::uint32_t want = std::uint32_t(buttons);
    constexpr float kThreshold = 0.5f;  // XNA's trigger and thumbstick-direction threshold
    const std::pair<fxport::Buttons, bool> all[] = {
        {fxport::Buttons::DPadUp, down(DPad.Up)}, {fxport::Buttons::DPadDown, down(DPad.Down)},
        {fxport::Buttons::DPadLeft, down(DPad.Left)}, {fxport::Buttons::DPadRight, down(DPad.Right)},
        {fxport::Buttons::Start, down(Buttons.Start)}, {fxport::Buttons::Back, down(Buttons.Back)},
        {fxport::Buttons::LeftStick, down(Buttons.LeftStick)}, {fxport::Buttons::RightStick, down(Buttons.RightStick)},
        {fxport::Buttons::LeftShoulder, down(Buttons.LeftShoulder)}, {fxport::Buttons::RightShoulder, down(Buttons.RightShoulder)},
        {fxport::Buttons::BigButton, down(Buttons.BigButton)}, {fxport::Buttons::A, down(Buttons.A)},
        {fxport::Buttons::B, down(Buttons.B)}, {fxport::Buttons::X, down(Buttons.X)}, {fxport::Buttons::Y, down(Buttons.Y)},
        {fxport::Buttons::LeftTrigger, Triggers.Left > kThreshold}, {fxport::Buttons::RightTrigger, Triggers.Right > kThreshold},
        {fxport::Buttons::LeftThumbstickLeft, ThumbSticks.Left.X < -kThreshold},
        {fxport::Buttons::LeftThumbstickRight, ThumbSticks.Left.X > kThreshold},
        {fxport::Buttons::LeftThumbstickUp, ThumbSticks.Left.Y > kThreshold},
        {fxport::Buttons::LeftThumbstickDown, ThumbSticks.Left.Y < -kThreshold},
        {fxport::Buttons::RightThumbstickLeft, ThumbSticks.Right.X < -kThreshold},
        {fxport::Buttons::RightThumbstickRight, ThumbSticks.Right.X > kThreshold},
        {fxport::Buttons::RightThumbstickUp, ThumbSticks.Right.Y > kThreshold},
        {fxport::Buttons::RightThumbstickDown, ThumbSticks.Right.Y < -kThreshold},
    };
    std::uint32_t held = 0;
    for (const auto& [flag, isDown] : all)
        if (isDown) held |= std::uint32_t(flag);
    return want != 0 && (held & want) == want;
}

GamePadState GamePad::GetState(PlayerIndex playerIndex) {
    const int i = checkedIndex(playerIndex, "GamePad::GetState");
    if (const auto& scripted = headlessStates()[std::size_t(i)]) return *scripted;
    GraphicsDevice* device = GraphicsDevice::current();
    if (!device) throw InvalidOperation("GamePad::GetState: no GraphicsDevice exists");
    const platform::GamepadInput g = device->context().gamepad(i);
    if (!g.connected) return {};
    static int packet = 0;
    GamePadState s = fromPlatform(g);
    s.PacketNumber = ++packet;
    return s;
}

bool GamePad::SetVibration(PlayerIndex playerIndex, float, float) {
    checkedIndex(playerIndex, "GamePad::SetVibration");
    return false;
}

void GamePad::SetHeadlessState(PlayerIndex playerIndex, const GamePadState* state) {
    auto& slot = headlessStates()[std::size_t(checkedIndex(playerIndex, "GamePad::SetHeadlessState"))];
    if (state) slot = *state;
    else slot.reset();
}

}  // namespace fxport
