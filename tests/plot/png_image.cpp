#include "plot/png_image.hpp"

#include <png.h>

#include <cstring>
#include <stdexcept>

namespace magnus::test {

Image read_png(const std::string& path) {
  png_image img;
  std::memset(&img, 0, sizeof img);
  img.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&img, path.c_str()))
    throw std::runtime_error("cannot decode " + path + ": " + img.message);
  img.format = PNG_FORMAT_RGB;
  Image out;
  out.width = int(img.width);
  out.height = int(img.height);
  out.rgb.resize(PNG_IMAGE_SIZE(img));
  if (!png_image_finish_read(&img, nullptr, out.rgb.data(), 0, nullptr)) {
    png_image_free(&img);
    throw std::runtime_error("cannot decode " + path + ": " + img.message);
  }
  return out;
}

Image Image::shifted(int dx, int dy) const {
  Image s = blank();
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c)
        s.rgb[(size_t(y) * width + x) * 3 + c] = (unsigned char)at(x - dx, y - dy, c);
  return s;
}

Image Image::blank() const {
  Image s = *this;
  std::fill(s.rgb.begin(), s.rgb.end(), 255);
  return s;
}

}  // namespace magnus::test
