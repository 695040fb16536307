#pragma once
// Helpers for the scene JSON and loader tests: scene equality for load/save/load tests
// (everything rendered must be identical, floats compared by their bits so that a last-ulp
// drift is caught; a failure names every differing field), and scratch files per test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "render/scene/scene.h"
#include "support/test_paths.h"

namespace pt::test {

// A fresh folder for the running test under tempDir(), so tests never see each other's files.
inline std::string testFolder() {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::filesystem::path folder =
        std::filesystem::path(tempDir()) / (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder.string();
}

// Writes `text` to `folder`/`name` (creating subfolders) and returns the path.
inline std::string writeFile(const std::string& folder, const std::string& name, const std::string& text) {
    const std::filesystem::path path = std::filesystem::path(folder) / name;
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
}

inline std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Writes a .glb of `json` and a BIN chunk of `bin` (each padded to 4 bytes, as the spec asks:
// JSON with spaces, BIN with zeros) to `folder`/`name` and returns the path.
inline std::string writeGlb(const std::string& folder, const std::string& name, std::string json,
                            std::string bin) {
    while (json.size() % 4) json += ' ';
    while (bin.size() % 4) bin += '\0';
    std::string glb = "glTF";
    const auto u32 = [&glb](uint32_t v) { glb.append(reinterpret_cast<const char*>(&v), 4); };
    u32(2);
    u32(uint32_t(12 + 8 + json.size() + 8 + bin.size()));
    u32(uint32_t(json.size()));
    glb += "JSON" + json;
    u32(uint32_t(bin.size()));
    glb += std::string("BIN\0", 4) + bin;
    return writeFile(folder, name, glb);
}

inline bool bitsEqual(float a, float b) { return std::memcmp(&a, &b, sizeof(float)) == 0; }
inline bool bitsEqual(Vec2 a, Vec2 b) { return bitsEqual(a.x, b.x) && bitsEqual(a.y, b.y); }
inline bool bitsEqual(Vec3 a, Vec3 b) {
    return bitsEqual(a.x, b.x) && bitsEqual(a.y, b.y) && bitsEqual(a.z, b.z);
}
inline bool bitsEqual(Vec4 a, Vec4 b) { return bitsEqual(a.xyz(), b.xyz()) && bitsEqual(a.w, b.w); }
inline bool bitsEqual(const Affine3& a, const Affine3& b) {
    return bitsEqual(a.rows[0], b.rows[0]) && bitsEqual(a.rows[1], b.rows[1]) &&
           bitsEqual(a.rows[2], b.rows[2]);
}
template <typename T>
bool bitsEqual(const std::vector<T>& a, const std::vector<T>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        if (!bitsEqual(a[i], b[i])) return false;
    }
    return true;
}
inline bool bitsEqual(uint32_t a, uint32_t b) { return a == b; }
inline bool bitsEqual(const TextureRef& a, const TextureRef& b) {
    return a.texture == b.texture && a.texCoord == b.texCoord && bitsEqual(a.offset, b.offset) &&
           bitsEqual(a.scale, b.scale) && bitsEqual(a.rotation, b.rotation);
}

// Collects the names of differing fields.
class Differences {
public:
    template <typename T>
    void check(const std::string& what, const T& a, const T& b) {
        if (!same(a, b)) fields_.push_back(what);
    }
    ::testing::AssertionResult result() const {
        if (fields_.empty()) return ::testing::AssertionSuccess();
        std::string list;
        for (const std::string& field : fields_) list += (list.empty() ? "" : ", ") + field;
        return ::testing::AssertionFailure() << "scenes differ in " << list;
    }

private:
    template <typename T>
    static bool same(const T& a, const T& b) {
        if constexpr (std::is_same_v<T, float> || std::is_same_v<T, Vec2> || std::is_same_v<T, Vec3> ||
                      std::is_same_v<T, Affine3> || std::is_same_v<T, TextureRef>) {
            return bitsEqual(a, b);
        } else if constexpr (std::is_same_v<T, std::vector<Vec3>> || std::is_same_v<T, std::vector<Vec2>> ||
                             std::is_same_v<T, std::vector<Vec4>> || std::is_same_v<T, std::vector<float>>) {
            return bitsEqual(a, b);
        } else {
            return a == b;
        }
    }
    std::vector<std::string> fields_;
};

inline void compareMaterial(Differences& d, const std::string& at, const Material& a, const Material& b) {
#define PT_CHECK_FIELD(field) d.check(at + "." #field, a.field, b.field)
    PT_CHECK_FIELD(baseColor);
    PT_CHECK_FIELD(alpha);
    PT_CHECK_FIELD(metallic);
    PT_CHECK_FIELD(roughness);
    PT_CHECK_FIELD(emission);
    PT_CHECK_FIELD(emissionStrength);
    PT_CHECK_FIELD(ior);
    PT_CHECK_FIELD(transmission);
    PT_CHECK_FIELD(specular);
    PT_CHECK_FIELD(specularColor);
    PT_CHECK_FIELD(clearcoat);
    PT_CHECK_FIELD(clearcoatRoughness);
    PT_CHECK_FIELD(diffuseTransmission);
    PT_CHECK_FIELD(diffuseTransmissionColor);
    PT_CHECK_FIELD(sheenColor);
    PT_CHECK_FIELD(sheenRoughness);
    PT_CHECK_FIELD(anisotropyStrength);
    PT_CHECK_FIELD(anisotropyRotation);
    PT_CHECK_FIELD(iridescence);
    PT_CHECK_FIELD(iridescenceIor);
    PT_CHECK_FIELD(iridescenceThicknessMin);
    PT_CHECK_FIELD(iridescenceThicknessMax);
    PT_CHECK_FIELD(dispersion);
    PT_CHECK_FIELD(thickness);
    PT_CHECK_FIELD(attenuationColor);
    PT_CHECK_FIELD(attenuationDistance);
    PT_CHECK_FIELD(scatterColor);
    PT_CHECK_FIELD(scatterAnisotropy);
    PT_CHECK_FIELD(subsurface);
    PT_CHECK_FIELD(subsurfaceColor);
    PT_CHECK_FIELD(subsurfaceRadius);
    PT_CHECK_FIELD(subsurfaceRadiusScale);
    PT_CHECK_FIELD(alphaMode);
    PT_CHECK_FIELD(alphaCutoff);
    PT_CHECK_FIELD(normalScale);
    PT_CHECK_FIELD(doubleSided);
    PT_CHECK_FIELD(unlit);
    PT_CHECK_FIELD(baseColorTexture);
    PT_CHECK_FIELD(metallicRoughnessTexture);
    PT_CHECK_FIELD(normalTexture);
    PT_CHECK_FIELD(emissiveTexture);
    PT_CHECK_FIELD(transmissionTexture);
    PT_CHECK_FIELD(diffuseTransmissionTexture);
    PT_CHECK_FIELD(diffuseTransmissionColorTexture);
    PT_CHECK_FIELD(sheenColorTexture);
    PT_CHECK_FIELD(sheenRoughnessTexture);
    PT_CHECK_FIELD(anisotropyTexture);
    PT_CHECK_FIELD(iridescenceTexture);
    PT_CHECK_FIELD(iridescenceThicknessTexture);
#undef PT_CHECK_FIELD
}

inline void compareGeometry(Differences& d, const Scene& a, const Scene& b) {
    d.check("meshes.size", a.meshes.size(), b.meshes.size());
    for (size_t i = 0; i < std::min(a.meshes.size(), b.meshes.size()); ++i) {
        const Mesh &x = a.meshes[i], &y = b.meshes[i];
        const std::string at = "meshes[" + std::to_string(i) + "]";
        d.check(at + ".name", x.name, y.name);
        d.check(at + ".kind", x.kind, y.kind);
        d.check(at + ".positions", x.positions, y.positions);
        d.check(at + ".normals", x.normals, y.normals);
        d.check(at + ".uvs", x.uvs, y.uvs);
        d.check(at + ".tangents", x.tangents, y.tangents);
        d.check(at + ".indices", x.indices, y.indices);
        d.check(at + ".spheres", x.spheres, y.spheres);
        d.check(at + ".primitiveSlots", x.primitiveSlots, y.primitiveSlots);
        d.check(at + ".slotCount", x.slotCount, y.slotCount);
    }
    d.check("instances.size", a.instances.size(), b.instances.size());
    for (size_t i = 0; i < std::min(a.instances.size(), b.instances.size()); ++i) {
        const Instance &x = a.instances[i], &y = b.instances[i];
        const std::string at = "instances[" + std::to_string(i) + "]";
        d.check(at + ".name", x.name, y.name);
        d.check(at + ".mesh", x.mesh, y.mesh);
        d.check(at + ".objectToWorld", x.objectToWorld, y.objectToWorld);
        d.check(at + ".materials", x.materials, y.materials);
        d.check(at + ".object", x.object, y.object);
        d.check(at + ".visible", x.visible, y.visible);
        d.check(at + ".variantMaterials", x.variantMaterials, y.variantMaterials);
        d.check(at + ".defaultMaterials", x.defaultMaterials, y.defaultMaterials);
    }
}

inline void compareMaterialsAndTextures(Differences& d, const Scene& a, const Scene& b) {
    d.check("materials.size", a.materials.size(), b.materials.size());
    for (size_t i = 0; i < std::min(a.materials.size(), b.materials.size()); ++i) {
        const std::string at = "materials[" + std::to_string(i) + "]";
        d.check(at + ".name", a.materials[i].name, b.materials[i].name);
        d.check(at + ".object", a.materials[i].object, b.materials[i].object);
        compareMaterial(d, at, a.materials[i].params, b.materials[i].params);
    }
    d.check("textures.size", a.textures.size(), b.textures.size());
    for (size_t i = 0; i < std::min(a.textures.size(), b.textures.size()); ++i) {
        const Texture &x = a.textures[i], &y = b.textures[i];
        const std::string at = "textures[" + std::to_string(i) + "]";
        d.check(at + ".sourcePath", x.sourcePath, y.sourcePath);
        d.check(at + ".size", std::make_pair(x.width, x.height), std::make_pair(y.width, y.height));
        d.check(at + ".format", x.format, y.format);
        d.check(at + ".texels8", x.texels8, y.texels8);
        d.check(at + ".texelsF", x.texelsF, y.texelsF);
        d.check(at + ".object", x.object, y.object);
    }
}

inline void compareSettings(Differences& d, const Scene& a, const Scene& b) {
    d.check("camera.position", a.camera.position, b.camera.position);
    d.check("camera.lookAt", a.camera.lookAt, b.camera.lookAt);
    d.check("camera.up", a.camera.up, b.camera.up);
    d.check("camera.fov", a.camera.verticalFovDegrees, b.camera.verticalFovDegrees);
    d.check("camera.aperture", a.camera.apertureRadius, b.camera.apertureRadius);
    d.check("camera.focusDistance", a.camera.focusDistance, b.camera.focusDistance);
    d.check("cameraFromFile", a.cameraFromFile, b.cameraFromFile);
    d.check("render.width", a.render.width, b.render.width);
    d.check("render.height", a.render.height, b.render.height);
    d.check("render.maxDepth", a.render.maxDepth, b.render.maxDepth);
    d.check("render.spp", a.render.spp, b.render.spp);
    d.check("render.seed", a.render.seed, b.render.seed);
    d.check("environment.color", a.environment.color, b.environment.color);
    d.check("environment.imagePath", a.environment.imagePath, b.environment.imagePath);
    d.check("environment.texture", a.environment.texture, b.environment.texture);
    d.check("environment.intensity", a.environment.intensity, b.environment.intensity);
    d.check("environment.rotation", a.environment.rotationDegrees, b.environment.rotationDegrees);
    d.check("color.config", a.color.config, b.color.config);
    d.check("color.display", a.color.display, b.color.display);
    d.check("color.view", a.color.view, b.color.view);
    d.check("color.look", a.color.look, b.color.look);
}

inline void compareLights(Differences& d, const Scene& a, const Scene& b) {
    d.check("lights.size", a.lights.size(), b.lights.size());
    for (size_t i = 0; i < std::min(a.lights.size(), b.lights.size()); ++i) {
        const Light &x = a.lights[i], &y = b.lights[i];
        const std::string at = "lights[" + std::to_string(i) + "]";
        d.check(at + ".name", x.name, y.name);
        d.check(at + ".type", x.type, y.type);
        d.check(at + ".color", x.color, y.color);
        d.check(at + ".intensity", x.intensity, y.intensity);
        d.check(at + ".position", x.position, y.position);
        d.check(at + ".direction", x.direction, y.direction);
        d.check(at + ".innerCone", x.innerConeDegrees, y.innerConeDegrees);
        d.check(at + ".outerCone", x.outerConeDegrees, y.outerConeDegrees);
        d.check(at + ".range", x.range, y.range);
        d.check(at + ".object", x.object, y.object);
    }
}

inline void compareObjects(Differences& d, const Scene& a, const Scene& b) {
    d.check("objects.size", a.objects.size(), b.objects.size());
    for (size_t i = 0; i < std::min(a.objects.size(), b.objects.size()); ++i) {
        const SceneObject &x = a.objects[i], &y = b.objects[i];
        const std::string at = "objects[" + std::to_string(i) + "]";
        d.check(at + ".name", x.name, y.name);
        d.check(at + ".kind", x.kind, y.kind);
        d.check(at + ".path", x.path, y.path);
        d.check(at + ".transform", x.transform.toAffine(), y.transform.toAffine());
        d.check(at + ".transform.useMatrix", x.transform.useMatrix, y.transform.useMatrix);
        d.check(at + ".material", x.material, y.material);
        d.check(at + ".materialOverrides", x.materialOverrides, y.materialOverrides);
        d.check(at + ".variants", x.variants, y.variants);
        d.check(at + ".variant", x.variant, y.variant);
    }
}

inline ::testing::AssertionResult scenesEqual(const Scene& a, const Scene& b) {
    Differences d;
    compareGeometry(d, a, b);
    compareMaterialsAndTextures(d, a, b);
    compareSettings(d, a, b);
    compareLights(d, a, b);
    compareObjects(d, a, b);
    return d.result();
}

}  // namespace pt::test
