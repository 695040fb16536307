#pragma once
// A bound on how deeply arrays and objects nest in JSON text, checked on the raw bytes before
// any parser sees them. Every JSON parser and walker that reads untrusted files recurses over
// the nesting somewhere (tinygltf's parser; nlohmann's destructor and dump(); the glTF check
// quoting a value), so a 40 KB file of 20,000 '[' overflowed the stack. No file the project
// reads needs more than a few dozen levels: glTF's deepest schema path is under ten, scene
// JSON's under six, and `extras` kept for round trips get the rest.
#include <cstdint>
#include <string>
#include <string_view>

namespace pt {

constexpr uint32_t kMaxJsonDepth = 256;

// Throws InputError("<label>: JSON nested deeper than <limit> levels (at byte N)") where the
// text opens its (limit + 1)-th nested array or object. Brackets inside strings (escapes
// included) do not count; malformed text is otherwise left for the parser to report.
void checkJsonDepth(std::string_view text, const std::string& label, uint32_t limit = kMaxJsonDepth);

}  // namespace pt
