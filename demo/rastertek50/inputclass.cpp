////////////////////////////////////////////////////////////////////////////////
// Filename: inputclass.cpp
////////////////////////////////////////////////////////////////////////////////
#include "rastertek50/inputclass.h"

namespace Rastertek50 {

InputClass::InputClass()
{
	m_screenWidth = 0;
	m_screenHeight = 0;
}


InputClass::~InputClass()
{
}


bool InputClass::Initialize(int screenWidth, int screenHeight)
{
	// Store the screen size which will be used for positioning the mouse cursor.
	m_screenWidth = screenWidth;
	m_screenHeight = screenHeight;

	return true;
}


void InputClass::Shutdown()
{
	return;
}


bool InputClass::Frame()
{
	// Read the current state of the keyboard.
	m_keyboardState = fxport::Keyboard::GetState();

	return true;
}


bool InputClass::IsEscapePressed()
{
	// Do a bitwise and on the keyboard state to check if the escape key is currently being pressed.
	return m_keyboardState.IsKeyDown(fxport::Keys::Escape);
}

}  // namespace Rastertek50
