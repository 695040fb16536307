#pragma once
// The editor's commands on values: each factory reads the current value from the document,
// and returns a command that sets the new one and reports the SceneChanges it implies
// (DESIGN.md, "Data flow"). Drags fold into one undo step through the merge key, which names
// the edited thing (e.g. "material:3"): two different sliders of one material still fold,
// which is what users expect of one continuous gesture.
#include <memory>
#include <string>
#include <vector>

#include "editor/edit_command.h"

namespace pt::editor {

std::unique_ptr<EditCommand> setMaterial(const Document& doc, uint32_t material, const Material& after);
// Moves the object and everything placed under it (its instances and its file's lights). `verb`
// names the step in the history ("Move", "Rotate", "Scale": what the gizmo did).
std::unique_ptr<EditCommand> setObjectTransform(const Document& doc, uint32_t object,
                                                const ObjectTransform& after,
                                                const std::string& verb = "Move");
// For instances no object owns (scenes built in code).
std::unique_ptr<EditCommand> setInstanceTransform(const Document& doc, uint32_t instance,
                                                  const Affine3& after, const std::string& verb = "Move");
std::unique_ptr<EditCommand> setLight(const Document& doc, uint32_t light, const Light& after);
std::unique_ptr<EditCommand> setCamera(const Document& doc, const Camera& after);
std::unique_ptr<EditCommand> setRenderSettings(const Document& doc, const RenderSettings& after);
std::unique_ptr<EditCommand> setEnvironment(const Document& doc, const Environment& after);
// Lights the scene with the equirectangular image at `path`, keeping its strength and rotation.
// The image is decoded here (throws InputError naming the file); it joins Scene::textures when
// the command first applies and stays there through undo, so that redo finds it again.
std::unique_ptr<EditCommand> setEnvironmentImage(const Document& doc, const std::string& path);
std::unique_ptr<EditCommand> setToggles(const Document& doc, const IntegratorToggles& after);
// Display-only (exposure, tone mapper, AOV) and the viewer's sample settings: no reset.
std::unique_ptr<EditCommand> setViewer(const Document& doc, const ViewerSettings& after);
// The scene's OpenColorIO config, display, view and look (saved with it): no reset.
std::unique_ptr<EditCommand> setColorSettings(const Document& doc, const ColorSettings& after);
// Deforms the mesh (a BLAS refit, not a rebuild) and records the weights on the objects that
// place it, so saving keeps them.
std::unique_ptr<EditCommand> setMorphWeights(const Document& doc, uint32_t mesh,
                                             const std::vector<float>& after);

}  // namespace pt::editor
