#pragma once
// Whose file an existing output is. magnus replaces its own outputs (following a link to one is fine) but
// not a file it did not write: `-o link.h5` with the link pointing at /etc/passwd must not replace passwd.
// An existing file counts as magnus's own when it is
//   - empty (0 bytes: nothing to lose),
//   - HDF5 whose root attribute `format` starts with "magnus-" (results, sweeps, checkpoints),
//   - PNG with a tEXt chunk Software = "magnus …" (every PNG magnus writes carries one),
//   - XDMF beginning with magnus's preamble and reading its mesh from /mesh/points of an HDF5 file,
//   - CSV whose first line begins with the header of one of magnus's CSV tables (kMagnusCsvHeaders),
//   - GIF with a comment extension "magnus …" before its first image, MP4 ending in a box "free" holding
//     "magnus VERSION" (the films of `magnus plot --movie`; mark_film_file).
// Anything else is refused unless replacing it was asked for (--force).
#include <string>

namespace magnus {

/// Why the existing file at `target` is not one magnus wrote ("" when it may be replaced: absent, empty, or
/// a magnus output by the rules above). Reads at most the first 64 KiB (and the HDF5 root attributes).
std::string not_a_magnus_output(const std::string& target);

/// Whether an HDF5 file is one magnus wrote (its root `format` is one of magnus's). Reading HDF5 is io's:
/// io installs its reader with set_hdf5_owner_check; until then every HDF5 file counts as not magnus's.
using Hdf5OwnerCheck = bool (*)(const std::string& target);
/// Installs the HDF5 half of not_a_magnus_output (io/result_file.cpp does, when it is linked in).
void set_hdf5_owner_check(Hdf5OwnerCheck check);

/// --force: allow replacing any existing regular file (process-wide; off by default).
void set_replace_any_file(bool yes);

/// Throws one line "cannot write 'path': 'target' exists and is not a magnus output (…); --force replaces
/// it" unless the file at target may be replaced (or --force was given).
void check_replaceable(const std::string& path, const std::string& target);

/// png with a tEXt chunk "Software" = "magnus VERSION" after its IHDR chunk: the mark that lets magnus
/// recognise (and replace) a PNG it wrote. png is returned unchanged if it is not a PNG.
std::string mark_png(const std::string& png);

/// mark_png applied to the file at path, in place; false if it cannot be read or written.
bool mark_png_file(const std::string& path);

/// Marks the film at path (GIF or MP4) as magnus's, in place: a GIF gets the comment extension "magnus
/// VERSION" after its global colour table, an MP4 a last top-level box "free" holding it (players skip both).
/// False if it is neither or cannot be read or written.
bool mark_film_file(const std::string& path);

}  // namespace magnus
