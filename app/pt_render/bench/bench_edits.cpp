#include "pt_render/bench/bench_edits.h"

#include <cmath>
#include <cstdio>
#include <functional>

#include "editor/editor_session.h"
#include "editor/scene_edits.h"
#include "render/scene/morph.h"

namespace pt::cli {
namespace {

using editor::EditCommand;
using editor::EditorSession;

// One kind of edit, as the editor would issue it; `run` alternates the value so that every
// run really changes the scene.
struct EditKind {
    std::string name;
    std::function<std::unique_ptr<EditCommand>(const editor::Document&, uint32_t run)> make;
};

int32_t largestTriangleMesh(const Scene& scene) {
    int32_t mesh = -1;
    for (size_t i = 0; i < scene.meshes.size(); ++i) {
        if (scene.meshes[i].kind == GeometryKind::Triangles &&
            (mesh < 0 || scene.meshes[i].positions.size() > scene.meshes[size_t(mesh)].positions.size())) {
            mesh = int32_t(i);
        }
    }
    return mesh;
}

int32_t morphedMesh(const Scene& scene) {
    for (size_t i = 0; i < scene.meshes.size(); ++i) {
        if (hasMorphTargets(scene.meshes[i])) return int32_t(i);
    }
    return -1;
}

std::vector<EditKind> editKinds(const Scene& scene) {
    std::vector<EditKind> kinds;
    if (!scene.materials.empty()) {
        kinds.push_back({"material (roughness slider)", [](const editor::Document& d, uint32_t run) {
                             Material m = d.scene.materials[0].params;
                             m.roughness = run % 2 ? 0.3f : 0.6f;
                             return editor::setMaterial(d, 0, m);
                         }});
    }
    if (!scene.objects.empty()) {
        kinds.push_back({"transform (object)", [](const editor::Document& d, uint32_t run) {
                             ObjectTransform t = d.scene.objects[0].transform;
                             t.translate.x += run % 2 ? 1e-3f : -1e-3f;
                             return editor::setObjectTransform(d, 0, t);
                         }});
    }
    kinds.push_back({"camera (orbit)", [](const editor::Document& d, uint32_t run) {
                         Camera c = d.scene.camera;
                         c.position.x += run % 2 ? 1e-3f : -1e-3f;
                         return editor::setCamera(d, c);
                     }});
    if (const int32_t mesh = morphedMesh(scene); mesh >= 0) {
        kinds.push_back({"morph weight", [mesh](const editor::Document& d, uint32_t run) {
                             std::vector<float> w = d.scene.meshes[size_t(mesh)].morphWeights;
                             w[0] = run % 2 ? 0.75f : 0.25f;
                             return editor::setMorphWeights(d, uint32_t(mesh), w);
                         }});
    }
    if (const int32_t mesh = largestTriangleMesh(scene); mesh >= 0) {
        // What skinning or a sculpt brush would do: every vertex of the largest mesh moves.
        const std::string name =
            "vertices (" + std::to_string(scene.meshes[size_t(mesh)].positions.size()) + ")";
        kinds.push_back({name, [mesh](const editor::Document& d, uint32_t run) {
                             const std::vector<Vec3>& before = d.scene.meshes[size_t(mesh)].positions;
                             std::vector<Vec3> after = before;
                             const float amount = run % 2 ? 1e-4f : -1e-4f;
                             for (size_t i = 0; i < after.size(); ++i)
                                 after[i].x += amount * std::sin(float(i));
                             return editor::makeValueCommand<std::vector<Vec3>>(
                                 "Move vertices", "", SceneChanges::Geometry, before, after,
                                 [mesh](editor::Document& doc, const std::vector<Vec3>& p) {
                                     doc.scene.meshes[size_t(mesh)].positions = p;
                                 });
                         }});
    }
    return kinds;
}

}  // namespace

void benchEdits(const std::string& backendName, Scene scene, const BenchSettings& settings,
                BenchReport& report) {
    const std::vector<EditKind> kinds = editKinds(scene);
    EditorSession session(createBackend(backendName));
    session.adopt(std::move(scene));
    session.execute(editor::setToggles(session.document(), settings.toggles));
    session.sync();
    session.backend().finishBackgroundWork();  // edits on the trees the editor settles on
    session.render(1);
    std::vector<float> frame;
    // Device memory standing in for the editor's OpenGL pixel buffer (mapped through CUDA-GL
    // interop there), so the GPU frame path is timed where there is no display.
    const std::shared_ptr<void> deviceFrame = session.backend().allocateDeviceFrame();
    for (const EditKind& kind : kinds) {
        std::vector<double> toFrame, toApply, toDisplay, toDeviceFrame;
        editor::EditLatency last;
        for (uint32_t run = 0; run <= settings.runs; ++run) {
            // Making the command is the tool's work (a brush computing 10M positions, say), not
            // the editor's: every figure counts from the moment the session gets it, the instant
            // EditLatency counts from, so that they differ only by what follows the samples.
            std::unique_ptr<EditCommand> command = kind.make(session.document(), run + 1);
            const auto start = Clock::now();
            session.execute(std::move(command));
            session.endDrag();
            session.sync();
            session.render(1);
            const double samplesDone = secondsSince(start);
            // The editor's CUDA-GL path: the frame is written into (here: stand-in) GL memory.
            const bool onDevice = deviceFrame && session.backend().copyBeautyToDevice(deviceFrame.get());
            const double deviceDisplayed = secondsSince(start);
            session.readDisplayed(session.document().viewer.aov, session.document().viewer.denoise, frame);
            const double displayed = secondsSince(start);
            last = session.lastEdit();
            if (run == 0) continue;  // warm-up
            toFrame.push_back(last.complete ? last.toFrameSeconds : samplesDone);
            toApply.push_back(last.applySeconds);
            toDisplay.push_back(displayed);
            if (onDevice) toDeviceFrame.push_back(deviceDisplayed);
        }
        const std::string action = last.action.empty() ? "nothing" : last.action;
        char apply[64];
        std::snprintf(apply, sizeof apply, "; command apply %.3g ms", median(toApply) * 1e3);
        report.add({"edit to first frame", kind.name, "samples done", median(toFrame) * 1e3, "ms",
                    "sync: " + action + apply});
        if (!toDeviceFrame.empty()) {
            report.add({"edit to first frame", kind.name, "frame on GPU (interop)",
                        median(toDeviceFrame) * 1e3, "ms", "no host copy"});
        }
        report.add({"edit to first frame", kind.name, "frame on host", median(toDisplay) * 1e3, "ms",
                    "sync " + std::to_string(last.syncSeconds * 1e3) + " ms"});
    }
}

}  // namespace pt::cli
