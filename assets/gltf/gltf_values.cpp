#include "assets/gltf/gltf_values.h"

#include <cfloat>
#include <cmath>

namespace pt {
namespace {

// Every number lands in a float; beyond FLT_MAX the conversion is undefined, not infinite.
bool fitsFloat(double v) { return std::isfinite(v) && std::abs(v) <= double(FLT_MAX); }

}  // namespace

double gltfNumber(const GltfContext& ctx, const tinygltf::Value& object, const char* key, double fallback,
                  const std::string& element) {
    if (!object.IsObject() || !object.Has(key)) return fallback;
    const tinygltf::Value& value = object.Get(key);
    if (!value.IsNumber() || !fitsFloat(value.GetNumberAsDouble())) {
        ctx.fail(element + "." + key, "expected a finite number");
    }
    return value.GetNumberAsDouble();
}

std::vector<double> gltfNumbers(const GltfContext& ctx, const tinygltf::Value& object, const char* key,
                                std::vector<double> fallback, const std::string& element) {
    if (!object.IsObject() || !object.Has(key)) return fallback;
    const tinygltf::Value& value = object.Get(key);
    const std::string where = element + "." + key;
    if (!value.IsArray() || value.ArrayLen() != fallback.size()) {
        ctx.fail(where, "expected " + std::to_string(fallback.size()) + " numbers");
    }
    for (size_t i = 0; i < fallback.size(); ++i) {
        const tinygltf::Value& item = value.Get(int(i));
        if (!item.IsNumber() || !fitsFloat(item.GetNumberAsDouble())) {
            ctx.fail(where, "expected " + std::to_string(fallback.size()) + " finite numbers");
        }
        fallback[i] = item.GetNumberAsDouble();
    }
    return fallback;
}

void checkGltfNumbers(const GltfContext& ctx, const std::vector<double>& values, size_t count,
                      const std::string& element) {
    if (values.size() != count) {
        ctx.fail(element,
                 "expected " + std::to_string(count) + " numbers, got " + std::to_string(values.size()));
    }
    for (double v : values) {
        if (!fitsFloat(v)) ctx.fail(element, "expected finite numbers");
    }
}

}  // namespace pt
