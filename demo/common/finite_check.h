// fxdemo --check-finite: every demo pass (PassTimer) is followed by a scan of the targets it bound
// for NaN/Inf (fxport::FiniteCheck); the first pass that leaves one stops the program with a
// message naming the pass, the target, the pixel and the value.
//
//   FiniteCheckScope finite(game.GraphicsDevice, common.checkFinite);   // in a run_*.cpp
#pragma once

#include <memory>
#include <stdexcept>
#include <vector>

#include "fxport/graphics/finite_check.h"

namespace fxport::demo {

// What PassTimer throws: what() is "--check-finite: pass 'LightMap' wrote NaN into ...".
class NonFiniteError : public std::runtime_error {
public:
    explicit NonFiniteError(const NonFiniteTarget& first);
    NonFiniteTarget first;
};

// Throws NonFiniteError for the first entry, if any.
void throwIfNonFinite(const std::vector<NonFiniteTarget>& found);

// Installs a FiniteCheck as PassTimer::finiteCheck while it lives (when `enabled`); at the end of
// a run that was not stopped, prints how many passes and targets were checked.
class FiniteCheckScope {
public:
    FiniteCheckScope(GraphicsDevice* device, bool enabled);
    ~FiniteCheckScope();
    FiniteCheckScope(const FiniteCheckScope&) = delete;
    FiniteCheckScope& operator=(const FiniteCheckScope&) = delete;

private:
    std::unique_ptr<FiniteCheck> check_;
};

}  // namespace fxport::demo
