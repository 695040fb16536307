// Inspector: the selection's properties. Objects: name, transform, visibility, the materials
// of the picked instance (every parameter, per-slot texture on/off) and morph target weights.
// Lights: colour, intensity, placement and cone. Each change is one command; a drag is one
// undo step.
#include <string>

#include "editor/object_edits.h"
#include "editor/scene_edits.h"
#include "editor/ui/widgets.h"
#include "render/scene/morph.h"

namespace pt::editor {
namespace {

bool textureToggle(EditorUi& ui, uint32_t material, int slot, const char* label, TextureRef& ref) {
    const Scene& scene = ui.doc().scene;
    auto& off = ui.switchedOffTextures;
    const auto key = std::make_pair(material, slot);
    const bool known = ref.present() || off.count(key);
    if (!known) return false;
    bool on = ref.present();
    const std::string name = ref.present() ? scene.textures[size_t(ref.texture)].name : std::string("off");
    const std::string text = std::string(label) + " texture (" + name + ")";
    if (!checkbox(text.c_str(), &on)) return false;
    if (on) {
        ref.texture = off[key];
        off.erase(key);
    } else {
        off[key] = ref.texture;
        ref.texture = -1;
    }
    return true;
}

void materialEditor(EditorUi& ui, uint32_t index) {
    const Scene& scene = ui.doc().scene;
    Material m = scene.materials[index].params;
    bool changed = false;
    ImGui::PushID(int(index));
    changed |= colorEdit(ui, "Base color", &m.baseColor);
    changed |= textureToggle(ui, index, 0, "Base color", m.baseColorTexture);
    changed |= sliderFloat(ui, "Metallic", &m.metallic, 0.0f, 1.0f);
    changed |= sliderFloat(ui, "Roughness", &m.roughness, 0.0f, 1.0f);
    changed |= textureToggle(ui, index, 1, "Metallic-roughness", m.metallicRoughnessTexture);
    changed |= sliderFloat(ui, "Specular", &m.specular, 0.0f, 1.0f);
    changed |= colorEdit(ui, "Specular color", &m.specularColor);
    changed |= sliderFloat(ui, "IOR", &m.ior, 1.0f, 4.0f);
    changed |= sliderFloat(ui, "Transmission", &m.transmission, 0.0f, 1.0f);
    changed |= textureToggle(ui, index, 4, "Transmission", m.transmissionTexture);
    changed |= sliderFloat(ui, "Clearcoat", &m.clearcoat, 0.0f, 1.0f);
    changed |= sliderFloat(ui, "Clearcoat roughness", &m.clearcoatRoughness, 0.0f, 1.0f);
    changed |= sliderFloat(ui, "Diffuse transmission", &m.diffuseTransmission, 0.0f, 1.0f);
    changed |= textureToggle(ui, index, 5, "Diffuse transmission", m.diffuseTransmissionTexture);
    changed |= colorEdit(ui, "Diffuse transmission color", &m.diffuseTransmissionColor);
    changed |= textureToggle(ui, index, 6, "Diffuse transmission color", m.diffuseTransmissionColorTexture);
    changed |= colorEdit(ui, "Sheen color", &m.sheenColor);
    changed |= textureToggle(ui, index, 7, "Sheen color", m.sheenColorTexture);
    changed |= sliderFloat(ui, "Sheen roughness", &m.sheenRoughness, 0.0f, 1.0f);
    changed |= textureToggle(ui, index, 8, "Sheen roughness", m.sheenRoughnessTexture);
    changed |= sliderFloat(ui, "Anisotropy", &m.anisotropyStrength, 0.0f, 1.0f);
    changed |= sliderAngle(ui, "Anisotropy rotation", &m.anisotropyRotation, -180.0f, 180.0f);
    changed |= textureToggle(ui, index, 9, "Anisotropy", m.anisotropyTexture);
    changed |= sliderFloat(ui, "Iridescence", &m.iridescence, 0.0f, 1.0f);
    changed |= textureToggle(ui, index, 10, "Iridescence", m.iridescenceTexture);
    changed |= sliderFloat(ui, "Iridescence IOR", &m.iridescenceIor, 1.0f, 2.5f);
    changed |=
        sliderFloat(ui, "Iridescence thickness min (nm)", &m.iridescenceThicknessMin, 0.0f, 1200.0f, "%.0f");
    changed |=
        sliderFloat(ui, "Iridescence thickness max (nm)", &m.iridescenceThicknessMax, 0.0f, 1200.0f, "%.0f");
    changed |= textureToggle(ui, index, 11, "Iridescence thickness", m.iridescenceThicknessTexture);
    // Ctrl+click types a value past the slider's end (glTF allows any dispersion >= 0).
    changed |= sliderFloat(ui, "Dispersion (20/Abbe)", &m.dispersion, 0.0f, 1.0f);
    changed |= sliderFloat(ui, "Subsurface", &m.subsurface, 0.0f, 1.0f);
    changed |= colorEdit(ui, "Subsurface color", &m.subsurfaceColor);
    // Mean free path in world units, scaled per channel: logarithmic, as skin (1e-3) and wax
    // (1e-1) are both in reach.
    changed |= sliderFloat(ui, "Subsurface radius", &m.subsurfaceRadius, 1e-4f, 10.0f, "%.4f",
                           ImGuiSliderFlags_Logarithmic);
    changed |= colorEdit(ui, "Subsurface radius scale", &m.subsurfaceRadiusScale);
    changed |= colorEdit(ui, "Emission", &m.emission);
    changed |= sliderFloat(ui, "Emission strength", &m.emissionStrength, 0.0f, 1000.0f, "%.3f",
                           ImGuiSliderFlags_Logarithmic);
    changed |= textureToggle(ui, index, 3, "Emission", m.emissiveTexture);
    changed |= textureToggle(ui, index, 2, "Normal", m.normalTexture);
    changed |= sliderFloat(ui, "Normal scale", &m.normalScale, 0.0f, 2.0f);
    bool unlit = m.unlit != 0;
    if (checkbox("Unlit (shows its base color as is)", &unlit)) {
        m.unlit = unlit ? 1u : 0u;
        changed = true;
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("KHR_materials_unlit: baked or stylised looks; no light, no shading");
    if (ImGui::TreeNode("Volume and alpha")) {
        changed |= sliderFloat(ui, "Thickness", &m.thickness, 0.0f, 10.0f);
        changed |= colorEdit(ui, "Attenuation color", &m.attenuationColor);
        changed |= dragFloat(ui, "Attenuation distance", &m.attenuationDistance, 0.01f, 1e-4f, kInf);
        changed |= colorEdit(ui, "Scatter color", &m.scatterColor);
        changed |= sliderFloat(ui, "Scatter anisotropy", &m.scatterAnisotropy, -0.99f, 0.99f);
        changed |= sliderFloat(ui, "Alpha", &m.alpha, 0.0f, 1.0f);
        int mode = int(m.alphaMode);
        const bool picked = ImGui::Combo("Alpha mode", &mode, "opaque\0mask\0blend\0");
        tooltipIfCut("Alpha mode");
        if (picked) {
            m.alphaMode = AlphaMode(mode);
            changed = true;
        }
        changed |= sliderFloat(ui, "Alpha cutoff", &m.alphaCutoff, 0.0f, 1.0f);
        bool doubleSided = m.doubleSided != 0;
        if (checkbox("Double sided", &doubleSided)) {
            m.doubleSided = doubleSided ? 1u : 0u;
            changed = true;
        }
        ImGui::TreePop();
    }
    ImGui::PopID();
    if (changed) ui.apply(setMaterial(ui.doc(), index, m));
}

void transformEditor(EditorUi& ui, uint32_t object) {
    ObjectTransform t = ui.doc().scene.objects[object].transform;
    if (t.useMatrix) {
        ImGui::TextWrapped("Placed by a 4x4 matrix in the scene file; edit it there.");
        return;
    }
    bool changed = false;
    changed |= dragVec3(ui, "Translate", &t.translate, 0.01f);
    changed |= dragVec3(ui, "Rotate (deg)", &t.rotateDegrees, 0.5f, "%.1f");
    changed |= dragVec3(ui, "Scale", &t.scale, 0.01f);
    if (changed) ui.apply(setObjectTransform(ui.doc(), object, t));
}

void morphEditor(EditorUi& ui, uint32_t mesh) {
    const Mesh& m = ui.doc().scene.meshes[mesh];
    if (!hasMorphTargets(m) || !ImGui::CollapsingHeader("Morph targets", ImGuiTreeNodeFlags_DefaultOpen))
        return;
    std::vector<float> weights = m.morphWeights;
    bool changed = false;
    for (size_t t = 0; t < weights.size(); ++t) {
        ImGui::PushID(int(t));
        changed |= sliderFloat(ui, m.morphTargets[t].name.c_str(), &weights[t], 0.0f, 1.0f);
        ImGui::PopID();
    }
    if (ImGui::Button("Reset to the file's pose") && m.defaultMorphWeights.size() == weights.size()) {
        weights = m.defaultMorphWeights;
        changed = true;
        ui.endDrag();
    }
    if (changed) ui.apply(setMorphWeights(ui.doc(), mesh, weights));
}

// glTF KHR_materials_variants: the file's variants, and its default materials first.
void variantEditor(EditorUi& ui, uint32_t object) {
    const SceneObject& o = ui.doc().scene.objects[object];
    if (o.variants.empty()) return;
    const char* shown = o.variant >= 0 ? o.variants[size_t(o.variant)].c_str() : "(default materials)";
    if (!ImGui::BeginCombo("Material variant", shown)) {
        tooltipIfCut("Material variant");
        return;
    }
    int32_t chosen = o.variant;
    for (int32_t v = -1; v < int32_t(o.variants.size()); ++v) {
        ImGui::PushID(v);
        if (ImGui::Selectable(v >= 0 ? o.variants[size_t(v)].c_str() : "(default materials)",
                              v == o.variant)) {
            chosen = v;
        }
        ImGui::PopID();
    }
    ImGui::EndCombo();
    if (chosen != o.variant) ui.apply(setObjectVariant(ui.doc(), object, chosen));  // invalidates `o`
}

void objectInspector(EditorUi& ui) {
    const Scene& scene = ui.doc().scene;
    const uint32_t object = uint32_t(ui.selection.index);
    if (object >= scene.objects.size()) return;
    std::string name = scene.objects[object].name;
    if (inputName("Name", name)) ui.apply(renameObject(ui.doc(), object, name));
    bool hidden = objectHidden(scene, object);
    if (checkbox("Hidden", &hidden)) ui.apply(setObjectHidden(ui.doc(), object, hidden));
    transformEditor(ui, object);
    variantEditor(ui, object);
    const int32_t instance = ui.selection.instance;
    if (instance < 0 || size_t(instance) >= scene.instances.size()) return;
    const Instance& inst = scene.instances[size_t(instance)];
    const Mesh& mesh = scene.meshes[inst.mesh];
    const uint32_t primitives = mesh.primitiveCount();
    const char* what = mesh.kind == GeometryKind::Spheres ? (primitives == 1 ? "sphere" : "spheres")
                                                          : (primitives == 1 ? "triangle" : "triangles");
    ImGui::Text("Instance: %s (%u %s)", inst.name.c_str(), primitives, what);
    morphEditor(ui, inst.mesh);
    for (size_t slot = 0; slot < inst.materials.size(); ++slot) {
        const uint32_t material = inst.materials[slot];
        const std::string header =
            "Material: " + scene.materials[material].name + "##" + std::to_string(slot);
        if (ImGui::CollapsingHeader(header.c_str(), ImGuiTreeNodeFlags_DefaultOpen))
            materialEditor(ui, material);
    }
}

void instanceInspector(EditorUi& ui) {
    const Scene& scene = ui.doc().scene;
    const uint32_t instance = uint32_t(ui.selection.index);
    if (instance >= scene.instances.size()) return;
    const Instance& inst = scene.instances[instance];
    ImGui::Text("%s", inst.name.c_str());
    Vec3 position = inst.objectToWorld.translation();
    if (dragVec3(ui, "Position", &position, 0.01f)) {
        Affine3 m = inst.objectToWorld;
        for (int r = 0; r < 3; ++r) m.rows[r].w = position[r];
        ui.apply(setInstanceTransform(ui.doc(), instance, m));
    }
    morphEditor(ui, inst.mesh);
    for (uint32_t material : inst.materials) {
        if (ImGui::CollapsingHeader(scene.materials[material].name.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
            materialEditor(ui, material);
        }
    }
}

void lightInspector(EditorUi& ui) {
    const Scene& scene = ui.doc().scene;
    const uint32_t index = uint32_t(ui.selection.index);
    if (index >= scene.lights.size()) return;
    Light l = scene.lights[index];
    bool changed = false;
    static const char* kTypes[] = {"point", "spot", "directional"};
    ImGui::Text("%s light", kTypes[uint32_t(l.type) % 3]);
    changed |= colorEdit(ui, "Color", &l.color);
    changed |= sliderFloat(ui, l.type == LightType::Directional ? "Intensity (lux)" : "Intensity (cd)",
                           &l.intensity, 0.0f, 1e5f, "%.3f", ImGuiSliderFlags_Logarithmic);
    if (l.type != LightType::Directional) changed |= dragVec3(ui, "Position", &l.position, 0.01f);
    if (l.type != LightType::Point) changed |= dragVec3(ui, "Direction", &l.direction, 0.01f);
    if (l.type == LightType::Spot) {
        changed |= sliderFloat(ui, "Inner cone (deg)", &l.innerConeDegrees, 0.0f, l.outerConeDegrees);
        changed |= sliderFloat(ui, "Outer cone (deg)", &l.outerConeDegrees, 0.1f, 90.0f);
    }
    ImGui::TextDisabled("Punctual lights have no size; area lights are emissive objects.");
    if (changed) ui.apply(setLight(ui.doc(), index, l));
}

}  // namespace

void drawInspector(EditorUi& ui) {
    if (!ImGui::CollapsingHeader("Inspector", ImGuiTreeNodeFlags_DefaultOpen)) return;
    switch (ui.selection.kind) {
        case Selection::Kind::Object: objectInspector(ui); break;
        case Selection::Kind::Instance: instanceInspector(ui); break;
        case Selection::Kind::Light: lightInspector(ui); break;
        case Selection::Kind::Camera: ImGui::TextDisabled("The camera is edited in the Camera panel."); break;
        default: ImGui::TextDisabled("Click an object in the viewport or the Outliner."); break;
    }
}

}  // namespace pt::editor
