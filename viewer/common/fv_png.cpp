// PNG writing and reading through OpenImageIO (fv_png.h).
#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <vector>

#include "fv_png.h"

using namespace OIIO;

extern "C" int fv_png_write(const char *path, int w, int h, const unsigned char *rgba,
                            int bottom_up)
{
   std::unique_ptr<ImageOutput> out = ImageOutput::create(path);
   if (!out) {
      std::fprintf(stderr, "fv_png: cannot create %s: %s\n", path, OIIO::geterror().c_str());
      return -1;
   }
   ImageSpec spec(w, h, 4, TypeDesc::UINT8);
   if (!out->open(path, spec)) {
      std::fprintf(stderr, "fv_png: cannot open %s: %s\n", path, out->geterror().c_str());
      return -1;
   }
   const stride_t row = (stride_t)w * 4;
   const unsigned char *first = bottom_up ? rgba + (size_t)(h - 1) * row : rgba;
   bool ok = out->write_image(TypeDesc::UINT8, first, AutoStride, bottom_up ? -row : row);
   ok = out->close() && ok;
   if (!ok) {
      std::fprintf(stderr, "fv_png: cannot write %s\n", path);
      return -1;
   }
   return 0;
}

extern "C" int fv_png_read(const char *path, int *w, int *h, unsigned char **rgba)
{
   std::unique_ptr<ImageInput> in = ImageInput::open(path);
   if (!in) {
      std::fprintf(stderr, "fv_png: cannot read %s: %s\n", path, OIIO::geterror().c_str());
      return -1;
   }
   const ImageSpec &spec = in->spec();
   int nc = spec.nchannels;
   std::vector<unsigned char> px((size_t)spec.width * spec.height * nc);
   if (!in->read_image(0, 0, 0, nc, TypeDesc::UINT8, px.data())) {
      std::fprintf(stderr, "fv_png: cannot decode %s\n", path);
      return -1;
   }
   unsigned char *outp = (unsigned char *)std::malloc((size_t)spec.width * spec.height * 4);
   if (!outp)
      return -1;
   for (size_t i = 0; i < (size_t)spec.width * spec.height; i++) {
      for (int c = 0; c < 4; c++) {
         if (c < nc && !(nc < 3 && c > 0 && c < 3))
            outp[i * 4 + c] = px[i * nc + c];
         else if (c == 3)
            outp[i * 4 + c] = nc == 2 ? px[i * nc + 1] : 255;
         else
            outp[i * 4 + c] = px[i * nc];   // grey
      }
   }
   *w = spec.width;
   *h = spec.height;
   *rgba = outp;
   in->close();
   return 0;
}
