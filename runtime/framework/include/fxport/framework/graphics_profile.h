// GraphicsProfile: XNA 4's two feature sets (Microsoft.Xna.Framework.Graphics.GraphicsProfile).
// fxport's device always has every HiDef feature and enforces none of Reach's limits (texture
// sizes, formats, shader model 2), so a game written for either profile runs unchanged; a Reach
// game that breaks a Reach rule is not stopped as XNA would stop it.
#pragma once

namespace fxport {

enum class GraphicsProfile { Reach, HiDef };

}  // namespace fxport
