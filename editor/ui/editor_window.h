#pragma once
// The editor's window: GLFW + OpenGL 3.3 core + Dear ImGui, the render thread, and the frame
// loop that draws the viewport and panels. `pathtracer` (app/pathtracer) is a thin main()
// over runEditor().
#include "editor/ui/editor_ui.h"

namespace pt::editor {

// Opens the window and runs until it is closed (or until --frames are done). Returns the
// process exit status; prints why to stderr when the window cannot be opened.
int runEditor(const EditorOptions& options);

}  // namespace pt::editor
