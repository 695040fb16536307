#pragma once
// InputError: bad input (malformed file, missing file, wrong JSON type). Importers throw it
// with a message that names the file and the element; the public entry points (loadScene,
// readSceneJson) catch it and return the message, so callers never see a crash.
#include <stdexcept>
#include <string>

namespace pt {

class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace pt
