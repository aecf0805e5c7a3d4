// The .xmf sidecar in the viewers themselves (opt-in: ctest -L viewers). Each test skips, with a note,
// when its viewer is not installed: meshio (python3-meshio, python3-h5py) and ParaView's pvpython.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>

#include "io/hdf5_io.hpp"
#include "support.hpp"

using namespace magnus;

namespace {

bool runs(const std::string& cmd) { return std::system((cmd + " >/dev/null 2>&1").c_str()) == 0; }

/// A result with every field on a small grid, written to dir/flow.h5 (+ flow.xmf).
FlowResult write_flow(const std::string& dir) {
  Case c = test::make_case(1.0, 32);
  c.output.fields.reset();
  const FlowResult r = run_case(c);
  write_result(r, dir + "/flow.h5");
  return r;
}

}  // namespace

TEST_CASE("meshio reads the .xmf: nodes, quadrilaterals, every field and the velocity", "[viewers]") {
  if (!runs("/usr/bin/python3 -c 'import meshio, h5py'")) {
    WARN(
        "skipped: meshio or h5py is not installed for /usr/bin/python3 (apt-get install python3-meshio "
        "python3-h5py)");
    return;
  }
  const std::string dir = test::temp_dir("viewer-meshio");
  const FlowResult r = write_flow(dir);
  const size_t nr = r.grid.n_r, nt = r.grid.n_theta;
  const std::string script =
      "import sys, meshio, h5py, numpy as np\n"
      "m = meshio.read(sys.argv[1] + '/flow.xmf')\n"
      "nr, nt = int(sys.argv[2]), int(sys.argv[3])\n"
      "assert m.points.shape == (nr * nt, 3), m.points.shape\n"
      "q = m.cells_dict['quad']\n"
      "assert q.shape == ((nr - 1) * nt, 4) and q.min() == 0 and q.max() == nr * nt - 1\n"
      "f = h5py.File(sys.argv[1] + '/flow.h5', 'r')\n"
      "for name in f['fields']:\n"
      "    assert np.array_equal(m.point_data[name], f['fields'][name][()].ravel()), name\n"
      "assert m.point_data['velocity'].shape == (nr * nt, 3)\n"
      "print('ok')\n";
  std::string out;
  const int status =
      test::run_script("/usr/bin/python3", dir, script, {dir, std::to_string(nr), std::to_string(nt)}, &out);
  CAPTURE(out);
  REQUIRE(status == 0);
}

TEST_CASE("ParaView's XDMF reader and both Xdmf3 readers open the .xmf", "[viewers]") {
  if (!runs("command -v pvpython")) {
    WARN("skipped: pvpython (ParaView) is not installed");
    return;
  }
  const std::string dir = test::temp_dir("viewer-paraview");
  const FlowResult r = write_flow(dir);
  const size_t n = size_t(r.grid.n_r) * size_t(r.grid.n_theta),
               cells = size_t(r.grid.n_r - 1) * size_t(r.grid.n_theta);
  const std::string script =
      "import sys\n"
      "from paraview.simple import *\n"
      "path, n, cells = sys.argv[1] + '/flow.xmf', int(sys.argv[2]), int(sys.argv[3])\n"
      "import numpy as np\n"
      "from paraview import servermanager\n"
      "from vtk.numpy_interface import dataset_adapter as dsa\n"
      "for make, key in ((XDMFReader, 'FileNames'), (Xdmf3ReaderS, 'FileName'), (Xdmf3ReaderT, "
      "'FileName')):\n"
      "    src = make(**{key: [path] if key == 'FileNames' else path})\n"
      "    src.UpdatePipeline()\n"
      "    info = src.GetDataInformation()\n"
      "    assert info.GetNumberOfPoints() == n, (make, info.GetNumberOfPoints())\n"
      "    assert info.GetNumberOfCells() == cells, (make, info.GetNumberOfCells())\n"
      "    assert src.PointData['velocity'].GetNumberOfComponents() == 3\n"
      "# The ring is closed by connectivity: ParaView's vorticity of the (irrotational) flow is no "
      "larger\n"
      "# on the seam θ = 0 than elsewhere (a seam closed only in space gave 4.09 there against 0.06).\n"
      "g = Gradient(Input=src)\n"
      "g.ScalarArray = ['POINTS', 'velocity']\n"
      "g.ComputeVorticity = 1\n"
      "d = dsa.WrapDataObject(servermanager.Fetch(g))\n"
      "w = np.abs(np.asarray(d.PointData['Vorticity'])[:, 2])\n"
      "p = np.asarray(d.Points)\n"
      "seam = (np.abs(p[:, 1]) < 1e-12) & (p[:, 0] > 0)\n"
      "assert seam.sum() > 0 and w[seam].max() <= 0.5 * w[~seam].max(), (w[seam].max(), w[~seam].max())\n"
      "print('ok')\n";
  std::string out;
  const int status =
      test::run_script("pvpython", dir, script, {dir, std::to_string(n), std::to_string(cells)}, &out);
  CAPTURE(out);
  REQUIRE(status == 0);
}

TEST_CASE("xarray (h5netcdf) sees the fields' dimensions as r and theta, with their values", "[viewers]") {
  if (!runs("/usr/bin/python3 -c 'import xarray, h5netcdf'")) {
    WARN("skipped: xarray or h5netcdf is not installed (apt-get install python3-xarray python3-h5netcdf)");
    return;
  }
  const std::string dir = test::temp_dir("viewer-xarray");
  const FlowResult r = write_flow(dir);
  const std::string script =
      "import sys, xarray as xr, numpy as np\n"
      "path, nr, nt = sys.argv[1] + '/flow.h5', int(sys.argv[2]), int(sys.argv[3])\n"
      "f = xr.open_dataset(path, engine='h5netcdf', group='fields', phony_dims='access')\n"
      "for name in f.data_vars:\n"
      "    assert f[name].dims == ('r', 'theta'), (name, f[name].dims)\n"
      "assert f['psi'].shape == (nr, nt)\n"
      "root = xr.open_dataset(path, engine='h5netcdf', phony_dims='access')\n"
      "assert root['r'].dims == ('r',) and root['theta'].dims == ('theta',)\n"
      "assert root['r'].values[0] > 0 and np.all(np.diff(root['theta'].values) > 0)\n"
      "print('ok')\n";
  std::string out;
  const int status =
      test::run_script("/usr/bin/python3", dir, script,
                       {dir, std::to_string(r.grid.n_r), std::to_string(r.grid.n_theta)}, &out);
  CAPTURE(out);
  REQUIRE(status == 0);
}
