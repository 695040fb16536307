#pragma once
// Outliner commands: rename, hide, delete and duplicate scene objects and lights. An object is
// the unit scene JSON saves (a file or a shape), so these act on the object and everything
// it placed (instances, the file's lights). Undo restores the layout exactly.
#include <memory>
#include <string>

#include "editor/edit_command.h"

namespace pt::editor {

std::unique_ptr<EditCommand> renameObject(const Document& doc, uint32_t object, const std::string& name);
// Hidden objects are not traced; hiding is a view state and is not saved in scene JSON.
std::unique_ptr<EditCommand> setObjectHidden(const Document& doc, uint32_t object, bool hidden);
std::unique_ptr<EditCommand> deleteObject(const Document& doc, uint32_t object);
// The copy, named "<name> copy", shares the original's meshes and materials and stands `offset`
// (world) from it, with everything it placed (instances, the file's lights).
std::unique_ptr<EditCommand> duplicateObject(const Document& doc, uint32_t object, Vec3 offset = Vec3(0.0f));
// Where a copy is seen beside the original rather than inside it: along the camera's right or
// left, toward the middle of the view, by the object's width in that direction and a tenth more
// (zero for an object without geometry).
Vec3 duplicateOffset(const Scene& scene, uint32_t object);
// Shows material variant `variant` of a glTF object (KHR_materials_variants; -1: the file's
// default materials); saved with the scene.
std::unique_ptr<EditCommand> setObjectVariant(const Document& doc, uint32_t object, int32_t variant);

std::unique_ptr<EditCommand> renameLight(const Document& doc, uint32_t light, const std::string& name);
std::unique_ptr<EditCommand> deleteLight(const Document& doc, uint32_t light);
std::unique_ptr<EditCommand> duplicateLight(const Document& doc, uint32_t light);

// Whether every instance the object placed is hidden (an object that placed none is not).
bool objectHidden(const Scene& scene, uint32_t object);

}  // namespace pt::editor
