#include "assets/image/oiio_image_io.h"

#include "assets/plugin_module.h"

namespace pt {

const OiioImageIo& oiioImageIo() {
    static const OiioImageIo* const table = static_cast<const OiioImageIo*>(
        openModuleTable(PT_OIIO_MODULE, "ptOiioImageIo", "OpenImageIO's readers and writers"));
    return *table;
}

}  // namespace pt
