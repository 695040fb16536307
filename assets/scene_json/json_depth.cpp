#include "assets/scene_json/json_depth.h"

#include "assets/input_error.h"

namespace pt {

void checkJsonDepth(std::string_view text, const std::string& label, uint32_t limit) {
    uint32_t depth = 0;
    bool inString = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\') {
                ++i;  // the escaped character, a quote included, never ends the string
            } else if (c == '"') {
                inString = false;
            }
            continue;
        }
        if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > limit) {
                throw InputError(label + ": JSON nested deeper than " + std::to_string(limit) +
                                 " levels (at byte " + std::to_string(i) + ")");
            }
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
}

}  // namespace pt
