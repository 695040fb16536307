#include "assets/message_text.h"

#include <cstdio>

namespace pt {

std::string shortened(std::string_view text, size_t maxChars) {
    if (text.size() <= maxChars) return std::string(text);
    constexpr std::string_view kEllipsis = "...";
    size_t keep = maxChars > kEllipsis.size() ? maxChars - kEllipsis.size() : 0;
    // Back up over UTF-8 continuation bytes (10xxxxxx) so no character is cut in half.
    while (keep > 0 && (static_cast<unsigned char>(text[keep]) & 0xC0u) == 0x80u) --keep;
    return std::string(text.substr(0, keep)) + std::string(kEllipsis);
}

std::string escapedControls(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (u >= 0x20u && u != 0x7fu) {
            out += c;
        } else if (c == '\n') {
            out += "\\n";
        } else if (c == '\r') {
            out += "\\r";
        } else if (c == '\t') {
            out += "\\t";
        } else {
            char code[5];
            std::snprintf(code, sizeof code, "\\x%02x", unsigned(u));
            out += code;
        }
    }
    return out;
}

std::string oneLineMessage(std::string_view message) {
    // Escaping at most quadruples the bytes: escape a bounded prefix, then shorten.
    return shortened(escapedControls(message.substr(0, 4 * kMaxMessageChars)), kMaxMessageChars);
}

}  // namespace pt
