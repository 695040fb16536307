#pragma once
// What the fuzz targets share. The loaders and readers take paths, so each input is written
// to files of the process's own temp folder (test::tempDir(), under $TMPDIR), read from there
// as the editor and pt-render read them, and removed again, so that no input sees the files
// of the one before it and every crash reproduces from its input alone.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "render/scene/scene.h"

namespace pt::fuzz {

// Writes `data` to each of `names` (the first is the file loaded), runs loadScene on it and,
// when it loads, compiles the scene for rendering (flattened geometry, BVHs, lights), which
// every scene that loads must survive. Returns the scene when it loaded.
std::optional<Scene> loadAndCompile(const std::vector<std::string>& names, const uint8_t* data, size_t size);

// Writes `data` to `name` in the temp folder, calls `read` with its path and removes the file.
// An InputError is the readers' promised answer to bad input, not a finding.
void readWrittenInput(const std::string& name, const uint8_t* data, size_t size,
                      const std::function<void(const std::string& path)>& read);

// Aborts (a finding for the fuzzer) with `what` and the message on stderr.
[[noreturn]] void fail(const std::string& what, const std::string& message);

}  // namespace pt::fuzz
