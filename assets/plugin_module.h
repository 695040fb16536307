#pragma once
// Opening a module of ours with dlopen (RTLD_LOCAL), for libraries kept out of the programs'
// symbol namespace: OpenImageIO (its ~260 libraries slowed every start-up; oiio_image_io.h) and
// Draco (its library exports the tinygltf and stb it bundles, which took the place of ours;
// draco_decoder.h). Each module exports one C function, `const void* entry()`, returning its
// table of functions (that exact type: a call through another is undefined, and UBSan says so).
#include <string>

namespace pt {

// Calls `entry` of the module built at `builtPath` and returns what it returns: the module's
// table. A copy of the module beside the running program (a bundle carried to another machine)
// outranks the build tree's. Throws InputError naming `what` when the module cannot be opened.
const void* openModuleTable(const std::string& builtPath, const char* entry, const std::string& what);

}  // namespace pt
