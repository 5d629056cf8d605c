// XNA's Keyboard, Mouse and GamePad (runtime/framework/src/input.cpp, gamepad.cpp), headless.
#include <gtest/gtest.h>

#include "fxport/framework.h"

namespace fxport {
namespace {

// Input reads the current device's window; headless it is OSMesa's, with no keyboard or pad.
GraphicsDevice& device() {
    static GraphicsDevice d(PresentationParameters{});
    return d;
}

// Headless platforms have no keyboard or mouse: everything reads as up, so ported Update() code runs.
TEST(Input, HeadlessKeyboardAndMouseAreIdle) {
    device();
    KeyboardState k = Keyboard::GetState();
    EXPECT_TRUE(k.IsKeyUp(Keys::Z));
    EXPECT_FALSE(k.IsKeyDown(Keys::F1));
    MouseState m = Mouse::GetState();
    EXPECT_EQ(m.LeftButton, ButtonState::Released);
    EXPECT_TRUE(k.GetPressedKeys().empty());
    EXPECT_EQ(k[Keys::OemTilde], KeyState::Up);
    // XNA's key codes are Windows virtual keys, all of them.
    EXPECT_EQ(int(Keys::Home), 36);
    EXPECT_EQ(int(Keys::OemTilde), 192);
    EXPECT_EQ(int(Keys::F24), 135);
}

TEST(Input, HeadlessGamePadIsDisconnectedUnlessScripted) {
    device();
    EXPECT_FALSE(GamePad::GetState(PlayerIndex::One).IsConnected);
    EXPECT_FALSE(GamePad::SetVibration(PlayerIndex::Two, 1, 1));
    EXPECT_THROW(GamePad::GetState(PlayerIndex(7)), ArgumentError);

    GamePadState scripted;
    scripted.IsConnected = true;
    scripted.Buttons.A = ButtonState::Pressed;
    scripted.DPad.Left = ButtonState::Pressed;
    scripted.Triggers.Right = 0.7f;
    scripted.Triggers.Left = 0.3f;
    scripted.ThumbSticks.Left = Vector2(-0.8f, 0.2f);
    GamePad::SetHeadlessState(PlayerIndex::Two, &scripted);
    const GamePadState pad = GamePad::GetState(PlayerIndex::Two);
    EXPECT_TRUE(pad.IsConnected);
    EXPECT_FALSE(GamePad::GetState(PlayerIndex::One).IsConnected);
    EXPECT_TRUE(pad.IsButtonDown(Buttons::A));
    EXPECT_TRUE(pad.IsButtonDown(Buttons::A | Buttons::DPadLeft));   // every flag held
    EXPECT_FALSE(pad.IsButtonDown(Buttons::A | Buttons::B));
    EXPECT_TRUE(pad.IsButtonDown(Buttons::RightTrigger));             // past XNA's 0.5 threshold
    EXPECT_TRUE(pad.IsButtonUp(Buttons::LeftTrigger));
    EXPECT_TRUE(pad.IsButtonDown(Buttons::LeftThumbstickLeft));
    EXPECT_TRUE(pad.IsButtonUp(Buttons::LeftThumbstickUp));
    GamePad::SetHeadlessState(PlayerIndex::Two, nullptr);
    EXPECT_FALSE(GamePad::GetState(PlayerIndex::Two).IsConnected);
}

}  // namespace
}  // namespace fxport
