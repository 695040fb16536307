#include "editor/ui/input_events.h"

#include <algorithm>
#include <cmath>

#include "editor/ui/gl.h"

namespace pt::editor {

static_assert(kModShift == GLFW_MOD_SHIFT && kModCtrl == GLFW_MOD_CONTROL && kModAlt == GLFW_MOD_ALT);

void InputEvents::counted() {
    ++count_;
    if (!firstEvent_) firstEvent_ = std::chrono::steady_clock::now();
}

void InputEvents::key(int key, int action, int mods) {
    counted();
    if (action == GLFW_PRESS) presses_.push_back({key, mods});
    const auto held = std::find(heldPlain_.begin(), heldPlain_.end(), key);
    if (action == GLFW_RELEASE && held != heldPlain_.end()) heldPlain_.erase(held);
    if (action == GLFW_PRESS && (mods & (kModCtrl | kModAlt)) == 0 && held == heldPlain_.end())
        heldPlain_.push_back(key);
}

bool InputEvents::heldPlain(int key) const {
    return std::find(heldPlain_.begin(), heldPlain_.end(), key) != heldPlain_.end();
}

void InputEvents::mouseButton(int button, int action, ScreenPoint at, double seconds) {
    counted();
    if (action != GLFW_PRESS) return;
    const Click click{button, at, seconds};
    clicks_.push_back(click);
    const bool paired = lastClick_.button == button && seconds - lastClick_.seconds <= kDoubleClickSeconds &&
                        std::hypot(at.x - lastClick_.at.x, at.y - lastClick_.at.y) <= kDoubleClickDistance;
    if (paired) {
        doubleClicks_.push_back(click);
        lastClick_ = {};  // a third press starts a new pair
    } else {
        lastClick_ = click;
    }
}

bool InputEvents::tapped(int key) const {
    return std::any_of(presses_.begin(), presses_.end(), [key](const Press& p) { return p.key == key; });
}

bool InputEvents::chord(int key, int mods) const {
    constexpr int kChordMods = kModShift | kModCtrl | kModAlt;
    return std::any_of(presses_.begin(), presses_.end(),
                       [&](const Press& p) { return p.key == key && (p.mods & kChordMods) == mods; });
}

namespace {

std::optional<ScreenPoint> firstOf(const std::vector<InputEvents::Click>& clicks, int button) {
    for (const InputEvents::Click& c : clicks) {
        if (c.button == button) return c.at;
    }
    return std::nullopt;
}

}  // namespace

std::optional<ScreenPoint> InputEvents::doubleClick(int button) const {
    return firstOf(doubleClicks_, button);
}

std::optional<ScreenPoint> InputEvents::pressed(int button) const { return firstOf(clicks_, button); }

void InputEvents::endFrame() {
    firstEvent_.reset();
    presses_.clear();
    doubleClicks_.clear();
    clicks_.clear();
}

InputEvents& inputEvents() {
    static InputEvents events;
    return events;
}

namespace {

void onKey(GLFWwindow*, int key, int, int action, int mods) { inputEvents().key(key, action, mods); }

void onMouseButton(GLFWwindow* window, int button, int action, int) {
    InputEvents& events = inputEvents();
    ScreenPoint at;
    if (events.cursor()) {
        at = *events.cursor();
    } else {  // no move seen yet: where the pointer is now
        double x = 0, y = 0;
        glfwGetCursorPos(window, &x, &y);
        at = {float(x), float(y)};
    }
    events.mouseButton(button, action, at, glfwGetTime());
}

// Window coordinates, as ImGui's MousePos.
void onCursorPos(GLFWwindow*, double x, double y) { inputEvents().cursorMoved({float(x), float(y)}); }
void onScroll(GLFWwindow*, double, double) { inputEvents().other(); }
void onChar(GLFWwindow*, unsigned int) { inputEvents().other(); }
void onFocus(GLFWwindow*, int) { inputEvents().other(); }
void onCursorEnter(GLFWwindow*, int) { inputEvents().other(); }
void onSize(GLFWwindow*, int, int) { inputEvents().other(); }
void onRefresh(GLFWwindow*) { inputEvents().other(); }

}  // namespace

void installInputCallbacks(GLFWwindow* window) {
    glfwSetKeyCallback(window, onKey);
    glfwSetMouseButtonCallback(window, onMouseButton);
    glfwSetCursorPosCallback(window, onCursorPos);
    glfwSetScrollCallback(window, onScroll);
    glfwSetCharCallback(window, onChar);
    glfwSetWindowFocusCallback(window, onFocus);
    glfwSetCursorEnterCallback(window, onCursorEnter);
    glfwSetFramebufferSizeCallback(window, onSize);
    glfwSetWindowRefreshCallback(window, onRefresh);
}

}  // namespace pt::editor
