// The .xmf sidecar in the viewers themselves (opt-in: ctest -L viewers). Each test skips, with a note,
// when its viewer is not installed: meshio (python3-meshio, python3-h5py) and ParaView's pvpython.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "io/hdf5_io.hpp"
#include "io/viscous_fixture.hpp"
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

namespace {

/// A navier-stokes result by hand with `states` stored states, written to dir/ns.h5 (+ ns.xmf).
FlowResult write_viscous(const std::string& dir, int states) {
  const FlowResult r = test::viscous_result_by_hand(1.0, 32, 16, states);
  write_result(r, dir + "/ns.h5");
  return r;
}

}  // namespace

TEST_CASE("meshio reads a navier-stokes .xmf: the last state, and the stored states as a time series",
          "[viewers][viscous]") {
  if (!runs("/usr/bin/python3 -c 'import meshio, h5py'")) {
    WARN("skipped: meshio or h5py is not installed for /usr/bin/python3");
    return;
  }
  const std::string dir = test::temp_dir("viewer-meshio-ns");
  write_viscous(dir, 4);
  std::filesystem::create_directories(dir + "/none");
  write_viscous(dir + "/none", 0);
  // meshio.read takes one grid: a file without states; TimeSeriesReader takes the time series (its mesh
  // from the last state's grid, one step per stored state).
  const std::string script =
      "import sys, meshio, h5py, numpy as np\n"
      "d = sys.argv[1]\n"
      "m = meshio.read(d + '/none/ns.xmf')\n"
      "g = h5py.File(d + '/none/ns.h5', 'r')\n"
      "assert np.array_equal(m.point_data['vorticity'], g['fields/vorticity'][()].ravel())\n"
      "f = h5py.File(d + '/ns.h5', 'r')\n"
      "t, psi, vort = f['snapshots/t'][()], f['snapshots/psi'][()], f['snapshots/vorticity'][()]\n"
      "n = psi.shape[1] * psi.shape[2]\n"
      "with meshio.xdmf.TimeSeriesReader(d + '/ns.xmf') as r:\n"
      "    points, cells = r.read_points_cells()\n"
      "    assert points.shape == (n, 3) and cells[0].type == 'quad', (points.shape, cells)\n"
      "    assert r.num_steps == len(t) == 4, r.num_steps\n"
      "    for k in range(r.num_steps):\n"
      "        tk, pd, cd = r.read_data(k)\n"
      "        assert tk == t[k], (tk, t[k])\n"
      "        assert np.array_equal(pd['vorticity'], vort[k].ravel()), k\n"
      "        assert np.array_equal(pd['psi'], psi[k].ravel()), k\n"
      "print('ok')\n";
  std::string out;
  const int status = test::run_script("/usr/bin/python3", dir, script, {dir}, &out);
  CAPTURE(out);
  REQUIRE(status == 0);
}

TEST_CASE("ParaView's XDMF reader and both Xdmf3 readers play the stored states in time",
          "[viewers][viscous]") {
  if (!runs("command -v pvpython")) {
    WARN("skipped: pvpython (ParaView) is not installed");
    return;
  }
  const std::string dir = test::temp_dir("viewer-paraview-ns");
  write_viscous(dir, 3);
  // The XDMF reader gives both grids (the last state, static, and the time series: a multiblock); the
  // Xdmf3 readers give the time series. At each stored time, the state's own vorticity and ψ.
  const std::string script =
      "import sys, h5py, numpy as np\n"
      "from paraview.simple import *\n"
      "from paraview import servermanager\n"
      "from vtk.numpy_interface import dataset_adapter as dsa\n"
      "d = sys.argv[1]\n"
      "f = h5py.File(d + '/ns.h5', 'r')\n"
      "t, psi, vort = f['snapshots/t'][()], f['snapshots/psi'][()], f['snapshots/vorticity'][()]\n"
      "last = f['fields/vorticity'][()].ravel()\n"
      "n = psi.shape[1] * psi.shape[2]\n"
      "for make, key in ((XDMFReader, 'FileNames'), (Xdmf3ReaderS, 'FileName'), (Xdmf3ReaderT, "
      "'FileName')):\n"
      "    src = make(**{key: [d + '/ns.xmf'] if key == 'FileNames' else d + '/ns.xmf'})\n"
      "    src.UpdatePipelineInformation()\n"
      "    assert np.allclose(list(src.TimestepValues), t, rtol=0, atol=1e-12), (make, src.TimestepValues)\n"
      "    for k, tk in enumerate(t):\n"
      "        src.UpdatePipeline(tk)\n"
      "        w = dsa.WrapDataObject(servermanager.Fetch(src))\n"
      "        v, p = w.PointData['vorticity'], w.PointData['psi']\n"
      "        if hasattr(v, 'Arrays'):\n"
      "            blocks = [np.asarray(a) for a in v.Arrays]\n"
      "            assert len(blocks) == 2 and np.array_equal(blocks[0], last), make\n"
      "            v, p = blocks[1], np.asarray(p.Arrays[1])\n"
      "        assert np.asarray(v).shape == (n,), (make, np.asarray(v).shape)\n"
      "        assert np.array_equal(np.asarray(v), vort[k].ravel()), (make, k)\n"
      "        assert np.array_equal(np.asarray(p), psi[k].ravel()), (make, k)\n"
      "print('ok')\n";
  std::string out;
  const int status = test::run_script("pvpython", dir, script, {dir}, &out);
  CAPTURE(out);
  REQUIRE(status == 0);
}
