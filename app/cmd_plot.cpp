// magnus plot FILE [-o DIR] [--size WxH] [--window X0:X1,Y0:Y1] [--onset3d FILE.h5]… [--movie FILM [--fps N]] [-q]
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/movie.hpp"
#include "app/plot_files.hpp"

namespace magnus {

void add_plot_command(CLI::App& app) {
  struct Options {
    std::string file, dir, size, window, movie;
    std::vector<std::string> onset;
    int fps = 12;
    bool quiet = false;
  };
  auto o = std::make_shared<Options>();
  auto* plot = app.add_subcommand(
      "plot",
      "PNG pictures of a result (streamlines, the Cp field, surface Cp against exact; navier-stokes adds the "
      "vorticity, C_L and C_D against time and the wall shear stress) or of a sweep (C_L); or, with --movie, "
      "a film of a navier-stokes result's snapshots");
  plot->add_option("file", o->file, "result file (HDF5, from magnus run) or sweep file (magnus sweep -o)")
      ->required();
  auto* dir = output_file(
      plot->add_option("-o,--output-dir", o->dir, "directory for the PNGs (default: beside the result)"));
  add_force_flag(plot);
  plot->add_option("--size", o->size, "PNG (or film frame) size WxH in pixels (default 1000x800)");
  plot->add_option("--window", o->window,
                   "the field pictures' window X0:X1,Y0:Y1 in units of the radius, wind frame (e.g. -5:25,-6:6; "
                   "default: ±4 around the body, or -5:25,-6:6 down the wake of an unsteady navier-stokes result)");
  auto* movie = output_file(plot->add_option(
      "--movie", o->movie,
      "instead of the PNGs, a film (.mp4 or .gif, encoded by ffmpeg) of a navier-stokes result's snapshots "
      "(output.snapshots = N): each frame the vorticity, over one colour range, above C_L and C_D against "
      "time with the frame's time marked"));
  movie->excludes(dir);
  plot->add_option("--fps", o->fps, "the film's frames a second (default 12)")->needs(movie);
  auto* onset = plot->add_option("--onset3d", o->onset,
                                 "with an S(Re, α) map: a stability file holding a 3D onset (magnus stability "
                                 "--spanwise --critical-reynolds A:B --output FILE; repeatable, one per α); points "
                                 "above the onset curve are marked as three-dimensional");
  onset->excludes(movie);
  plot->add_flag("-q,--quiet", o->quiet, "do not list the files written");
  plot->callback([o] {
    if (o->movie.empty()) return command_plot(o->file, o->dir, o->size, o->window, o->quiet, o->onset);
    const PlotSize size = o->size.empty() ? PlotSize{} : parse_plot_size(o->size);
    std::optional<PlotWindow> window;
    if (!o->window.empty()) window = parse_plot_window(o->window);
    make_movie(o->file, o->movie, size, window, o->fps);
    if (!o->quiet) std::printf("%s\n", o->movie.c_str());
  });
}

}  // namespace magnus
