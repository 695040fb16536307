#pragma once
// The kinds both scene forms name: the editable Scene (scene.h) and the flat RenderScene that
// per-ray code reads (render_scene.h), which must not pull in the editable form's std
// containers (issue 16).
#include <cstdint>

namespace pt {

enum class GeometryKind : uint32_t { Triangles = 0, Spheres = 1 };
enum class WrapMode : uint32_t { Repeat = 0, ClampToEdge = 1, MirroredRepeat = 2 };
enum class TexelFormat : uint32_t { RGBA8 = 0, RGBA32F = 1 };
enum class LightType : uint32_t { Point = 0, Spot = 1, Directional = 2 };

}  // namespace pt
