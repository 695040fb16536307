#pragma once
// How gtest prints a SceneDelta in a failed comparison: its bits in hex and the ids it names.
#include <ostream>

#include "render/scene/scene_changes.h"

namespace pt {

inline void printTouched(const char* kind, const TouchedIds& touched, std::ostream* os) {
    *os << ' ' << kind << '=';
    if (touched.every) {
        *os << "every";
        return;
    }
    *os << '{';
    for (size_t i = 0; i < touched.ids.size(); ++i) *os << (i ? "," : "") << touched.ids[i];
    *os << '}';
}

inline void PrintTo(const SceneDelta& delta, std::ostream* os) {
    *os << "SceneDelta{mask=0x" << std::hex << delta.mask << std::dec;
    if (delta.has(SceneChanges::Materials)) printTouched("materials", delta.materials, os);
    if (delta.has(SceneChanges::Geometry)) printTouched("meshes", delta.meshes, os);
    if (delta.has(SceneChanges::Transforms)) printTouched("instances", delta.instances, os);
    *os << '}';
}

}  // namespace pt
