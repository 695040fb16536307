#pragma once
// Key presses as events. ImGui 1.86's GLFW backend only records whether a key is down at the
// start of a frame, so a key pressed and released within one frame (a quick tap, or xdotool)
// is never seen by ImGui::IsKeyPressed. A GLFW key callback installed before ImGui's (which
// chains to it) records every press here until the frame has looked at them.
#include <set>

struct GLFWwindow;

namespace pt::editor {

void installKeyTapCallback(GLFWwindow* window);  // before ImGui_ImplGlfw_InitForOpenGL
bool keyTapped(int glfwKey);                     // pressed since the last clearKeyTaps()
void clearKeyTaps();                             // at the end of each frame

}  // namespace pt::editor
