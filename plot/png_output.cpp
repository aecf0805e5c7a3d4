#include "plot/png_output.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <fmt/core.h>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

namespace magnus::page {
namespace {

/// fopencookie's write: all n bytes to the descriptor, or -1 with the first errno kept (ENOSPC when
/// write(2) writes nothing without one).
ssize_t sink_write(void* cookie, const char* buf, size_t n) {
  auto* s = static_cast<PngSink*>(cookie);
  size_t done = 0;
  while (done < n) {
    const ssize_t w = ::write(s->fd, buf + done, n - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) {
      if (!s->error) s->error = w < 0 ? errno : ENOSPC;
      return -1;
    }
    done += size_t(w);
  }
  return ssize_t(n);
}

/// fopencookie's close: closes the descriptor; -1 when it or an earlier write failed.
int sink_close(void* cookie) {
  auto* s = static_cast<PngSink*>(cookie);
  if (s->fd >= 0 && ::close(s->fd) != 0 && !s->error) s->error = errno;
  s->fd = -1;
  return s->error ? -1 : 0;
}

}  // namespace

FILE* open_png_sink(PngSink& sink, const std::string& path) {
  sink.fd = ::open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  if (sink.fd < 0) return nullptr;
  FILE* file = fopencookie(&sink, "wb", {nullptr, sink_write, nullptr, sink_close});
  if (!file) {
    const int e = errno;
    ::close(sink.fd);
    sink.fd = -1;
    errno = e;
  }
  return file;
}

std::string check_png(const std::string& path, PlotSize size) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "the rendered file cannot be read back";
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
  if (bytes.size() < 8 + 25 + 12 || std::memcmp(bytes.data(), sig, 8) != 0 ||
      bytes.compare(12, 4, "IHDR") != 0)
    return "PLplot produced no PNG image";
  auto be32 = [&](size_t at) {
    const auto* b = reinterpret_cast<const unsigned char*>(bytes.data()) + at;
    return (unsigned long)b[0] << 24 | (unsigned long)b[1] << 16 | (unsigned long)b[2] << 8 | b[3];
  };
  if (be32(16) != (unsigned long)size.width || be32(20) != (unsigned long)size.height)
    return fmt::format("PLplot produced a {}x{} image instead of {}x{}", be32(16), be32(20), size.width,
                       size.height);
  if (std::memcmp(bytes.data() + bytes.size() - 12, iend, 12) != 0)
    return "the PNG is truncated (disk full?)";
  return {};
}

}  // namespace magnus::page
