// GameTime: what XNA's Game passes to Update and Draw. Times are TimeSpans (100 ns ticks), as in XNA:
// gameTime.ElapsedGameTime.TotalSeconds(). Plain values (docs/API.md: stored properties are fields).
#pragma once

#include "fxport/framework/time_span.h"

namespace fxport {

struct GameTime {
    // Game time since the previous Update (fixed step: TargetElapsedTime per Update; in Draw, the
    // sum of the steps run since the previous Draw).
    TimeSpan ElapsedGameTime;
    // Game time since the game started (the sum of every Update's ElapsedGameTime).
    TimeSpan TotalGameTime;
    // Fixed step only: set once Update has been running late for several frames (the game did more
    // than one Update per Draw to catch up), cleared when it has caught up. See Game::Tick.
    bool IsRunningSlowly = false;

    GameTime() = default;
    GameTime(TimeSpan totalGameTime, TimeSpan elapsedGameTime, bool isRunningSlowly = false)
        : ElapsedGameTime(elapsedGameTime), TotalGameTime(totalGameTime), IsRunningSlowly(isRunningSlowly) {}
};

}  // namespace fxport
