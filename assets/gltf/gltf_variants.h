#pragma once
// glTF KHR_materials_variants: the file's named variants (a chair in fabric or leather) and,
// per primitive, the material each variant gives it. The extension is optional by nature: a
// viewer that ignores it shows the default materials, so a malformed mapping is ignored with
// a warning instead of failing the file. Internal to pt_assets.
#include <string>
#include <vector>

#include "assets/gltf/gltf_context.h"

namespace pt {

// A variant the primitive does not map: it keeps its default material.
constexpr int kUnmappedVariant = -2;

// The variants' names in file order ("variant i" for one without a name); empty without the
// extension, or (with a warning) when its list is malformed or longer than 256.
std::vector<std::string> gltfVariantNames(const GltfContext& ctx);

// Per variant (of `variantCount`), the glTF material primitive `primitiveIndex` of mesh
// `meshIndex` takes under it, or kUnmappedVariant.
std::vector<int> gltfPrimitiveVariantMaterials(const GltfContext& ctx, size_t meshIndex,
                                               size_t primitiveIndex, size_t variantCount);

}  // namespace pt
