#pragma once
// The .xmf sidecar (XDMF) and the /mesh group it reads: an unstructured grid of (n_r − 1)·n_θ
// quadrilaterals over the n_r·n_θ grid nodes, whose connectivity wraps column n_θ − 1 to column 0 (the
// ring is closed by connectivity: no duplicated seam nodes, so gradients are continuous across θ = 0).
// The node coordinates and the fields are HDF5 virtual datasets (views, no storage) of /grid/x, /grid/y
// and /fields, flattened to (n_r·n_θ) or (n_r·n_θ, 3): every value is stored once. Valid against the
// XDMF 2 DTD (tests/data/Xdmf.dtd); read by ParaView (XDMF and Xdmf3 readers) and meshio.
#include <string>
#include <vector>

#include "io/hdf5_io.hpp"
#include "postproc/result.hpp"

namespace magnus {

/// Node index of grid point (i, j): i·n_θ + j (row-major, as the fields).
/// Quadrilateral k = i·n_θ + j (i < n_r − 1) has nodes (i, j), (i+1, j), (i+1, j+1 mod n_θ), (i, j+1 mod
/// n_θ): counter-clockwise in the (x, y) plane. Returns 4·(n_r − 1)·n_θ indices.
std::vector<int> quad_connectivity(size_t n_r, size_t n_theta);

/// Write /mesh: points (n_r·n_θ, 3) = view of (x, y, 0), quads ((n_r−1)·n_θ, 4) int32, and one view
/// (n_r·n_θ) per stored field, velocity (n_r·n_θ, 3) = view of (u_x, u_y, 0) when both are stored.
/// Needs /grid/x, /grid/y and /fields written first.
void write_mesh(const FlowResult& r, H5Writer& w);

/// The .xmf text referring to h5_name:/mesh/... (h5_name relative to the .xmf's directory).
std::string xdmf_text(const FlowResult& r, const std::string& h5_name);

}  // namespace magnus
