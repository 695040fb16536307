#include "editor/ui/input_events.h"

#include <algorithm>
#include <cmath>

#include "editor/ui/gl.h"

namespace pt::editor {

static_assert(kModShift == GLFW_MOD_SHIFT && kModCtrl == GLFW_MOD_CONTROL && kModAlt == GLFW_MOD_ALT);

void InputEvents::key(int key, int action, int mods) {
    ++count_;
    if (action == GLFW_PRESS) presses_.push_back({key, mods});
}

void InputEvents::mouseButton(int button, int action, ScreenPoint at, double seconds) {
    ++count_;
    if (action != GLFW_PRESS) return;
    const Click click{button, at, seconds};
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

std::optional<ScreenPoint> InputEvents::doubleClick(int button) const {
    for (const Click& c : doubleClicks_) {
        if (c.button == button) return c.at;
    }
    return std::nullopt;
}

void InputEvents::endFrame() {
    presses_.clear();
    doubleClicks_.clear();
}

InputEvents& inputEvents() {
    static InputEvents events;
    return events;
}

namespace {

void onKey(GLFWwindow*, int key, int, int action, int mods) { inputEvents().key(key, action, mods); }

void onMouseButton(GLFWwindow* window, int button, int action, int) {
    double x = 0, y = 0;
    glfwGetCursorPos(window, &x, &y);  // window coordinates, as ImGui's MousePos
    inputEvents().mouseButton(button, action, {float(x), float(y)}, glfwGetTime());
}

void onCursorPos(GLFWwindow*, double, double) { inputEvents().other(); }
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
