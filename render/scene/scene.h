#pragma once
// Scene: the editable host form of everything that is rendered (STYLE.md rule 5). It owns
// names, ids and std containers; compileRenderScene() flattens it for the backends. Nothing
// here reads files: the assets library fills it.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "render/animation/rig.h"
#include "render/kernel/material.h"
#include "render/kernel/scene_kinds.h"
#include "render/math/affine.h"
#include "render/math/vec.h"

namespace pt {

// One glTF morph target of a Mesh: per-vertex offsets added, scaled by the target's weight,
// to the undeformed vertices (glTF 2.0 section 3.7.2.2). Indexed like Mesh::positions.
struct MorphTarget {
    std::string name;                  // glTF mesh extras.targetNames[i] when present, else "target i"
    std::vector<Vec3> positionDeltas;  // one per vertex of the Mesh
    std::vector<Vec3> normalDeltas;    // empty, or one per vertex
};

// One BLAS worth of geometry, in object space. A mesh is shared by every instance that
// references it. Materials are not stored here: each primitive names a *slot*, and each
// instance maps slots to scene materials, so one mesh can be instanced with other materials.
struct Mesh {
    std::string name;
    GeometryKind kind = GeometryKind::Triangles;
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;  // empty, or one unit normal per position
    std::vector<Vec2> uvs;      // empty, or one per position (glTF TEXCOORD_0)
    // Empty, or one per position (glTF TANGENT): xyz a unit tangent along increasing U, w = +-1
    // the handedness (bitangent = cross(normal, xyz) * w). A zero vector (w = 0) marks a
    // vertex without one; the renderer then derives the frame from the triangle's UVs.
    std::vector<Vec4> tangents;
    std::vector<uint32_t> indices;         // three per triangle, each < positions.size()
    std::vector<Vec4> spheres;             // Spheres: xyz = center, w = radius (> 0)
    std::vector<uint32_t> primitiveSlots;  // empty (all slot 0), or one per primitive
    uint32_t slotCount = 1;
    // Morph targets (render/scene/morph.h): positions and normals above are the deformed
    // ones, basePositions + sum of weight x delta; a weight change calls applyMorphWeights.
    std::vector<MorphTarget> morphTargets;  // glTF mesh targets, in file order
    std::vector<float> morphWeights;        // one per target; the current deformation
    std::vector<float>
        defaultMorphWeights;          // one per target: the file's pose (scene JSON writes only changes)
    std::vector<Vec3> basePositions;  // undeformed positions; empty when no targets
    std::vector<Vec3> baseNormals;    // undeformed normals; empty when no targets or no normals

    uint32_t primitiveCount() const {
        return kind == GeometryKind::Spheres ? uint32_t(spheres.size()) : uint32_t(indices.size() / 3);
    }
};

struct Instance {
    std::string name;
    uint32_t mesh = 0;
    Affine3 objectToWorld;
    std::vector<uint32_t> materials;  // one Scene::materials index per mesh slot
    int32_t object = -1;              // the SceneObject that created it (-1: none)
    bool visible = true;
    // glTF KHR_materials_variants, when its object's file has variants: the slots' materials
    // under each variant (SceneObject::variants order; every row complete, a slot the variant
    // does not map keeping its default) and under none (the file's defaults).
    std::vector<std::vector<uint32_t>> variantMaterials;
    std::vector<uint32_t> defaultMaterials;
};

struct NamedMaterial {
    std::string name;
    Material params;
    int32_t object = -1;  // -1: defined by the scene JSON; else imported by that object
};

// An image as decoded from its file. Whether its texels are sRGB-encoded is decided by the
// slot that samples it (base color and emission are; normal and metallic-roughness are not).
struct Texture {
    std::string name;
    std::string sourcePath;  // file it came from ("" when embedded), for messages
    uint32_t width = 0, height = 0;
    TexelFormat format = TexelFormat::RGBA8;
    std::vector<uint8_t> texels8;  // RGBA8: width * height * 4
    std::vector<float> texelsF;    // RGBA32F: width * height * 4
    WrapMode wrapS = WrapMode::Repeat, wrapT = WrapMode::Repeat;
    bool nearest = false;  // sampler magFilter NEAREST; else bilinear
    int32_t object = -1;   // as NamedMaterial::object
};

struct Camera {
    Vec3 position{0.0f, 0.0f, 5.0f};
    Vec3 lookAt{0.0f, 0.0f, 0.0f};
    Vec3 up{0.0f, 1.0f, 0.0f};
    float verticalFovDegrees = 45.0f;
    float apertureRadius = 0.0f;  // thin lens radius in world units; 0 is a pinhole
    float focusDistance = 0.0f;   // world units along the view direction; <= 0: the look-at distance
};

struct RenderSettings {
    uint32_t width = 512, height = 512;
    uint32_t maxDepth = 8;  // path vertices after the camera
    uint32_t spp = 64;
    uint32_t seed = 0;
};

struct Environment {
    Vec3 color{0.0f, 0.0f, 0.0f};  // constant radiance, used when there is no image
    std::string imagePath;         // equirectangular HDR (absolute once loaded)
    int32_t texture = -1;          // Scene::textures index of the decoded image
    float intensity = 1.0f;
    float rotationDegrees = 0.0f;  // about +Y
};

// Object-to-parent transform as written in scene JSON: either TRS (Euler XYZ in degrees,
// applied scale, then rotate X, Y, Z, then translate) or a full column-major 4x4 matrix.
struct ObjectTransform {
    Vec3 translate{0.0f, 0.0f, 0.0f};
    Vec3 rotateDegrees{0.0f, 0.0f, 0.0f};
    Vec3 scale{1.0f, 1.0f, 1.0f};
    bool useMatrix = false;
    float matrix[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

    Affine3 toAffine() const;
};

enum class ObjectKind : uint32_t { File = 0, Sphere = 1, Box = 2, Quad = 3 };

// A scene JSON "objects" entry, kept so that saving writes what was loaded. Built-in shapes
// are unit sized: sphere of radius 1 at the origin, box from -1 to 1, quad from -1 to 1 in
// XZ facing +Y (a rectangular area light when its material emits).
struct SceneObject {
    std::string name;
    ObjectKind kind = ObjectKind::File;
    std::string path;  // File: absolute path of the .gltf/.glb/.obj
    ObjectTransform transform;
    std::string material;                                  // shapes: a Scene material name
    std::map<std::string, std::string> materialOverrides;  // File: file material -> scene material
    // File: mesh name -> morph weights replacing the file's defaults (Mesh::defaultMorphWeights).
    std::map<std::string, std::vector<float>> morphWeights;
    // File: the glTF's material variants (KHR_materials_variants), by name in file order, and
    // the one its instances show (-1: none, the file's default materials).
    std::vector<std::string> variants;
    int32_t variant = -1;
    // File: the animation its rig shows (render/scene/scene_animation.h), by name ("": the
    // rest pose), and the time into it, seconds.
    std::string animation;
    float animationTime = 0.0f;
};

// Shows variant `variant` of objects[object] (-1: the file's default materials) on every
// instance it placed (those placed without variant rows keep their materials). Takes the
// lists rather than a Scene so that editor commands can apply it to a copy of the layout.
void selectObjectVariant(std::vector<SceneObject>& objects, std::vector<Instance>& instances, uint32_t object,
                         int32_t variant);

// A punctual light (KHR_lights_punctual), in world space. Photometric units as in glTF, taken
// as the renderer's radiometric units without a 683 lm/W factor, the same convention as
// emission strength (so emission in nits, lights in candela and lux agree):
//   point, spot: `intensity` is luminous intensity in candela (radiant intensity = color x
//   intensity, falling off as 1/d^2); directional: illuminance in lux on a surface facing it.
// glTF's `range` is kept but not rendered: the falloff is the physical 1/d^2 at any distance,
// as the extension allows ("range ... MAY" cut off); a range only exists to help rasterisers.
struct Light {
    std::string name;
    LightType type = LightType::Point;
    Vec3 color{1.0f, 1.0f, 1.0f};       // linear Rec.709
    float intensity = 1.0f;             // candela (point, spot) or lux (directional)
    Vec3 position{0.0f, 0.0f, 0.0f};    // point, spot
    Vec3 direction{0.0f, 0.0f, -1.0f};  // spot, directional: where the light shines (need not be unit)
    float innerConeDegrees = 0.0f;      // spot: full intensity inside this angle from `direction`
    float outerConeDegrees = 45.0f;     // spot: dark outside; smooth falloff in between (glTF)
    float range = 0.0f;                 // glTF range, 0 = infinite; not rendered (see above)
    int32_t object = -1;                // -1: defined by the scene JSON; else imported by that object
};

// How the scene is viewed (scene JSON "color"): the OpenColorIO config and its display, view
// and look. "" means the default: for `config` the usual search (assets/color_config.h:
// resolveColorConfigPath), for the others the config's defaults. `config` is absolute once
// read from a file (the JSON holds it relative to the scene file). Display only: changing it
// never restarts accumulation.
struct ColorSettings {
    std::string config;
    std::string display, view, look;
};

struct Scene {
    std::string sourcePath;  // file it was loaded from (absolute), "" if built in code
    std::vector<SceneObject> objects;
    std::vector<Mesh> meshes;
    std::vector<Instance> instances;
    std::vector<NamedMaterial> materials;
    std::vector<Texture> textures;
    std::vector<Light> lights;  // punctual lights (emissive surfaces are materials)
    Camera camera;
    bool cameraFromFile = false;  // the camera came from the JSON or a glTF camera
    RenderSettings render;
    Environment environment;
    ColorSettings color;
    // Skins and animations of the model files (render/animation/rig.h): what
    // render/scene/scene_animation.h poses.
    std::vector<AnimationRig> rigs;
    std::vector<std::string> warnings;  // non-fatal import messages, each naming file and element
    // Every glTF extension the scene's model files declare, and whether this build honours it
    // (pt-render info lists them). Import information, not rendered.
    std::map<std::string, bool> gltfExtensions;

    int32_t findMaterial(const std::string& name) const;
    // Bounds of all visible instances in world space; empty scenes give a unit box.
    void worldBounds(Vec3& lo, Vec3& hi) const;
    // Bounds of one instance in world space, hidden or not; false where it has no geometry.
    bool instanceBounds(uint32_t instance, Vec3& lo, Vec3& hi) const;
    uint64_t triangleCount() const;  // over instances (what is traced)
};

}  // namespace pt
