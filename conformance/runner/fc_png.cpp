// fc_png.cpp - the only C++ of the harness: OpenImageIO glue behind fc_png.h.
#include "fc_png.h"

#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <cstdlib>

using namespace OIIO;

extern "C" int fc_png_write(const char *path, int width, int height, int channels,
                            const unsigned char *pixels)
{
    auto out = ImageOutput::create(path);
    if (!out) {
        std::fprintf(stderr, "fc_png_write: %s: %s\n", path, OIIO::geterror().c_str());
        return 0;
    }
    ImageSpec spec(width, height, channels, TypeDesc::UINT8);
    bool ok = out->open(path, spec) && out->write_image(TypeDesc::UINT8, pixels) && out->close();
    if (!ok)
        std::fprintf(stderr, "fc_png_write: %s: %s\n", path, out->geterror().c_str());
    return ok ? 1 : 0;
}

extern "C" int fc_png_read(const char *path, int *width, int *height, int *channels,
                           unsigned char **pixels)
{
    auto in = ImageInput::open(path);
    if (!in)
        return 0;
    const ImageSpec &spec = in->spec();
    size_t size = (size_t)spec.width * (size_t)spec.height * (size_t)spec.nchannels;
    unsigned char *buf = static_cast<unsigned char *>(std::malloc(size ? size : 1));
    if (!in->read_image(0, 0, 0, spec.nchannels, TypeDesc::UINT8, buf)) {
        std::free(buf);
        return 0;
    }
    *width = spec.width;
    *height = spec.height;
    *channels = spec.nchannels;
    *pixels = buf;
    return 1;
}
