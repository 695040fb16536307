#pragma once
#include <functional>
#include <string>

namespace pt {

// Writes `path` all at once: `writeTemp` fills a temporary file in the same folder, which then
// replaces `path` by rename, so readers see the old file or the new one, never a torn one, and
// a failed export leaves the old file untouched. Throws InputError naming `path` on failure.
void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& tempPath)>& writeTemp);

// Convenience for text and byte content.
void writeTextAtomically(const std::string& path, const std::string& content);

}  // namespace pt
