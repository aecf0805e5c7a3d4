// magnus plot FILE [-o DIR] [--size WxH] [--window X0:X1,Y0:Y1] [-q]
#include <memory>

#include "app/commands.hpp"
#include "app/plot_files.hpp"

namespace magnus {

void add_plot_command(CLI::App& app) {
  struct Options {
    std::string file, dir, size, window;
    bool quiet = false;
  };
  auto o = std::make_shared<Options>();
  auto* plot = app.add_subcommand(
      "plot",
      "PNG pictures of a result (streamlines, the Cp field, surface Cp against exact; navier-stokes adds the "
      "vorticity, C_L and C_D against time and the wall shear stress) or of a sweep (C_L)");
  plot->add_option("file", o->file, "result file (HDF5, from magnus run) or sweep file (magnus sweep -o)")
      ->required();
  output_file(plot->add_option("-o,--output-dir", o->dir, "directory for the PNGs (default: beside the result)"));
  add_force_flag(plot);
  plot->add_option("--size", o->size, "PNG size WxH in pixels (default 1000x800)");
  plot->add_option("--window", o->window,
                   "the field pictures' window X0:X1,Y0:Y1 in units of the radius, wind frame (e.g. -5:25,-6:6; "
                   "default: ±4 around the body, or -5:25,-6:6 down the wake of an unsteady navier-stokes result)");
  plot->add_flag("-q,--quiet", o->quiet, "do not list the files written");
  plot->callback([o] { command_plot(o->file, o->dir, o->size, o->window, o->quiet); });
}

}  // namespace magnus
