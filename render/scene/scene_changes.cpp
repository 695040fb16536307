#include "render/scene/scene_changes.h"

#include <algorithm>

namespace pt {

TouchedIds TouchedIds::only(std::initializer_list<uint32_t> ids) { return only(std::vector<uint32_t>(ids)); }

TouchedIds TouchedIds::only(std::vector<uint32_t> ids) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    TouchedIds touched;
    touched.every = false;
    touched.ids = std::move(ids);
    return touched;
}

bool TouchedIds::contains(uint32_t id) const {
    return every || std::binary_search(ids.begin(), ids.end(), id);
}

std::vector<uint32_t> TouchedIds::below(uint32_t count) const {
    std::vector<uint32_t> list;
    if (every) {
        list.resize(count);
        for (uint32_t i = 0; i < count; ++i) list[i] = i;
    } else {
        for (const uint32_t id : ids) {
            if (id < count) list.push_back(id);
        }
    }
    return list;
}

void TouchedIds::add(const TouchedIds& other) {
    if (every || other.every) {
        every = true;
        ids.clear();
        return;
    }
    std::vector<uint32_t> merged;
    merged.reserve(ids.size() + other.ids.size());
    std::set_union(ids.begin(), ids.end(), other.ids.begin(), other.ids.end(), std::back_inserter(merged));
    ids = std::move(merged);
}

namespace {

// The ids of one kind after merging: only a side whose bits name the kind contributes.
void mergeKind(TouchedIds& ids, bool had, const TouchedIds& later, bool laterHas) {
    if (!laterHas) return;
    if (had) {
        ids.add(later);
    } else {
        ids = later;
    }
}

}  // namespace

SceneDelta& SceneDelta::operator|=(const SceneDelta& later) {
    mergeKind(materials, has(SceneChanges::Materials), later.materials, later.has(SceneChanges::Materials));
    mergeKind(meshes, has(SceneChanges::Geometry), later.meshes, later.has(SceneChanges::Geometry));
    mergeKind(instances, has(SceneChanges::Transforms), later.instances, later.has(SceneChanges::Transforms));
    mask |= later.mask;
    return *this;
}

SceneDelta SceneDelta::without(SceneChangeMask bits) const {
    SceneDelta kept = *this;
    kept.mask &= ~bits;
    if (!kept.has(SceneChanges::Materials)) kept.materials = {};
    if (!kept.has(SceneChanges::Geometry)) kept.meshes = {};
    if (!kept.has(SceneChanges::Transforms)) kept.instances = {};
    return kept;
}

bool SceneDelta::operator==(const SceneDelta& o) const {
    return mask == o.mask && (!has(SceneChanges::Materials) || materials == o.materials) &&
           (!has(SceneChanges::Geometry) || meshes == o.meshes) &&
           (!has(SceneChanges::Transforms) || instances == o.instances);
}

SceneDelta materialsEdited(std::vector<uint32_t> materials) {
    SceneDelta delta(SceneChanges::Materials);
    delta.materials = TouchedIds::only(std::move(materials));
    return delta;
}

SceneDelta meshesMoved(std::vector<uint32_t> meshes) {
    SceneDelta delta(SceneChanges::Geometry);
    delta.meshes = TouchedIds::only(std::move(meshes));
    return delta;
}

SceneDelta instancesMoved(std::vector<uint32_t> instances) {
    SceneDelta delta(SceneChanges::Transforms);
    delta.instances = TouchedIds::only(std::move(instances));
    return delta;
}

}  // namespace pt
