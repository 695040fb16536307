#include "assets/gltf/gltf_variants.h"

namespace pt {
namespace {

constexpr const char* kExtension = "KHR_materials_variants";
// More than any real file has (product configurators show a handful); each variant costs a
// row of materials in every instance of the file.
constexpr size_t kMaxVariants = 256;

// `object[key]`, or null where `object` is not an object or has no such key.
const tinygltf::Value* member(const tinygltf::Value& object, const char* key) {
    return object.Has(key) ? &object.Get(key) : nullptr;
}

const tinygltf::Value* extensionBlock(const tinygltf::ExtensionMap& extensions) {
    const auto it = extensions.find(kExtension);
    return it == extensions.end() ? nullptr : &it->second;
}

// One mapping's material and variants into `materials`, checked; what is unusable is warned
// about and left out.
void readMapping(const GltfContext& ctx, const tinygltf::Value& mapping, size_t variantCount,
                 const std::string& element, std::vector<int>& materials) {
    const tinygltf::Value* material = member(mapping, "material");
    const tinygltf::Value* variants = member(mapping, "variants");
    if (!material || !material->IsInt() || !variants || !variants->IsArray()) {
        ctx.warn(element, "needs an integer material and an array of variants; ignored");
        return;
    }
    const int index = material->Get<int>();
    if (index < 0 || size_t(index) >= ctx.model().materials.size()) {
        ctx.warn(element, "material " + std::to_string(index) + " does not exist (" +
                              std::to_string(ctx.model().materials.size()) + " in the file); ignored");
        return;
    }
    for (size_t i = 0; i < variants->ArrayLen(); ++i) {
        const tinygltf::Value& variant = variants->Get(int(i));
        if (!variant.IsInt() || variant.Get<int>() < 0 || size_t(variant.Get<int>()) >= variantCount) {
            ctx.warn(element + ".variants[" + std::to_string(i) + "]",
                     "is not a variant of the file (" + std::to_string(variantCount) + " in it); ignored");
            continue;
        }
        materials[size_t(variant.Get<int>())] = index;
    }
}

}  // namespace

std::vector<std::string> gltfVariantNames(const GltfContext& ctx) {
    const tinygltf::Value* block = extensionBlock(ctx.model().extensions);
    if (!block) return {};
    const std::string element = std::string("extensions.") + kExtension + ".variants";
    const tinygltf::Value* variants = member(*block, "variants");
    if (!variants || !variants->IsArray()) {
        ctx.warn(element, "is not an array; material variants ignored");
        return {};
    }
    if (variants->ArrayLen() > kMaxVariants) {
        ctx.warn(element, "lists " + std::to_string(variants->ArrayLen()) + " variants, more than " +
                              std::to_string(kMaxVariants) + "; material variants ignored");
        return {};
    }
    // The specification requires a name. tinygltf drops an empty object ({}) from an array
    // while parsing, so a variant written as {} cannot be seen here, and later variants'
    // indices shift by one: such a file is malformed, and its mappings may then be off.
    std::vector<std::string> names;
    for (size_t i = 0; i < variants->ArrayLen(); ++i) {
        const tinygltf::Value* name = member(variants->Get(int(i)), "name");
        const bool named = name && name->IsString() && !name->Get<std::string>().empty();
        names.push_back(named ? name->Get<std::string>() : "variant " + std::to_string(i));
    }
    return names;
}

std::vector<int> gltfPrimitiveVariantMaterials(const GltfContext& ctx, size_t meshIndex,
                                               size_t primitiveIndex, size_t variantCount) {
    std::vector<int> materials(variantCount, kUnmappedVariant);
    const auto& primitive = ctx.model().meshes[meshIndex].primitives[primitiveIndex];
    const tinygltf::Value* block = extensionBlock(primitive.extensions);
    if (!block || variantCount == 0) return materials;
    const std::string element = gltfPath("meshes", meshIndex) + ".primitives[" +
                                std::to_string(primitiveIndex) + "].extensions." + kExtension + ".mappings";
    const tinygltf::Value* mappings = member(*block, "mappings");
    if (!mappings || !mappings->IsArray()) {
        ctx.warn(element, "is not an array; ignored");
        return materials;
    }
    for (size_t i = 0; i < mappings->ArrayLen(); ++i) {
        readMapping(ctx, mappings->Get(int(i)), variantCount, element + "[" + std::to_string(i) + "]",
                    materials);
    }
    return materials;
}

}  // namespace pt
