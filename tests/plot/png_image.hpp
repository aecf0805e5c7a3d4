#pragma once
// Decoded PNG pixels for tests that check what a picture shows, not only its format.
#include <string>
#include <vector>

namespace magnus::test {

/// An 8-bit RGB image, row-major from the top-left corner.
struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;  ///< 3 bytes a pixel

  /// Channel c (0 r, 1 g, 2 b) of pixel (x, y); white outside the image.
  int at(int x, int y, int c) const {
    if (x < 0 || y < 0 || x >= width || y >= height) return 255;
    return rgb[(size_t(y) * width + x) * 3 + c];
  }
  /// Not white (anything drawn).
  bool inked(int x, int y) const { return at(x, y, 0) + at(x, y, 1) + at(x, y, 2) < 3 * 235; }
  /// Dark grey to black (text, frames, black lines).
  bool dark(int x, int y) const { return at(x, y, 0) < 110 && at(x, y, 1) < 110 && at(x, y, 2) < 110; }
  /// The red of the numeric markers.
  bool red(int x, int y) const { return at(x, y, 0) > 150 && at(x, y, 1) < 110 && at(x, y, 2) < 110; }
  /// The blue of the contour lines (anti-aliased: blue clearly above red and green).
  bool blue(int x, int y) const {
    return at(x, y, 2) > 120 && at(x, y, 2) - at(x, y, 0) > 60 && at(x, y, 2) - at(x, y, 1) > 30;
  }
  /// Some pixel within radius rad of (x, y) satisfies pred.
  template <class Pred>
  bool near(double x, double y, int rad, Pred pred) const {
    for (int dy = -rad; dy <= rad; ++dy)
      for (int dx = -rad; dx <= rad; ++dx)
        if (pred(int(x + 0.5) + dx, int(y + 0.5) + dy)) return true;
    return false;
  }
  /// The image moved by (dx, dy) pixels, white where nothing comes in (a negative control).
  Image shifted(int dx, int dy) const;
  /// A white image of the same size (a negative control).
  Image blank() const;
};

/// Decodes a PNG file into RGB (libpng). Throws std::runtime_error when it cannot.
Image read_png(const std::string& path);

}  // namespace magnus::test
