#include "base/output_owner.hpp"

#include <fmt/core.h>
#include <sys/stat.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <vector>

namespace magnus {

namespace {

bool g_replace_any = false;
Hdf5OwnerCheck g_hdf5_check = nullptr;

/// The first line of every CSV table magnus writes begins with one of these (sweep, navier-stokes map,
/// compare, bench, navier-stokes bench, probe, inspect --surface-csv).
const char* const kMagnusCsvHeaders[] = {
    "alpha,circulation_m2_s,lift_N_m,", "reynolds,alpha,row,column,", "file,title,",
    "method,stencil,n_theta,n_r,unknowns,", "n_theta,n_r,nodes,dt_s,", "x_m,y_m,r_m,theta_rad,",
    "theta_rad,theta_deg,u_theta_m_s,"};

/// magnus's XDMF preamble (io/xdmf.cpp) and the mesh every magnus sidecar reads.
constexpr const char* kXdmfPreamble =
    "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf Version=\"3.0\">\n";
constexpr const char* kXdmfMesh = ":/mesh/points</DataItem>";

const unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
constexpr const char* kPngSoftware = "Software";

uint32_t be32(const std::string& s, size_t at) {
  const auto* b = reinterpret_cast<const unsigned char*>(s.data()) + at;
  return uint32_t(b[0]) << 24 | uint32_t(b[1]) << 16 | uint32_t(b[2]) << 8 | uint32_t(b[3]);
}

void put_be32(std::string& s, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) s += char((v >> shift) & 0xFF);
}

/// CRC-32 (ISO-HDLC, the PNG chunk checksum) of bytes.
uint32_t crc32(const std::string& bytes) {
  static const std::array<uint32_t, 256> table = [] {
    std::array<uint32_t, 256> t{};
    for (uint32_t n = 0; n < 256; ++n) {
      uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  uint32_t c = 0xFFFFFFFFu;
  for (unsigned char b : bytes) c = table[(c ^ b) & 0xFF] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

/// Whether the PNG bytes (the first part of a file at least) hold a tEXt Software = "magnus…" chunk before
/// the image data.
bool png_by_magnus(const std::string& png) {
  for (size_t at = 8; at + 12 <= png.size();) {
    const uint32_t len = be32(png, at);
    const std::string type = png.substr(at + 4, 4);
    if (type == "IDAT" || type == "IEND" || len > png.size()) return false;
    if (type == "tEXt" && at + 8 + len <= png.size()) {
      const std::string text = png.substr(at + 8, len);
      if (text.rfind(std::string(kPngSoftware) + '\0' + "magnus", 0) == 0) return true;
    }
    at += 12 + size_t(len);
  }
  return false;
}

/// The mark of a film: a GIF comment extension, or an MP4's last top-level box ("free", ignored by players).
std::string film_mark() { return std::string("magnus ") + MAGNUS_VERSION; }

/// Where a GIF's blocks begin: after the header, the logical screen descriptor and the global colour table
/// (0 when the bytes are not a GIF).
size_t gif_blocks(const std::string& gif) {
  if (gif.size() < 13 || (gif.rfind("GIF89a", 0) != 0 && gif.rfind("GIF87a", 0) != 0)) return 0;
  const unsigned packed = static_cast<unsigned char>(gif[10]);
  const size_t at = 13 + (packed & 0x80 ? 3 * (size_t(2) << (packed & 7)) : 0);
  return at <= gif.size() ? at : 0;
}

/// Whether the GIF bytes hold a comment extension starting with "magnus" before the first image.
bool gif_by_magnus(const std::string& gif) {
  size_t at = gif_blocks(gif);
  if (at == 0) return false;
  while (at + 2 < gif.size() && static_cast<unsigned char>(gif[at]) == 0x21) {
    const bool comment = static_cast<unsigned char>(gif[at + 1]) == 0xFE;
    at += 2;
    if (comment && at + 7 <= gif.size() && gif.compare(at + 1, 6, "magnus") == 0) return true;
    while (at < gif.size() && gif[at] != 0) at += 1 + static_cast<unsigned char>(gif[at]);  // sub-blocks
    ++at;
  }
  return false;
}

/// Whether the file (an MP4: ftyp first) ends with the box "free" holding film_mark().
bool mp4_by_magnus(const std::string& path) {
  const std::string box = "free" + film_mark();
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  const std::streamoff size = in.tellg();
  if (!in || size < std::streamoff(box.size() + 4)) return false;
  std::string tail(box.size() + 4, '\0');
  in.seekg(size - std::streamoff(tail.size()));
  in.read(&tail[0], std::streamsize(tail.size()));
  return bool(in) && be32(tail, 0) == tail.size() && tail.compare(4, box.size(), box) == 0;
}

}  // namespace

std::string not_a_magnus_output(const std::string& target) {
  struct stat st;
  if (::stat(target.c_str(), &st) != 0 || !S_ISREG(st.st_mode) || st.st_size == 0) return "";
  std::ifstream in(target, std::ios::binary);
  if (!in) return "a file that cannot be read to tell whether magnus wrote it";
  std::string head(64 * 1024, '\0');
  in.read(&head[0], std::streamsize(head.size()));
  head.resize(size_t(in.gcount()));
  if (head.rfind("\x89HDF\r\n\x1a\n", 0) == 0)
    return g_hdf5_check && g_hdf5_check(target) ? "" : "an HDF5 file without a magnus format attribute";
  if (head.size() >= 8 && std::memcmp(head.data(), kPngSignature, 8) == 0)
    return png_by_magnus(head) ? "" : "a PNG image magnus did not write (no Software = magnus text chunk)";
  if (gif_blocks(head) > 0) return gif_by_magnus(head) ? "" : "a GIF magnus did not write (no magnus comment)";
  if (head.size() >= 8 && head.compare(4, 4, "ftyp") == 0)
    return mp4_by_magnus(target) ? "" : "an MP4 magnus did not write (no magnus box at its end)";
  if (head.rfind(kXdmfPreamble, 0) == 0 && head.find(kXdmfMesh) != std::string::npos) return "";
  const std::string first_line = head.substr(0, head.find('\n'));
  for (const char* h : kMagnusCsvHeaders)
    if (first_line.rfind(h, 0) == 0) return "";
  return "not a file magnus wrote (not a magnus HDF5, PNG, XDMF, CSV, GIF or MP4 output)";
}

void set_replace_any_file(bool yes) { g_replace_any = yes; }

void set_hdf5_owner_check(Hdf5OwnerCheck check) { g_hdf5_check = check; }

void check_replaceable(const std::string& path, const std::string& target) {
  if (g_replace_any) return;
  const std::string why = not_a_magnus_output(target);
  if (why.empty()) return;
  const std::string where = target == path ? "it" : fmt::format("'{}' (its link target)", target);
  throw std::runtime_error(fmt::format(
      "cannot write '{}': {} exists and is {}; magnus replaces only its own outputs (--force replaces it)",
      path, where, why));
}

std::string mark_png(const std::string& png) {
  if (png.size() < 8 + 25 || std::memcmp(png.data(), kPngSignature, 8) != 0 || png.compare(12, 4, "IHDR") != 0)
    return png;
  const size_t after_ihdr = 8 + 12 + size_t(be32(png, 8));
  if (after_ihdr > png.size()) return png;
  const std::string body = std::string("tEXt") + kPngSoftware + '\0' + "magnus " + MAGNUS_VERSION;
  std::string chunk;
  put_be32(chunk, uint32_t(body.size() - 4));
  chunk += body;
  put_be32(chunk, crc32(body));
  return png.substr(0, after_ihdr) + chunk + png.substr(after_ihdr);
}

namespace {

/// Replaces the file at path, in place, by edit(its bytes); false if it cannot be read or written, or edit
/// returns "" (nothing to write).
template <class Edit>
bool rewrite_file(const std::string& path, Edit edit) {
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    bytes.assign((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) return false;
  }
  const std::string edited = edit(bytes);
  if (edited.empty()) return false;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(edited.data(), std::streamsize(edited.size()));
  out.close();
  return bool(out);
}

}  // namespace

bool mark_png_file(const std::string& path) { return rewrite_file(path, mark_png); }

bool mark_film_file(const std::string& path) {
  return rewrite_file(path, [](const std::string& bytes) {
    const std::string mark = film_mark();
    if (const size_t at = gif_blocks(bytes); at > 0)  // a comment extension: 0x21 0xFE, one sub-block, 0
      return bytes.substr(0, at) + "\x21\xFE" + char(mark.size()) + mark + '\0' + bytes.substr(at);
    if (bytes.size() < 8 || bytes.compare(4, 4, "ftyp") != 0) return std::string();
    std::string marked = bytes;  // an MP4: a last top-level box "free"
    put_be32(marked, uint32_t(8 + mark.size()));
    return marked + "free" + mark;
  });
}

}  // namespace magnus
