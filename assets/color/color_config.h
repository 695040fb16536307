#pragma once
// OpenColorIO configs (DESIGN.md "Display and color"). The renderer accumulates linear
// Rec.709 ("scene_linear" in the config); a config's display / view / look turns that into
// display pixels, on the CPU for file export (assets/color_processor.h) and in GLSL for the
// editor (assets/color_gpu_shader.h). The project ships scenes/ocio/config.ocio.
//
// Only built with PT_OCIO=ON (PT_HAVE_OCIO is then defined for every target linking
// pt_assets); OpenColorIO's own headers stay out of this one.
#include <memory>
#include <string>
#include <vector>

namespace pt {

// A display, a view of it and an optional look; "" = the config's default (look: none).
struct ViewTransform {
    std::string display, view, look;
};

// Which config to use, first match wins:
//   1. `flagPath` (pt-render --ocio), if non-empty;
//   2. `scenePath` (the scene's ColorSettings::config, already absolute), if non-empty;
//   3. $OCIO, if set and non-empty;
//   4. the shipped config (shippedColorConfigPath()).
// Returns the path as given (not checked for existence: ColorConfig::load reports that).
std::string resolveColorConfigPath(const std::string& flagPath, const std::string& scenePath);

// The project's config: $PT_SOURCE_DIR/scenes/ocio/config.ocio when that variable is set (the
// GPU machine's bundle), else <executable>/../share/pathtracer/ocio/config.ocio when that
// exists (an installed copy), else the source tree this was built from.
std::string shippedColorConfigPath();

// A loaded, validated config. Immutable once loaded; share it between threads freely.
class ColorConfig {
public:
    // Throws InputError "<path>: <OpenColorIO's message>" when the file is missing, does not
    // parse, fails Config::validate(), or has no scene_linear role.
    static std::shared_ptr<const ColorConfig> load(const std::string& path);

    const std::string& path() const { return path_; }
    std::vector<std::string> displays() const;
    std::vector<std::string> views(const std::string& display) const;  // [] for an unknown display
    std::vector<std::string> looks() const;
    std::string defaultDisplay() const;
    std::string defaultView(const std::string& display) const;

    // Completes a choice: an empty display or view becomes the default; an empty look stays
    // empty (none). Throws InputError naming the unknown display, view or look, the config,
    // and listing the names that exist.
    ViewTransform resolve(const ViewTransform& wanted) const;

    // OpenColorIO's config object (OCIO::ConstConfigRcPtr); for assets/color_*.cpp only.
    struct Impl;
    const Impl& impl() const { return *impl_; }

    ~ColorConfig();
    ColorConfig(const ColorConfig&) = delete;
    ColorConfig& operator=(const ColorConfig&) = delete;

private:
    ColorConfig(std::string path, std::unique_ptr<Impl> impl);
    std::string path_;
    std::unique_ptr<Impl> impl_;
};

}  // namespace pt
