// Reading scene JSON (schema: scenes/README.md). Every error is one InputError of the form
// "<json file name>: <json path>: <what>"; see assets/json_value.h for the helpers that
// build those paths and reject unknown keys.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "assets/image/image_read.h"
#include "assets/input_error.h"
#include "assets/message_text.h"
#include "assets/model_import.h"
#include "assets/scene_json/json_value.h"
#include "assets/scene_json/light_json.h"
#include "assets/scene_json/material_json.h"
#include "assets/scene_json/scene_json.h"
#include "assets/scene_loader.h"
#include "render/scene/builtin_shapes.h"
#include "render/scene/morph.h"
#include "render/scene/scene_animation.h"

namespace pt {
namespace fs = std::filesystem;

namespace {

constexpr uint32_t kMaxResolution = 32768;  // beyond this a typo, not an image: refuse it
constexpr uint32_t kMaxDepth = 4096;

// The world transforms of instances and their inverses must be finite: a zero scale or an
// overflowing product would turn into NaN on every ray that meets the instance.
bool invertible(const Affine3& m) {
    const float det = m.determinant();
    return std::isfinite(det) && det != 0.0f && isFinite(m) && isFinite(inverse(m));
}

ObjectTransform readTransform(const JsonValue& value) {
    ObjectReader reader(value);
    const std::optional<JsonValue> matrix = reader.get("matrix");
    const std::optional<JsonValue> translate = reader.get("translate");
    const std::optional<JsonValue> rotate = reader.get("rotate");
    const std::optional<JsonValue> scale = reader.get("scale");
    reader.finish();
    if (matrix && (translate || rotate || scale)) {
        value.fail("\"matrix\" excludes \"translate\", \"rotate\" and \"scale\"");
    }
    ObjectTransform transform;
    if (matrix) {
        const std::vector<float> m = matrix->asFloats(16);
        std::copy(m.begin(), m.end(), transform.matrix);
        transform.useMatrix = true;
        if (m[3] != 0.0f || m[7] != 0.0f || m[11] != 0.0f || m[15] != 1.0f) {
            matrix->fail("not affine: elements 3, 7, 11, 15 (the last row) must be 0, 0, 0, 1");
        }
    }
    if (translate) transform.translate = translate->asVec3();
    if (rotate) transform.rotateDegrees = rotate->asVec3();
    if (scale) transform.scale = scale->json().is_number() ? Vec3(scale->asFloat()) : scale->asVec3();
    if (!invertible(transform.toAffine())) {
        const JsonValue& culprit = matrix ? *matrix : scale ? *scale : value;
        culprit.fail("the transform is not invertible (a zero or extreme scale)");
    }
    return transform;
}

using MorphWeights = std::map<std::string, std::vector<float>>;  // SceneObject::morphWeights
using ImportKey = std::pair<std::string, MorphWeights>;          // absolute path, morph pose

class SceneJsonReader {
public:
    SceneJsonReader(const std::string& path, const ProgressFn& progress)
        : fileName_(fs::path(path).filename().string()),
          folder_(fs::absolute(path).lexically_normal().parent_path()),
          progress_(progress) {
        scene_.sourcePath = fs::absolute(path).lexically_normal().string();
    }

    Scene read(const Json& document) {
        const JsonValue root(document, "", fileName_);
        ObjectReader reader(root);
        readVersion(reader.require("version"));  // first: a newer file may have keys we lack
        const std::optional<JsonValue> camera = reader.get("camera");
        const std::optional<JsonValue> render = reader.get("render");
        const std::optional<JsonValue> environment = reader.get("environment");
        const std::optional<JsonValue> color = reader.get("color");
        const std::optional<JsonValue> materials = reader.get("materials");
        const std::optional<JsonValue> lights = reader.get("lights");
        const std::optional<JsonValue> objects = reader.get("objects");
        reader.finish();
        if (render) readRender(*render);
        if (camera) readCamera(*camera);
        if (environment) readEnvironment(*environment);
        if (color) readColor(*color);
        if (materials) readMaterials(*materials);
        if (lights) readLights(*lights);  // before the lights of model files, as the writer expects
        if (objects) readObjects(*objects);
        if (!camera) chooseCamera();
        reportProgress(progress_, "load scene", 1.0);
        return std::move(scene_);
    }

private:
    void readVersion(const JsonValue& value) const {
        const int64_t version = value.asInt();
        if (version > kSceneJsonVersion) {
            value.fail(std::to_string(version) + " is newer than the newest version this program reads (" +
                       std::to_string(kSceneJsonVersion) + ")");
        }
        if (version < 1) value.fail("expected a version >= 1, got " + value.describe());
    }

    void readRender(const JsonValue& value) {
        ObjectReader reader(value);
        RenderSettings& render = scene_.render;
        if (auto resolution = reader.get("resolution")) {
            if (!resolution->json().is_array() || resolution->json().size() != 2) {
                resolution->fail("expected [width, height], got " + resolution->describe());
            }
            const std::vector<JsonValue> size = resolution->asArray();
            render.width = size[0].asUint(1, kMaxResolution);
            render.height = size[1].asUint(1, kMaxResolution);
        }
        if (auto depth = reader.get("maxDepth")) render.maxDepth = depth->asUint(1, kMaxDepth);
        if (auto spp = reader.get("spp")) render.spp = spp->asUint(1);
        if (auto seed = reader.get("seed")) render.seed = seed->asUint(0);
        reader.finish();
    }

    void readCamera(const JsonValue& value) {
        ObjectReader reader(value);
        Camera& camera = scene_.camera;
        if (auto position = reader.get("position")) camera.position = position->asVec3();
        if (auto lookAt = reader.get("lookAt")) camera.lookAt = lookAt->asVec3();
        const std::optional<JsonValue> up = reader.get("up");
        if (up) camera.up = up->asVec3();
        if (auto fov = reader.get("fov")) {
            camera.verticalFovDegrees = fov->asFloat();
            if (!(camera.verticalFovDegrees > 0.0f && camera.verticalFovDegrees < 180.0f)) {
                fov->fail("expected a number in (0, 180), got " + fov->describe());
            }
        }
        if (auto aperture = reader.get("aperture")) {
            camera.apertureRadius = aperture->asFloat(NumberRange::NonNegative);
        }
        if (auto focus = reader.get("focusDistance")) {
            camera.focusDistance = focus->asFloat();
            // Kept as given (the writer writes it back), but a plane of focus at or behind the
            // lens is no focus at all: say that the renderer uses the look-at distance.
            if (camera.focusDistance <= 0.0f) {
                scene_.warnings.push_back(
                    fileName_ + ": " + focus->path() + ": " + focus->describe() +
                    " is not a distance in front of the lens; focusing at lookAt instead");
            }
        }
        reader.finish();
        const Vec3 view = camera.lookAt - camera.position;
        if (lengthSquared(view) == 0.0f) value.fail("lookAt equals position: no view direction");
        if (lengthSquared(cross(view, camera.up)) == 0.0f) {
            (up ? *up : value).fail("up is zero or parallel to the view direction");
        }
        scene_.cameraFromFile = true;
    }

    void readEnvironment(const JsonValue& value) {
        ObjectReader reader(value);
        Environment& environment = scene_.environment;
        if (auto color = reader.get("color")) environment.color = color->asVec3(NumberRange::NonNegative);
        if (auto image = reader.get("image")) {
            environment.texture = loadTexture(*image);
            environment.imagePath = scene_.textures[size_t(environment.texture)].sourcePath;
        }
        if (auto intensity = reader.get("intensity")) {
            environment.intensity = intensity->asFloat(NumberRange::NonNegative);
        }
        if (auto rotation = reader.get("rotation")) environment.rotationDegrees = rotation->asFloat();
        reader.finish();
    }

    // {"config": path, "display", "view", "look"}: names are checked against the config when
    // the display is built (the config may be absent from this build), the file here.
    void readColor(const JsonValue& value) {
        ObjectReader reader(value);
        ColorSettings& color = scene_.color;
        if (auto config = reader.get("config")) color.config = resolveFile(*config).string();
        if (auto display = reader.get("display")) color.display = display->asString();
        if (auto view = reader.get("view")) color.view = view->asString();
        if (auto look = reader.get("look")) color.look = look->asString();
        reader.finish();
    }

    void readMaterials(const JsonValue& value) {
        for (const JsonValue& element : value.asArray()) {
            ObjectReader reader(element);
            const JsonValue nameValue = reader.require("name");
            const std::string name = nameValue.asString();
            if (const int32_t existing = findSceneMaterial(scene_, name); existing >= 0) {
                nameValue.fail("duplicate material name \"" + name + "\" (also materials[" +
                               std::to_string(existing) + "])");
            }
            const Material params =
                readMaterialParams(reader, [this](const JsonValue& image) { return loadTexture(image); });
            reader.finish();
            scene_.materials.push_back(NamedMaterial{name, params, -1});
        }
    }

    void readLights(const JsonValue& value) {
        for (const JsonValue& element : value.asArray()) scene_.lights.push_back(readLightJson(element));
    }

    void readObjects(const JsonValue& value) {
        const std::vector<JsonValue> elements = value.asArray();
        addDefaultMaterialIfUsed(elements);
        for (size_t i = 0; i < elements.size(); ++i) {
            reportProgress(progress_, "load scene", double(i) / double(elements.size()));
            readObject(elements[i], int32_t(i));
        }
    }

    // Added before any object so that its index does not depend on which files come first,
    // and a saved scene (which leaves it out) reads back with the same material indices.
    void addDefaultMaterialIfUsed(const std::vector<JsonValue>& objects) {
        const bool used = std::any_of(objects.begin(), objects.end(), [](const JsonValue& o) {
            return o.json().is_object() && o.json().contains("shape") && !o.json().contains("material");
        });
        if (used && findSceneMaterial(scene_, kDefaultMaterialName) < 0) {
            scene_.materials.push_back(NamedMaterial{kDefaultMaterialName, Material{}, -1});
        }
    }

    void readObject(const JsonValue& value, int32_t index) {
        ObjectReader reader(value);
        SceneObject object;
        if (auto name = reader.get("name")) object.name = name->asString();
        const std::optional<JsonValue> file = reader.get("file");
        const std::optional<JsonValue> shape = reader.get("shape");
        if (file && shape) value.fail("\"file\" and \"shape\" exclude each other");
        if (!file && !shape) value.fail("missing key \"file\" or \"shape\"");
        if (auto transform = reader.get("transform")) object.transform = readTransform(*transform);
        const std::optional<JsonValue> material = reader.get("material");
        const std::optional<JsonValue> overrides = reader.get("materialOverrides");
        const std::optional<JsonValue> morphWeights = reader.get("morphWeights");
        const std::optional<JsonValue> variant = reader.get("variant");
        const std::optional<JsonValue> animation = reader.get("animation");
        if (file && material) material->fail("applies to shapes; a file object takes \"materialOverrides\"");
        if (shape && overrides) overrides->fail("applies to file objects; a shape takes \"material\"");
        if (shape && morphWeights)
            morphWeights->fail("applies to file objects; shapes have no morph targets");
        if (shape && variant) variant->fail("applies to file objects; shapes have no material variants");
        if (shape && animation) animation->fail("applies to file objects; shapes have no animations");
        reader.finish();
        if (file) {
            if (overrides) object.materialOverrides = readOverrides(*overrides);
            if (morphWeights) object.morphWeights = readMorphWeights(*morphWeights);
            addFileObject(*file, morphWeights, std::move(object), index);
            if (variant) selectVariant(*variant, index);
            if (animation) selectAnimation(*animation, index);
        } else {
            object.material = material ? material->asString() : kDefaultMaterialName;
            addShapeObject(*shape, material ? *material : value, std::move(object), index);
        }
    }

    // "animation": {"name": one of the file's animations, "time": seconds into it}; the
    // object's rig is posed there.
    void selectAnimation(const JsonValue& value, int32_t index) {
        ObjectReader reader(value);
        const JsonValue nameValue = reader.require("name");
        const std::optional<JsonValue> timeValue = reader.get("time");
        reader.finish();
        const std::string name = nameValue.asString();
        const float time = timeValue ? timeValue->asFloat() : 0.0f;
        SceneObject& object = scene_.objects[size_t(index)];
        const std::string file = fs::path(object.path).filename().string();
        for (size_t r = 0; r < scene_.rigs.size(); ++r) {
            const AnimationRig& rig = scene_.rigs[r];
            if (rig.object != index) continue;
            std::string known;
            for (size_t a = 0; a < rig.animations.size(); ++a) {
                if (rig.animations[a].name == name) {
                    object.animation = name;
                    object.animationTime = time;
                    poseRig(scene_, uint32_t(r), int32_t(a), time);
                    return;
                }
                known += (known.empty() ? "\"" : ", \"") + shortened(rig.animations[a].name) + "\"";
            }
            if (!known.empty()) {
                nameValue.fail("\"" + shortened(name) + "\" is not an animation of " + file +
                               " (its animations: " + shortened(known, 4 * kMaxQuotedChars) + ")");
            }
        }
        value.fail(file + " has no animations");
    }

    // "variant": one of the file's material variants (KHR_materials_variants), by name.
    void selectVariant(const JsonValue& value, int32_t index) {
        const std::string name = value.asString();
        const SceneObject& object = scene_.objects[size_t(index)];
        const auto found = std::find(object.variants.begin(), object.variants.end(), name);
        if (found == object.variants.end()) {
            const std::string file = fs::path(object.path).filename().string();
            if (object.variants.empty()) value.fail(file + " has no material variants");
            std::string known;
            for (const std::string& v : object.variants)
                known += (known.empty() ? "\"" : ", \"") + shortened(v) + "\"";
            value.fail("\"" + shortened(name) + "\" is not a variant of " + file +
                       " (its variants: " + shortened(known, 4 * kMaxQuotedChars) + ")");
        }
        selectObjectVariant(scene_.objects, scene_.instances, uint32_t(index),
                            int32_t(found - object.variants.begin()));
    }

    std::map<std::string, std::string> readOverrides(const JsonValue& value) const {
        if (!value.json().is_object()) value.fail("expected an object, got " + value.describe());
        std::map<std::string, std::string> overrides;
        for (const auto& item : value.json().items()) {
            const JsonValue target(item.value(), value.childPath(item.key()), fileName_);
            overrides[item.key()] = target.asString();
        }
        return overrides;
    }

    // {"mesh name": [w0, w1, ...]}; the counts are checked against the meshes after import.
    MorphWeights readMorphWeights(const JsonValue& value) const {
        if (!value.json().is_object()) value.fail("expected an object, got " + value.describe());
        MorphWeights weights;
        for (const auto& item : value.json().items()) {
            const JsonValue list(item.value(), value.childPath(item.key()), fileName_);
            std::vector<float>& out = weights[item.key()];
            for (const JsonValue& weight : list.asArray()) out.push_back(weight.asFloat());
        }
        return weights;
    }

    // Replaces the default weights of the file's meshes (Scene meshes from `firstMesh` on,
    // added by its import) by the object's; every mesh of a name takes them.
    void applyMorphWeightOverrides(const JsonValue& value, const MorphWeights& weights,
                                   const std::string& path, size_t firstMesh) {
        for (const auto& [name, given] : weights) {
            const JsonValue at(value.json().at(name), value.childPath(name), fileName_);
            bool found = false;
            for (size_t m = firstMesh; m < scene_.meshes.size(); ++m) {
                Mesh& mesh = scene_.meshes[m];
                if (mesh.name != name) continue;
                found = true;
                if (given.size() != mesh.morphTargets.size()) {
                    at.fail("expected " + std::to_string(mesh.morphTargets.size()) +
                            " weights (the mesh's morph targets), got " + std::to_string(given.size()));
                }
                mesh.morphWeights = given;
                applyMorphWeights(mesh);
            }
            if (!found) at.fail(fs::path(path).filename().string() + " has no mesh \"" + name + "\"");
        }
    }

    void addShapeObject(const JsonValue& shape, const JsonValue& materialAt, SceneObject object,
                        int32_t index) {
        const std::string kindName = shape.asString();
        const ObjectKind kinds[] = {ObjectKind::Sphere, ObjectKind::Box, ObjectKind::Quad};
        const auto kind = std::find_if(std::begin(kinds), std::end(kinds),
                                       [&](ObjectKind k) { return kindName == shapeKindName(k); });
        if (kind == std::end(kinds)) {
            shape.fail("unknown shape \"" + kindName + "\" (expected \"sphere\", \"box\" or \"quad\")");
        }
        object.kind = *kind;
        const int32_t material = findSceneMaterial(scene_, object.material);
        if (material < 0) materialAt.fail("unknown material \"" + object.material + "\"");
        Instance instance;
        instance.name = objectDisplayName(object);
        instance.mesh = builtinShapeMesh(scene_, object.kind);
        instance.objectToWorld = object.transform.toAffine();
        instance.materials = {uint32_t(material)};
        instance.object = index;
        scene_.objects.push_back(std::move(object));
        scene_.instances.push_back(std::move(instance));
    }

    void addFileObject(const JsonValue& file, const std::optional<JsonValue>& morphWeights,
                       SceneObject object, int32_t index) {
        const fs::path path = resolveFile(file);
        if (!isModelFile(path.string())) {
            file.fail("unsupported model format \"" + path.extension().string() +
                      "\" (expected .gltf, .glb or .obj)");
        }
        object.kind = ObjectKind::File;
        object.path = path.string();
        const Affine3 objectToWorld = object.transform.toAffine();
        const MorphWeights weights = object.morphWeights;
        scene_.objects.push_back(std::move(object));
        const ImportedFile& imported = importFile(file, morphWeights, {path.string(), weights}, index);
        try {
            instantiateImportedFile(imported, index, scene_);
        } catch (const InputError& e) {
            throw InputError(fileName_ + ": " + e.what());
        }
        if (!fileCamera_ && imported.camera) fileCamera_ = cameraToWorld(*imported.camera, objectToWorld);
    }

    // A file named by several objects is imported once: its meshes are shared and the
    // objects differ only by their instances (this is how scene JSON instances). Meshes
    // hold one morph pose, so objects that pose the file differently import it apart.
    const ImportedFile& importFile(const JsonValue& file, const std::optional<JsonValue>& morphWeights,
                                   const ImportKey& key, int32_t index) {
        const auto cached = importedFiles_.find(key);
        if (cached != importedFiles_.end()) return cached->second;
        const size_t firstMesh = scene_.meshes.size();
        ImportedFile imported;
        try {
            imported = importModelFile(key.first, index, scene_, progress_);
        } catch (const InputError& e) {
            file.fail(e.what());
        }
        if (morphWeights) applyMorphWeightOverrides(*morphWeights, key.second, key.first, firstMesh);
        return importedFiles_.emplace(key, std::move(imported)).first->second;
    }

    // Paths in the JSON are relative to its folder; returned absolute and normalised.
    fs::path resolveFile(const JsonValue& value) const {
        const fs::path given(value.asString());
        const fs::path path = (given.is_absolute() ? given : folder_ / given).lexically_normal();
        std::error_code error;
        if (!fs::exists(path, error)) value.fail("no such file: " + path.string());
        if (!fs::is_regular_file(path, error)) value.fail("not a file: " + path.string());
        return path;
    }

    int32_t loadTexture(const JsonValue& image) {
        const std::string path = resolveFile(image).string();
        const auto cached = textures_.find(path);
        if (cached != textures_.end()) return cached->second;
        Texture texture;
        try {
            texture = readTextureFile(path);
        } catch (const InputError& e) {
            image.fail(e.what());
        }
        texture.sourcePath = path;  // the writer relativises it; keep the normalised form
        if (texture.name.empty()) texture.name = fs::path(path).filename().string();
        texture.object = -1;
        scene_.textures.push_back(std::move(texture));
        return textures_[path] = int32_t(scene_.textures.size() - 1);
    }

    void chooseCamera() {
        scene_.cameraFromFile = fileCamera_.has_value();
        scene_.camera = fileCamera_ ? *fileCamera_ : frameBounds(scene_);
    }

    std::string fileName_;
    fs::path folder_;
    ProgressFn progress_;
    Scene scene_;
    std::map<ImportKey, ImportedFile> importedFiles_;  // (absolute path, morph weights) -> its one import
    std::map<std::string, int32_t> textures_;          // absolute path -> Scene::textures
    std::optional<Camera> fileCamera_;                 // the first file camera, in world space
};

}  // namespace

Scene readSceneJson(const std::string& path, const ProgressFn& progress) {
    const std::string fileName = fs::path(path).filename().string();
    std::error_code error;
    if (!fs::is_regular_file(path, error)) throw InputError(path + ": no such file");
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    if (!in) throw InputError(path + ": cannot read the file");
    const Json document = parseJsonText(text.str(), fileName);
    try {
        return SceneJsonReader(path, progress).read(document);
    } catch (const Json::exception& e) {
        throw InputError(fileName + ": " + e.what());  // a check this reader missed: still name the file
    }
}

Camera withinFileRanges(const Camera& camera) {
    Camera c = camera;
    c.verticalFovDegrees = std::isnan(c.verticalFovDegrees)
                               ? Camera{}.verticalFovDegrees
                               : std::clamp(c.verticalFovDegrees, kMinEditedFov, kMaxEditedFov);
    c.apertureRadius = nearestInRange(c.apertureRadius, NumberRange::NonNegative);
    return c;
}

}  // namespace pt
