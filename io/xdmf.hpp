#pragma once
// XDMF sidecar: ParaView reads the fields on the curvilinear grid (X_Y geometry). The mesh is declared
// a 3DSMesh of (1, n_r, n_θ+1) nodes: ParaView 5.11's XDMF Reader reads vectors on such a mesh, not on a
// 2DSMesh (its hyperslab then has one rank too many), and its Xdmf3 readers crash on curvilinear grids.
#include <functional>
#include <string>
#include <vector>
#include "postproc/result.hpp"

namespace magnus {

/// A seam-closed array: the θ = 0 column repeated at θ = 2π so the ring closes.
struct XdmfArray {
  std::string name;
  std::vector<size_t> shape;  ///< (1, n_r, n_θ+1), or (1, n_r, n_θ+1, 3) for velocity
  std::vector<double> data;
  std::string units;
};

/// Visit x, y, every written field and the velocity vector (u_x, u_y, 0), one array at a time.
void for_each_xdmf_array(const FlowResult& r, const std::function<void(const XdmfArray&)>& visit);

/// The .xmf text referring to h5_name:/xdmf/...
std::string xdmf_text(const FlowResult& r, const std::string& h5_name);

}  // namespace magnus
