// XNA's Keyboard and Mouse: snapshots of the window's input (GLFW). Headless platforms report
// every key up and the mouse at (0,0), so ported Update() code runs unchanged in a headless demo.
//
//   KeyboardState k = Keyboard::GetState();
//   if (k.IsKeyDown(Keys::Z)) ...
#pragma once

#include <bitset>
#include <cstdint>
#include <vector>

#include "fxport/math/vector2.h"

namespace fxport {

class GraphicsDevice;

// XNA's Keys: Windows virtual-key codes, every value XNA 4 names.
enum class Keys : std::uint8_t {
    None = 0, Back = 8, Tab = 9, Enter = 13, Pause = 19, CapsLock = 20, Kana = 21, Kanji = 25, Escape = 27,
    ImeConvert = 28, ImeNoConvert = 29, Space = 32, PageUp = 33, PageDown = 34, End = 35, Home = 36,
    Left = 37, Up = 38, Right = 39, Down = 40, Select = 41, Print = 42, Execute = 43, PrintScreen = 44,
    Insert = 45, Delete = 46, Help = 47,
    D0 = 48, D1, D2, D3, D4, D5, D6, D7, D8, D9,
    A = 65, B, C, D, E, F, G, H, I, J, K, L, M, N, O, P, Q, R, S, T, U, V, W, X, Y, Z,
    LeftWindows = 91, RightWindows = 92, Apps = 93, Sleep = 95,
    NumPad0 = 96, NumPad1, NumPad2, NumPad3, NumPad4, NumPad5, NumPad6, NumPad7, NumPad8, NumPad9,
    Multiply = 106, Add = 107, Separator = 108, Subtract = 109, Decimal = 110, Divide = 111,
    F1 = 112, F2, F3, F4, F5, F6, F7, F8, F9, F10, F11, F12, F13, F14, F15, F16, F17, F18, F19, F20, F21, F22, F23, F24,
    NumLock = 144, Scroll = 145,
    LeftShift = 160, RightShift, LeftControl, RightControl, LeftAlt, RightAlt,
    BrowserBack = 166, BrowserForward, BrowserRefresh, BrowserStop, BrowserSearch, BrowserFavorites, BrowserHome,
    VolumeMute = 173, VolumeDown, VolumeUp, MediaNextTrack, MediaPreviousTrack, MediaStop, MediaPlayPause,
    LaunchMail = 180, SelectMedia, LaunchApplication1, LaunchApplication2,
    OemSemicolon = 186, OemPlus = 187, OemComma = 188, OemMinus = 189, OemPeriod = 190, OemQuestion = 191,
    OemTilde = 192, ChatPadGreen = 202, ChatPadOrange = 203, OemOpenBrackets = 219, OemPipe = 220,
    OemCloseBrackets = 221, OemQuotes = 222, Oem8 = 223, OemBackslash = 226, ProcessKey = 229,
    OemCopy = 242, OemAuto = 243, OemEnlW = 244, Attn = 246, Crsel = 247, Exsel = 248, EraseEof = 249,
    Play = 250, Zoom = 251, Pa1 = 253, OemClear = 254,
};

enum class KeyState : std::uint8_t { Up, Down };

class KeyboardState {
public:
    bool IsKeyDown(Keys key) const { return down_[std::size_t(key)]; }
    bool IsKeyUp(Keys key) const { return !down_[std::size_t(key)]; }
    KeyState operator[](Keys key) const { return IsKeyDown(key) ? KeyState::Down : KeyState::Up; }  // C#'s indexer
    std::vector<Keys> GetPressedKeys() const;

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

// XNA's GamePad: the four controllers of GLFW's standard (Xbox) mapping. Headless there are none:
// GetState reports IsConnected false unless a test or headless demo scripted a state with
// SetHeadlessState (fxport's addition, to drive ported Update() code without a controller).
//
//   GamePadState pad = GamePad::GetState(PlayerIndex::One);
//   if (pad.Buttons.A == ButtonState::Pressed || pad.IsButtonDown(Buttons::Start)) ...
//   position += pad.ThumbSticks.Left * speed;   // y up, as in XNA
enum class PlayerIndex : std::uint8_t { One, Two, Three, Four };

// XNA's Buttons flags (values as in XNA 4).
enum class Buttons : std::uint32_t {
    DPadUp = 1, DPadDown = 2, DPadLeft = 4, DPadRight = 8, Start = 16, Back = 32, LeftStick = 64, RightStick = 128,
    LeftShoulder = 256, RightShoulder = 512, BigButton = 2048, A = 4096, B = 8192, X = 16384, Y = 32768,
    LeftThumbstickLeft = 2097152, RightTrigger = 4194304, LeftTrigger = 8388608, RightThumbstickUp = 16777216,
    RightThumbstickDown = 33554432, RightThumbstickRight = 67108864, RightThumbstickLeft = 134217728,
    LeftThumbstickUp = 268435456, LeftThumbstickDown = 536870912, LeftThumbstickRight = 1073741824,
};
inline Buttons operator|(Buttons a, Buttons b) { return Buttons(std::uint32_t(a) | std::uint32_t(b)); }

struct GamePadButtons {
    ButtonState A = ButtonState::Released, B = ButtonState::Released, X = ButtonState::Released, Y = ButtonState::Released;
    ButtonState Back = ButtonState::Released, Start = ButtonState::Released, BigButton = ButtonState::Released;
    ButtonState LeftShoulder = ButtonState::Released, RightShoulder = ButtonState::Released;
    ButtonState LeftStick = ButtonState::Released, RightStick = ButtonState::Released;
};
struct GamePadDPad {
    ButtonState Up = ButtonState::Released, Down = ButtonState::Released, Left = ButtonState::Released, Right = ButtonState::Released;
};
struct GamePadThumbSticks {
    Vector2 Left, Right;  // each axis in [-1, 1], y up
};
struct GamePadTriggers {
    float Left = 0, Right = 0;  // [0, 1]
};

struct GamePadState {
    bool IsConnected = false;
    int PacketNumber = 0;
    GamePadButtons Buttons;
    GamePadDPad DPad;
    GamePadThumbSticks ThumbSticks;
    GamePadTriggers Triggers;
    // XNA's rules: a trigger counts as pressed past 0.5 (its threshold), a thumbstick direction
    // past 0.5 on that axis; Buttons may combine flags (all must be down).
    bool IsButtonDown(fxport::Buttons buttons) const;
    bool IsButtonUp(fxport::Buttons buttons) const { return !IsButtonDown(buttons); }
};

class GamePad {
public:
    // Thumbsticks get XNA's default dead zone (IndependentAxes, 0.24 of the range, rescaled).
    static GamePadState GetState(PlayerIndex playerIndex);
    // No vibration through GLFW: returns false (XNA's answer for a controller that cannot).
    static bool SetVibration(PlayerIndex playerIndex, float leftMotor, float rightMotor);
    // Headless runs: the state GetState reports for `playerIndex` until cleared (nullptr).
    static void SetHeadlessState(PlayerIndex playerIndex, const GamePadState* state);
};

}  // namespace fxport
