////////////////////////////////////////////////////////////////////////////////
// Filename: inputclass.h
////////////////////////////////////////////////////////////////////////////////
// Reconstructed (the seed uses InputClass but does not list it): only what tutorial 50 calls
// (Frame, IsEscapePressed), on fxport's Keyboard instead of DirectInput. Headless: never pressed.
#pragma once


//////////////
// INCLUDES //
//////////////
#include "fxport/graphics.h"
#include "fxport/framework/input.h"

namespace Rastertek50 {

////////////////////////////////////////////////////////////////////////////////
// Class name: InputClass
////////////////////////////////////////////////////////////////////////////////
class InputClass
{
public:
	InputClass();
	InputClass(const InputClass&) = delete;
	~InputClass();

	bool Initialize(int, int);
	void Shutdown();
	bool Frame();

	bool IsEscapePressed();

private:
	fxport::KeyboardState m_keyboardState;
	int m_screenWidth, m_screenHeight;
};

}  // namespace Rastertek50
