// Images through OpenImageIO (fv_image.h).
#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "fv_image.h"

using namespace OIIO;

static int fail(char *err, size_t size, const char *what, const std::string &why)
{
   std::snprintf(err, size, "%s%s%s", what, why.empty() ? "" : ": ", why.c_str());
   return -1;
}

extern "C" int fv_image_read(const char *path, struct fv_image *im, char *err, size_t err_size)
{
   std::memset(im, 0, sizeof *im);
   std::unique_ptr<ImageInput> in = ImageInput::open(path);
   if (!in)
      return fail(err, err_size, "cannot read it", OIIO::geterror());
   const ImageSpec &spec = in->spec();
   const int w = spec.width, h = spec.height, nc = spec.nchannels;
   if (w <= 0 || h <= 0 || nc <= 0 || (long long)w * h > (1LL << 28))
      return fail(err, err_size, "unsupported image size", std::to_string(w) + "x" +
                  std::to_string(h) + ", " + std::to_string(nc) + " channels");
   std::vector<unsigned char> px((size_t)w * h * nc);
   if (!in->read_image(0, 0, 0, nc, TypeDesc::UINT8, px.data())) {
      std::string why = in->geterror();
      return fail(err, err_size, "cannot decode it", why);
   }
   in->close();
   unsigned char *out = (unsigned char *)std::malloc((size_t)w * h * 4);
   if (!out)
      return fail(err, err_size, "out of memory", "");
   for (int y = 0; y < h; y++) {
      const unsigned char *s = &px[(size_t)(h - 1 - y) * w * nc];   // bottom row first
      unsigned char *d = &out[(size_t)y * w * 4];
      for (int x = 0; x < w; x++, s += nc, d += 4) {
         if (nc >= 3) {
            d[0] = s[0], d[1] = s[1], d[2] = s[2];
            d[3] = nc >= 4 ? s[3] : 255;
         } else {
            d[0] = d[1] = d[2] = s[0];
            d[3] = nc == 2 ? s[1] : 255;
         }
      }
   }
   im->w = w, im->h = h, im->channels = nc > 4 ? 4 : nc, im->rgba = out;
   return 0;
}

extern "C" int fv_image_write(const char *path, int w, int h, const unsigned char *rgba,
                              char *err, size_t err_size)
{
   std::unique_ptr<ImageOutput> out = ImageOutput::create(path);
   if (!out)
      return fail(err, err_size, "cannot create it", OIIO::geterror());
   ImageSpec spec(w, h, 4, TypeDesc::UINT8);
   if (!out->open(path, spec))
      return fail(err, err_size, "cannot open it", out->geterror());
   bool ok = out->write_image(TypeDesc::UINT8, rgba);
   ok = out->close() && ok;
   if (!ok)
      return fail(err, err_size, "cannot write it", out->geterror());
   return 0;
}

extern "C" void fv_image_free(struct fv_image *im)
{
   std::free(im->rgba);
   std::memset(im, 0, sizeof *im);
}
