#include "assets/oiio_image_io.h"

#include <dlfcn.h>

#include <filesystem>
#include <system_error>

#include "assets/input_error.h"

namespace pt {
namespace {

// The folder of the running program: a module copied beside the program (a bundle carried to
// another machine) outranks the one in the build tree.
std::filesystem::path programFolder() {
    std::error_code error;
    const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::filesystem::path() : program.parent_path();
}

const OiioImageIo* openModule() {
    const std::filesystem::path besideProgram =
        programFolder() / std::filesystem::path(PT_OIIO_MODULE).filename();
    std::error_code error;
    const std::string path =
        std::filesystem::is_regular_file(besideProgram, error) ? besideProgram.string() : PT_OIIO_MODULE;
    // RTLD_LOCAL: OpenImageIO's symbols stay out of the program's namespace.
    void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!module) throw InputError(std::string("cannot load OpenImageIO's readers and writers: ") + dlerror());
    using Entry = const OiioImageIo* (*)();
    const auto entry = reinterpret_cast<Entry>(dlsym(module, "ptOiioImageIo"));
    if (!entry) throw InputError(path + ": not the pt_oiio module (no ptOiioImageIo)");
    return entry();
}

}  // namespace

const OiioImageIo& oiioImageIo() {
    static const OiioImageIo* const table = openModule();
    return *table;
}

}  // namespace pt
