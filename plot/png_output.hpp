#pragma once
// Internal to plot/: the file a picture is written to. PLplot writes the PNG through stdio and closes
// the stream itself, which would drop a write error (a full disk) unseen: the stream here writes to the
// file descriptor and keeps the first errno. And the check that the bytes written are a whole PNG.
#include <cstdio>
#include <string>

#include "plot/plot.hpp"

namespace magnus::page {

/// The state of a PNG stream: its file descriptor and the first errno of a failed write or close.
struct PngSink {
  int fd = -1;
  int error = 0;  ///< 0: none
};

/// Opens path (existing, truncated) for writing as a stdio stream over `sink` (fopencookie); closing
/// the stream closes the descriptor. Null with errno set when it cannot.
FILE* open_png_sink(PngSink& sink, const std::string& path);

/// "" when the file is a complete PNG of the requested size (signature, IHDR, IEND last), else why not.
std::string check_png(const std::string& path, PlotSize size);

}  // namespace magnus::page
