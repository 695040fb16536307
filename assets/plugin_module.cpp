#include "assets/plugin_module.h"

#include <dlfcn.h>

#include <filesystem>
#include <system_error>

#include "assets/input_error.h"

namespace pt {
namespace {

std::filesystem::path programFolder() {
    std::error_code error;
    const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::filesystem::path() : program.parent_path();
}

}  // namespace

const void* openModuleTable(const std::string& builtPath, const char* entry, const std::string& what) {
    const std::filesystem::path besideProgram = programFolder() / std::filesystem::path(builtPath).filename();
    std::error_code error;
    const std::string path =
        std::filesystem::is_regular_file(besideProgram, error) ? besideProgram.string() : builtPath;
    // RTLD_LOCAL: the module's libraries' symbols stay out of the program's namespace.
    void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!module) throw InputError("cannot load " + what + ": " + dlerror());
    using Entry = const void* (*)();
    const auto function = reinterpret_cast<Entry>(dlsym(module, entry));
    if (!function) throw InputError(path + ": not the module of " + what + " (no " + entry + ")");
    return function();
}

}  // namespace pt
