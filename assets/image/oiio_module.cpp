// The entry point of the pt_oiio module (see oiio_image_io.h): the table of its functions.
#include "assets/image/image_read_oiio.h"
#include "assets/image/image_write_oiio.h"
#include "assets/image/oiio_image_io.h"

extern "C" const void* ptOiioImageIo() {
    static const pt::OiioImageIo table{pt::oiio::decodeTexture,     pt::oiio::writeExrChannels,
                                       pt::oiio::writeDisplayImage, pt::oiio::readImageRgba,
                                       pt::oiio::readExrChannels,   pt::oiio::readImageMetadata};
    return &table;
}
