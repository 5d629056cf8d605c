// The two ways the runtime reports API misuse, named after the .NET exceptions XNA throws so that a
// port keeps its meaning. Every message names the object and the value at fault.
#pragma once

#include <stdexcept>
#include <string>

namespace fxport {

// A bad argument: unknown parameter name, wrong value type or size, a size the driver cannot make.
class ArgumentError : public std::invalid_argument {
public:
    explicit ArgumentError(const std::string& what) : std::invalid_argument(what) {}
};

// A call that is wrong in the current state: drawing with no pass applied, sampling the texture
// that is being rendered to, using a disposed resource.
class InvalidOperation : public std::logic_error {
public:
    explicit InvalidOperation(const std::string& what) : std::logic_error(what) {}
};

}  // namespace fxport
