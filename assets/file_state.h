#pragma once
// What a path names, for loaders that must say why a file cannot be read in the right words
// (issue 17: a folder given as a scene was "no such file", an empty PNG "not found", and a
// folder named as a texture crashed tinygltf's reader with std::bad_alloc).
#include <string>

namespace pt {

enum class FileState { Readable, Empty, Missing, Folder, NotAFile };

FileState fileState(const std::string& path);

// The words for a state that is not Readable: "empty file", "no such file", "a folder, not a
// file", "not a regular file".
const char* fileStateWords(FileState state);

}  // namespace pt
