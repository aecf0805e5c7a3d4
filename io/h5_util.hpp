#pragma once
// Internal to io/: small helpers shared by the HDF5 writer and reader (not part of any API).
#include <hdf5.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

namespace magnus::h5 {

/// Closes an HDF5 identifier when it goes out of scope.
struct Handle {
  hid_t id;
  herr_t (*close)(hid_t);
  Handle(hid_t i, herr_t (*c)(hid_t)) : id(i), close(c) {}
  ~Handle() {
    if (id >= 0) close(id);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  operator hid_t() const { return id; }
};

/// No HDF5 error stacks on stderr: every failure becomes one line of ours.
inline void quiet() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

[[noreturn]] inline void fail(const std::string& what) { throw std::runtime_error(what); }

/// Fails with what, and the system's reason when the last HDF5 call set errno (": No space left on device").
inline void check(herr_t status, const std::string& what) {
  if (status >= 0) return;
  const int err = errno;
  fail(err != 0 ? what + ": " + std::strerror(err) : what);
}

/// Links and attributes stay in the object header (checksummed) however many there are: HDF5's "dense"
/// storage for more than 8 puts them in a fractal heap without checksums, and HDF5 1.10 can crash on a
/// damaged one (H5G__dense_iterate frees an uninitialised pointer).
inline void keep_compact(hid_t ocpl) {
  H5Pset_link_phase_change(ocpl, 1024, 1000);
  H5Pset_attr_phase_change(ocpl, 1024, 1000);
}

}  // namespace magnus::h5
