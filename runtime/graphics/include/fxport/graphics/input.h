// XNA's Keyboard and Mouse: snapshots of the window's input (GLFW). Headless platforms report
// every key up and the mouse at (0,0), so ported Update() code runs unchanged in a headless demo.
//
//   KeyboardState k = Keyboard::GetState();
//   if (k.IsKeyDown(Keys::Z)) ...
#pragma once

#include <bitset>
#include <cstdint>

namespace fxport {

class GraphicsDevice;

// Windows virtual-key codes, as XNA's Keys (a subset: what demos use).
enum class Keys : std::uint8_t {
    None = 0, Back = 8, Tab = 9, Enter = 13, Escape = 27, Space = 32, PageUp = 33, PageDown = 34,
    Left = 37, Up = 38, Right = 39, Down = 40,
    D0 = 48, D1, D2, D3, D4, D5, D6, D7, D8, D9,
    A = 65, B, C, D, E, F, G, H, I, J, K, L, M, N, O, P, Q, R, S, T, U, V, W, X, Y, Z,
    NumPad0 = 96, NumPad1, NumPad2, NumPad3, NumPad4, NumPad5, NumPad6, NumPad7, NumPad8, NumPad9,
    F1 = 112, F2, F3, F4, F5, F6, F7, F8, F9, F10, F11, F12,
    LeftShift = 160, RightShift, LeftControl, RightControl, LeftAlt, RightAlt,
    OemPlus = 187, OemMinus = 189,
};

class KeyboardState {
public:
    bool IsKeyDown(Keys key) const { return down_[std::size_t(key)]; }
    bool IsKeyUp(Keys key) const { return !down_[std::size_t(key)]; }

private:
    friend class Keyboard;
    std::bitset<256> down_;
};

class Keyboard {
public:
    // The keyboard of the current device's window.
    static KeyboardState GetState();
};

enum class ButtonState : std::uint8_t { Released, Pressed };

struct MouseState {
    int X = 0, Y = 0;
    int ScrollWheelValue = 0;
    ButtonState LeftButton = ButtonState::Released;
    ButtonState RightButton = ButtonState::Released;
    ButtonState MiddleButton = ButtonState::Released;
};

class Mouse {
public:
    static MouseState GetState();
    // Moves the pointer to window pixel (x, y); no-op headless.
    static void SetPosition(int x, int y);
};

}  // namespace fxport
