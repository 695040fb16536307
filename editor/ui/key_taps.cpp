#include "editor/ui/key_taps.h"

#include "editor/ui/gl.h"

namespace pt::editor {
namespace {

std::set<int>& taps() {
    static std::set<int> keys;  // the window's thread only
    return keys;
}

void onKey(GLFWwindow*, int key, int, int action, int) {
    if (action == GLFW_PRESS) taps().insert(key);
}

}  // namespace

void installKeyTapCallback(GLFWwindow* window) { glfwSetKeyCallback(window, onKey); }
bool keyTapped(int glfwKey) { return taps().count(glfwKey) > 0; }
void clearKeyTaps() { taps().clear(); }

}  // namespace pt::editor
