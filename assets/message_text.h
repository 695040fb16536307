#pragma once
// Error text that stays one bounded line whatever the input holds (issue 17: a 10 MB string
// quoted in full made a 10 MB message, and a file's escape sequences and newlines reached the
// terminal raw). Values are quoted shortened at the source; every message is escaped and
// bounded once more where it leaves the program (loadScene, pt-render, the editor).
#include <cstddef>
#include <string>
#include <string_view>

namespace pt {

constexpr size_t kMaxQuotedChars = 80;     // a value quoted in a message
constexpr size_t kMaxMessageChars = 1000;  // a whole message

// `text` cut to at most maxChars bytes, "..." included, never inside a UTF-8 sequence.
std::string shortened(std::string_view text, size_t maxChars = kMaxQuotedChars);

// `text` with control characters (below 0x20, and 0x7f) written as \n, \r, \t or \xNN.
std::string escapedControls(std::string_view text);

// A message as one bounded line: control characters escaped, then shortened to kMaxMessageChars.
std::string oneLineMessage(std::string_view message);

}  // namespace pt
