// pt_editor_latency: how long an edit made with the mouse takes to reach the screen, in the real
// editor window (issue 22). Starts `pathtracer SCENE --latency-log` under a private Xvfb, then
// drags as a user would, one small step at a time: the camera (right-drag in the viewport), the
// object's Translate X field, its first material's Roughness slider and, where its mesh has
// them, the first morph target's weight. Each step waits until the editor logs the swapped frame
// that shows it (editor/screen_latency.h), so steps do not queue behind each other.
//
// Two figures per step: the editor's own, from the event reaching the window (its GLFW callback)
// to the finished swap; and the driver's, from just before it starts `xdotool mousemove` (a
// process start, ~1 ms, included) to the same swap. Both clocks are CLOCK_MONOTONIC.
//
// Every edit the editor logs must be of the kind the step meant (its label names the object,
// material or morph target): a layout that moved (editor_layout.h) fails the run with a message
// instead of measuring the wrong widget. Screenshots (F12) of the first frame and of the end
// state go to --out. Run on the GPU by render/backend/cuda/editor_on_gpu.sh.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "assets/scene_loader.h"
#include "editor/editor_layout.h"
#include "editor/x11_session.h"
#include "render/scene/morph.h"

namespace pt::test {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using nlohmann::json;

#if defined(PT_EDITOR_APP)
constexpr const char* kEditorApp = PT_EDITOR_APP;  // tests/CMakeLists.txt
#else
constexpr const char* kEditorApp = "pathtracer";
#endif

constexpr const char* kUsage =
    "usage: pt_editor_latency SCENE [--backend cpu|cuda] [--size WxH] [--runs N] [--object NAME] [--out "
    "DIR]\n"
    "  --backend  the editor's renderer (default cpu; cuda draws with the GPU's GL too)\n"
    "  --size     the render's size (default 960x540); the window is that plus the panels\n"
    "  --runs     steps measured per edit kind (default 12)\n"
    "  --object   the object to edit, by name (default: the first object)\n"
    "  --out      folder for the editor's log, its output and the screenshots (default: a temporary one)\n"
    "  --no-frame-wait  passed to the editor: its swaps do not wait for the samples of that frame's edits\n"
    "  --follow-viewport  no --size for the editor: the render follows the viewport, as by default\n";

struct Options {
    std::string scene, backend = "cpu", object, out;
    uint32_t width = 960, height = 540;
    int runs = 12;
    bool frameWait = true;
    bool followViewport = false;
};

int64_t nowNs() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now().time_since_epoch()).count();
}
void sleepSeconds(double s) { std::this_thread::sleep_for(std::chrono::duration<double>(s)); }

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The editor's --latency-log, read as it grows.
class LogReader {
public:
    explicit LogReader(fs::path path) : path_(std::move(path)) {}
    // Lines completed since the last call.
    std::vector<json> poll() {
        std::ifstream in(path_, std::ios::binary);
        if (!in) return {};
        in.seekg(std::streamoff(offset_));
        std::vector<json> lines;
        std::string line;
        while (std::getline(in, line)) {
            if (in.eof()) break;  // a line still being written
            offset_ += line.size() + 1;
            lines.push_back(json::parse(line, nullptr, false));
        }
        return lines;
    }

private:
    fs::path path_;
    size_t offset_ = 0;
};

// One kind of edit: where its drag starts, how far each step moves, and what its logged edits
// must be called.
struct EditKind {
    std::string name;
    Point start;
    float step = 8.0f;     // pixels a step, to the right
    int button = 1;        // 3: the right button (the camera's orbit)
    std::string expected;  // a logged edit's label must hold it
    // The pointer stays within [lo, hi] (a slider's ends): a step that would leave turns back.
    float lo = -1e9f, hi = 1e9f;
};

struct Step {
    double editorMs = 0, driverMs = 0, uiFrameMs = 0;
    std::string sync, framePath;
};

class Driver {
public:
    explicit Driver(Options o) : o_(std::move(o)), log_(fs::path(o_.out) / "latency.jsonl") {}

    int run() {
        LoadResult loaded = loadScene(o_.scene);
        if (!loaded.ok()) return fail(loaded.error);
        scene_ = std::move(*loaded.scene);
        if (!startEditor()) return 1;
        std::printf("scene %s, backend %s, render %ux%u, window %.0fx%.0f, frame wait %s\n", o_.scene.c_str(),
                    o_.backend.c_str(), o_.width, o_.height, layout_->width, layout_->height,
                    o_.frameWait ? "on" : "off (--no-frame-wait)");
        if (!waitForFirstFrame()) return 1;
        sleepSeconds(2.0);
        screenshot("first");
        const std::vector<EditKind> kinds = editKinds();
        if (kinds.empty()) return 1;
        std::printf("%-16s %6s %10s %10s %10s %10s %9s  %s\n", "edit", "steps", "editor ms", "driver ms",
                    "min ms", "max ms", "UI ms", "sync / frame path");
        for (const EditKind& kind : kinds) {
            if (!measure(kind)) return 1;
        }
        sleepSeconds(1.0);
        screenshot("end");
        // A smaller window: the viewport and its frames follow (interop buffers re-registered at
        // the new size where the render follows the viewport); the screenshot shows the result.
        xdo({"windowsize", window_, std::to_string(int(layout_->width) - 240),
             std::to_string(int(layout_->height) - 120)});
        sleepSeconds(2.0);
        screenshot("after a resize");
        std::printf("GL: %s\n", glRenderer_.c_str());
        return 0;
    }

private:
    int fail(const std::string& message) {
        std::fprintf(stderr, "pt_editor_latency: %s\n", message.c_str());
        const fs::path editorLog = fs::path(o_.out) / "editor.log";
        if (fs::exists(editorLog)) {
            std::ifstream in(editorLog);
            std::string line;
            while (std::getline(in, line)) std::fprintf(stderr, "  editor: %s\n", line.c_str());
        }
        return 1;
    }

    bool xdo(const std::vector<std::string>& args) {
        const CommandResult r = x_->xdotool(args);
        if (r.status != 0) fail("xdotool " + args.front() + " failed: " + r.output);
        return r.status == 0;
    }
    bool moveTo(Point p) {
        return xdo({"mousemove", "--window", window_, std::to_string(int(std::lround(p.x))),
                    std::to_string(int(std::lround(p.y)))});
    }
    void click(Point p) {
        moveTo(p);
        sleepSeconds(0.3);
        xdo({"mousedown", "1"});
        sleepSeconds(0.3);
        xdo({"mouseup", "1"});
        sleepSeconds(0.5);
    }

    bool startEditor() {
        std::string error;
        const uint32_t w = std::max(o_.width, 640u) + uint32_t(kPanelWidth),
                       h = std::max(o_.height, 640u) + 40;
        const std::string screen =
            std::to_string(std::max(w, 1280u) + 64) + "x" + std::to_string(std::max(h, 1024u) + 64) + "x24";
        x_ = X11Session::start((fs::path(o_.out) / "xvfb.log").string(), 20.0, error, screen);
        if (!x_) return fail(error) == 0;
        std::vector<std::string> env{x_->displayEnv(),
                                     "XDG_CONFIG_HOME=" + (fs::path(o_.out) / "config").string()};
        if (o_.backend == "cpu") env.push_back("LIBGL_ALWAYS_SOFTWARE=1");
        const std::string size = std::to_string(o_.width) + "x" + std::to_string(o_.height);
        std::vector<std::string> args{kEditorApp,      o_.scene,
                                      "--backend",     o_.backend,
                                      "--screenshot",  (fs::path(o_.out) / "shot.png").string(),
                                      "--latency-log", (fs::path(o_.out) / "latency.jsonl").string()};
        if (!o_.followViewport) args.insert(args.end(), {"--size", size});
        if (!o_.frameWait) args.push_back("--no-frame-wait");
        editor_ = std::make_unique<ChildProcess>(args, env, (fs::path(o_.out) / "editor.log").string());
        const auto start = Clock::now();
        while (window_.empty() && Clock::now() - start < std::chrono::seconds(60) && editor_->running()) {
            const CommandResult r = x_->xdotool({"search", "--onlyvisible", "--name", " - pathtracer$"});
            if (r.status == 0)
                window_ = r.output.substr(0, r.output.find('\n'));
            else
                sleepSeconds(0.2);
        }
        if (window_.empty()) return fail("no pathtracer window within 60 s") == 0;
        xdo({"windowfocus", "--sync", window_});
        const std::string geometry = x_->xdotool({"getwindowgeometry", "--shell", window_}).output;
        const auto field = [&](const std::string& name) {
            const size_t at = geometry.find(name + "=");
            return at == std::string::npos ? 0.0f : std::stof(geometry.substr(at + name.size() + 1));
        };
        const float width = field("WIDTH"), height = field("HEIGHT");
        if (o_.followViewport) {  // the render fills the viewport (its size in pixels)
            o_.width = uint32_t(std::max(1.0f, width - kPanelWidth));
            o_.height = uint32_t(std::max(1.0f, height - kFrameHeight - kStatusBarHeight));
        }
        layout_.emplace(width, height, o_.width, o_.height);
        return moveTo(layout_->restingPoint());
    }

    bool waitForFirstFrame() {
        const auto start = Clock::now();
        while (Clock::now() - start < std::chrono::seconds(300)) {
            for (const json& line : log_.poll()) {
                if (line.value("event", "") == "gl")
                    glRenderer_ = line.value("renderer", "") + ", " + line.value("version", "");
                if (line.value("event", "") == "first_frame") {
                    std::printf("first frame: %s\n", line.value("frame_path", "").c_str());
                    return true;
                }
            }
            if (!editor_->running()) return fail("the editor ended before its first frame") == 0;
            sleepSeconds(0.05);
        }
        return fail("no first frame within 300 s") == 0;
    }

    void screenshot(const std::string& what) {
        const fs::path path =
            fs::path(o_.out) / (shots_ == 0 ? "shot.png" : "shot-" + std::to_string(shots_) + ".png");
        ++shots_;
        xdo({"keydown", "F12"});
        const auto start = Clock::now();
        while (!fs::exists(path) && Clock::now() - start < std::chrono::seconds(20)) sleepSeconds(0.02);
        xdo({"keyup", "F12"});
        sleepSeconds(0.3);
        std::printf("screenshot (%s): %s%s\n", what.c_str(), path.string().c_str(),
                    fs::exists(path) ? "" : " MISSING");
    }

    // The object the edits act on, its Outliner row and what the Inspector shows for it.
    struct Target {
        uint32_t object = 0;
        const Instance* instance = nullptr;
        InspectedObject inspected;
        bool matrix = false;
    };

    std::optional<Target> target() {
        Target t;
        if (!o_.object.empty()) {
            const auto it = std::find_if(scene_.objects.begin(), scene_.objects.end(),
                                         [&](const SceneObject& so) { return so.name == o_.object; });
            if (it == scene_.objects.end())
                return fail("no object named '" + o_.object + "' in " + o_.scene), std::nullopt;
            t.object = uint32_t(it - scene_.objects.begin());
        }
        if (scene_.objects.empty()) return fail(o_.scene + " has no objects"), std::nullopt;
        // The Outliner shows about nine rows without scrolling.
        if (t.object >= 8)
            return fail("object " + std::to_string(t.object) + " is below the Outliner's fold"), std::nullopt;
        for (const Instance& i : scene_.instances) {
            if (i.object == int32_t(t.object)) {
                t.instance = &i;
                break;
            }
        }
        const SceneObject& so = scene_.objects[t.object];
        t.matrix = so.transform.useMatrix;
        t.inspected.variants = !so.variants.empty();
        if (t.instance) {
            t.inspected.morphTargets = uint32_t(scene_.meshes[t.instance->mesh].morphTargets.size());
            if (!t.instance->materials.empty())
                t.inspected.baseColorTexture =
                    scene_.materials[t.instance->materials[0]].params.baseColorTexture.present();
        }
        return t;
    }

    std::vector<EditKind> editKinds() {
        std::vector<EditKind> kinds;
        kinds.push_back({"camera orbit", layout_->viewportCentre(), 6.0f, 3, "Camera"});
        const std::optional<Target> t = target();
        if (!t) return {};
        const SceneObject& so = scene_.objects[t->object];
        // Select the object: its Outliner row (row 0 is the camera).
        click({layout_->panelX() + 60.0f, layout_->outlinerRowCentreY(1 + int(t->object))});
        moveTo(layout_->restingPoint());
        sleepSeconds(0.5);
        const Layout& l = *layout_;
        if (!t->matrix) {
            // Translate, the third row: its X field is the first third of the item's width.
            const float y = l.inspectorTop() + 2 * kRow + 0.5f * kFrameHeight;
            kinds.push_back({"object move", {l.sliderLeft() + 20.0f, y}, 4.0f, 1, so.name});
        } else {
            std::printf(
                "object move: skipped (%s is placed by a matrix, which the Inspector does not edit)\n",
                so.name.c_str());
        }
        if (t->instance && !t->instance->materials.empty()) {
            const Material& m = scene_.materials[t->instance->materials[0]].params;
            const float y = l.roughnessCentreY(t->inspected) + (t->matrix ? kTextRow - 3 * kRow : 0.0f);
            kinds.push_back({"material",
                             {l.sliderX(m.roughness), y},
                             6.0f,
                             1,
                             "material " + scene_.materials[t->instance->materials[0]].name,
                             l.sliderX(0.0f),
                             l.sliderX(1.0f)});
        }
        if (t->inspected.morphTargets > 0) {
            const Mesh& mesh = scene_.meshes[t->instance->mesh];
            const float y = l.morphSliderCentreY(t->inspected, 0) + (t->matrix ? kTextRow - 3 * kRow : 0.0f);
            kinds.push_back({"morph weight",
                             {l.sliderX(mesh.morphWeights.at(0)), y},
                             6.0f,
                             1,
                             "Morph " + mesh.name,
                             l.sliderX(0.0f),
                             l.sliderX(1.0f)});
        } else {
            std::printf("morph weight: skipped (the object's mesh has no morph targets)\n");
        }
        return kinds;
    }

    // The next logged edit after `sentNs`, within `seconds`; every edit logged meanwhile must be
    // of the kind's label.
    std::optional<Step> awaitEdit(const EditKind& kind, int64_t sentNs, double seconds) {
        const auto start = Clock::now();
        while (Clock::now() - start < std::chrono::duration<double>(seconds)) {
            for (const json& line : log_.poll()) {
                if (!line.contains("edit")) continue;
                const std::string label = line.value("edit", "");
                if (label.find(kind.expected) == std::string::npos) {
                    wrongLabel_ = label;
                    return std::nullopt;
                }
                if (line.value("input_ns", int64_t(0)) < sentNs) continue;  // an earlier step's
                Step s;
                s.editorMs = line.value("input_to_swap_ms", 0.0);
                s.driverMs = double(line.value("swap_ns", int64_t(0)) - sentNs) * 1e-6;
                s.uiFrameMs = line.value("ui_frame_ms", 0.0);
                s.sync = line.value("sync", "");
                s.framePath = line.value("frame_path", "");
                return s;
            }
            sleepSeconds(0.001);
        }
        return std::nullopt;
    }

    bool measure(const EditKind& kind) {
        log_.poll();  // what came before
        moveTo(kind.start);
        sleepSeconds(0.3);
        xdo({"mousedown", std::to_string(kind.button)});
        sleepSeconds(0.3);
        std::vector<double> editor, driver, ui;
        std::map<std::string, int> syncs, paths;
        float x = kind.start.x, direction = 1.0f;
        int missed = 0;
        for (int step = 0; step < o_.runs + 1 && missed < 3; ++step) {
            if (x + direction * kind.step > kind.hi || x + direction * kind.step < kind.lo)
                direction = -direction;
            x += direction * kind.step;
            const int64_t sent = nowNs();
            moveTo({x, kind.start.y});
            const std::optional<Step> s = awaitEdit(kind, sent, 10.0);
            if (!wrongLabel_.empty()) break;
            if (!s) {
                ++missed;
                continue;
            }
            if (step == 0) continue;  // the press's own first frame may still be in flight
            editor.push_back(s->editorMs);
            driver.push_back(s->driverMs);
            ui.push_back(s->uiFrameMs);
            ++syncs[s->sync];
            ++paths[s->framePath];
            sleepSeconds(0.05);
        }
        xdo({"mouseup", std::to_string(kind.button)});
        sleepSeconds(0.5);
        moveTo(layout_->restingPoint());
        if (!wrongLabel_.empty() || editor.empty()) screenshot("the failed " + kind.name);
        if (!wrongLabel_.empty())
            return fail("the " + kind.name + " drag made the edit '" + wrongLabel_ + "', not one of '" +
                        kind.expected + "': the Inspector's layout differs from editor_layout.h") == 0;
        if (editor.empty())
            return fail("the " + kind.name + " drag from (" + std::to_string(int(kind.start.x)) + ", " +
                        std::to_string(int(kind.start.y)) + ") made no edit that reached the screen") == 0;
        const auto mostOf = [](const std::map<std::string, int>& m) {
            return std::max_element(m.begin(), m.end(), [](auto& a, auto& b) { return a.second < b.second; })
                ->first;
        };
        std::printf("%-16s %6zu %10.2f %10.2f %10.2f %10.2f %9.2f  %s / %s\n", kind.name.c_str(),
                    editor.size(), median(editor), median(driver),
                    *std::min_element(driver.begin(), driver.end()),
                    *std::max_element(driver.begin(), driver.end()), median(ui), mostOf(syncs).c_str(),
                    mostOf(paths).c_str());
        std::fflush(stdout);
        return true;
    }

    Options o_;
    LogReader log_;
    Scene scene_;
    std::unique_ptr<X11Session> x_;
    std::unique_ptr<ChildProcess> editor_;  // after the server: ends before it
    std::string window_, glRenderer_, wrongLabel_;
    std::optional<Layout> layout_;
    int shots_ = 0;
};

std::optional<Options> parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
            return argv[++i];
        };
        if (a == "--backend")
            o.backend = value();
        else if (a == "--size") {
            const std::string v = value();
            if (std::sscanf(v.c_str(), "%ux%u", &o.width, &o.height) != 2 || o.width == 0 || o.height == 0)
                throw std::invalid_argument("--size wants WxH, not " + v);
        } else if (a == "--runs")
            o.runs = std::max(1, std::stoi(value()));
        else if (a == "--object")
            o.object = value();
        else if (a == "--out")
            o.out = value();
        else if (a == "--no-frame-wait")
            o.frameWait = false;
        else if (a == "--follow-viewport")
            o.followViewport = true;
        else if (a == "--help" || a == "-h")
            return std::nullopt;
        else if (!a.empty() && a[0] == '-')
            throw std::invalid_argument("unknown option " + a);
        else
            o.scene = a;
    }
    if (o.scene.empty()) throw std::invalid_argument("no SCENE");
    return o;
}

}  // namespace
}  // namespace pt::test

int main(int argc, char** argv) {
    using namespace pt::test;
    std::optional<Options> options;
    try {
        options = parse(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pt_editor_latency: %s\n%s", e.what(), kUsage);
        return 2;
    }
    if (!options) {
        std::fputs(kUsage, stdout);
        return 0;
    }
    for (const char* program : {"Xvfb", "xdotool"}) {
        if (findOnPath(program).empty()) {
            std::fprintf(stderr, "pt_editor_latency: %s is not on PATH\n", program);
            return 77;
        }
    }
    if (options->out.empty())
        options->out =
            (fs::temp_directory_path() / ("pt-editor-latency-" + std::to_string(getpid()))).string();
    fs::create_directories(fs::path(options->out) / "config");
    try {
        return Driver(*options).run();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pt_editor_latency: %s\n", e.what());
        return 1;
    }
}
