#include "editor/color_view.h"

#include <exception>

namespace pt::editor {

std::string ColorView::key() const {
    if (!config) return "built-in";
    return config->path() + "\n" + view.display + "\n" + view.view + "\n" + view.look;
}

ColorView resolveColorView(const std::string& flagPath, const ColorSettings& settings,
                           const ColorView& current) {
    ColorView next;
#ifdef PT_HAVE_OCIO
    const std::string path = resolveColorConfigPath(flagPath, settings.config);
    try {
        next.config =
            current.config && current.config->path() == path ? current.config : ColorConfig::load(path);
    } catch (const std::exception& e) {
        next.error = e.what();
        return next;
    }
    try {
        next.view = next.config->resolve({settings.display, settings.view, settings.look});
    } catch (const std::exception& e) {
        // The scene names a view this config lacks: show the config's default instead.
        next.error = e.what();
        next.view = next.config->resolve({});
    }
#else
    (void)flagPath;
    (void)current;
    if (!settings.config.empty() || !settings.view.empty()) {
        next.error = "this build has no OpenColorIO (PT_OCIO=OFF): the built-in operators are used";
    }
#endif
    return next;
}

DisplayProcessor displayProcessorFor(const ColorView& color, const ViewerSettings& viewer) {
#ifdef PT_HAVE_OCIO
    if (color.config && !viewer.builtinDisplay) {
        return DisplayProcessor(*color.config, color.view, viewer.display.exposureStops);
    }
#else
    (void)color;
#endif
    return DisplayProcessor(viewer.display);
}

}  // namespace pt::editor
