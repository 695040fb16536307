#include "assets/model_import.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "assets/input_error.h"

namespace pt {

ImportedFile importModelFile(const std::string& path, int32_t object, Scene& scene,
                             const ProgressFn& progress) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".gltf" || extension == ".glb") return importGltf(path, object, scene, progress);
    if (extension == ".obj") return importObj(path, object, scene, progress);
    throw InputError(std::filesystem::path(path).filename().string() + ": unsupported model format '" +
                     extension + "' (expected .gltf, .glb or .obj)");
}

}  // namespace pt
