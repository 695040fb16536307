#include "assets/color/color_config.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "assets/color/color_ocio.h"
#include "assets/input_error.h"

namespace pt {
namespace fs = std::filesystem;

namespace {

std::string environmentVariable(const char* name) {
    const char* value = std::getenv(name);
    return value ? std::string(value) : std::string();
}

std::string executableFolder() {
    std::error_code error;
    const fs::path exe = fs::read_symlink("/proc/self/exe", error);
    return error ? std::string() : exe.parent_path().string();
}

std::string joinNames(const std::vector<std::string>& names) {
    if (names.empty()) return "none";
    std::string out;
    for (const std::string& name : names) out += (out.empty() ? "\"" : ", \"") + name + "\"";
    return out;
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

std::string shippedColorConfigPath() {
    const std::string sourceDir = environmentVariable("PT_SOURCE_DIR");
    if (!sourceDir.empty()) return sourceDir + "/scenes/ocio/config.ocio";
    const std::string exeFolder = executableFolder();
    if (!exeFolder.empty()) {
        const fs::path installed = fs::path(exeFolder) / "../share/pathtracer/ocio/config.ocio";
        std::error_code error;
        if (fs::is_regular_file(installed, error)) return installed.lexically_normal().string();
    }
    return PT_SHIPPED_OCIO_CONFIG;
}

std::string resolveColorConfigPath(const std::string& flagPath, const std::string& scenePath) {
    if (!flagPath.empty()) return flagPath;
    if (!scenePath.empty()) return scenePath;
    const std::string env = environmentVariable("OCIO");
    if (!env.empty()) return env;
    return shippedColorConfigPath();
}

ColorConfig::ColorConfig(std::string path, std::unique_ptr<Impl> impl)
    : path_(std::move(path)), impl_(std::move(impl)) {}

ColorConfig::~ColorConfig() = default;

std::shared_ptr<const ColorConfig> ColorConfig::load(const std::string& path) {
    std::error_code error;
    if (!fs::is_regular_file(path, error)) throw InputError(path + ": no such OpenColorIO config file");
    auto impl = std::make_unique<Impl>();
    try {
        OCIO::ConstConfigRcPtr config = OCIO::Config::CreateFromFile(path.c_str());
        config->validate();
        if (!config->getColorSpace(OCIO::ROLE_SCENE_LINEAR)) {
            throw InputError(path +
                             ": the config has no \"scene_linear\" role (the renderer's linear Rec.709)");
        }
        if (config->getNumDisplays() == 0) throw InputError(path + ": the config has no displays");
        impl->config = std::move(config);
    } catch (const OCIO::Exception& e) {
        throw InputError(path + ": " + e.what());
    }
    return std::shared_ptr<const ColorConfig>(new ColorConfig(path, std::move(impl)));
}

std::vector<std::string> ColorConfig::displays() const {
    std::vector<std::string> out;
    for (int i = 0; i < impl_->config->getNumDisplays(); ++i) out.emplace_back(impl_->config->getDisplay(i));
    return out;
}

std::vector<std::string> ColorConfig::views(const std::string& display) const {
    std::vector<std::string> out;
    if (!contains(displays(), display)) return out;
    for (int i = 0; i < impl_->config->getNumViews(display.c_str()); ++i) {
        out.emplace_back(impl_->config->getView(display.c_str(), i));
    }
    return out;
}

std::vector<std::string> ColorConfig::looks() const {
    std::vector<std::string> out;
    for (int i = 0; i < impl_->config->getNumLooks(); ++i)
        out.emplace_back(impl_->config->getLookNameByIndex(i));
    return out;
}

std::string ColorConfig::defaultDisplay() const { return impl_->config->getDefaultDisplay(); }

std::string ColorConfig::defaultView(const std::string& display) const {
    return impl_->config->getDefaultView(display.c_str());
}

ViewTransform ColorConfig::resolve(const ViewTransform& wanted) const {
    const std::string& file = path_;
    ViewTransform out;
    out.display = wanted.display.empty() ? defaultDisplay() : wanted.display;
    if (!contains(displays(), out.display)) {
        throw InputError(file + ": unknown display \"" + out.display + "\" (the config has " +
                         joinNames(displays()) + ")");
    }
    out.view = wanted.view.empty() ? defaultView(out.display) : wanted.view;
    if (!contains(views(out.display), out.view)) {
        throw InputError(file + ": display \"" + out.display + "\" has no view \"" + out.view +
                         "\" (it has " + joinNames(views(out.display)) + ")");
    }
    out.look = wanted.look;
    if (!out.look.empty() && !contains(looks(), out.look)) {
        throw InputError(file + ": unknown look \"" + out.look + "\" (the config has " + joinNames(looks()) +
                         ")");
    }
    return out;
}

OCIO::ConstProcessorRcPtr ocioDisplayProcessor(const ColorConfig& config, const ViewTransform& view) {
    try {
        OCIO::DisplayViewTransformRcPtr displayView = OCIO::DisplayViewTransform::Create();
        displayView->setSrc(OCIO::ROLE_SCENE_LINEAR);
        displayView->setDisplay(view.display.c_str());
        displayView->setView(view.view.c_str());
        if (view.look.empty()) return config.impl().config->getProcessor(displayView);
        OCIO::LookTransformRcPtr look = OCIO::LookTransform::Create();
        look->setSrc(OCIO::ROLE_SCENE_LINEAR);
        look->setDst(OCIO::ROLE_SCENE_LINEAR);
        look->setLooks(view.look.c_str());
        OCIO::GroupTransformRcPtr group = OCIO::GroupTransform::Create();
        group->appendTransform(look);
        group->appendTransform(displayView);
        return config.impl().config->getProcessor(group);
    } catch (const OCIO::Exception& e) {
        throw InputError(config.path() + ": " + view.display + " / " + view.view + ": " + e.what());
    }
}

}  // namespace pt
