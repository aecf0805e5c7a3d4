#pragma once
// Speed against error: a ladder of grids for each solver and stencil (magnus bench).
#include <cmath>
#include <functional>
#include <string>
#include <vector>
#include "physics/scene.hpp"

namespace magnus {

struct BenchOptions {
  std::vector<int> ladder = {32, 64, 128, 256, 512, 1024};  ///< n_θ of each rung
  std::vector<Method> methods = {Method::cholmod, Method::fft};
  std::vector<StencilKind> stencils = {StencilKind::five_point, StencilKind::nine_point};
  int repeats = 5;                     ///< median over this many runs of each rung
  long cholmod_max_unknowns = 300000;  ///< larger CHOLMOD rungs are skipped (time)
  int threads = 1;
};

/// One rung: median wall times (s) of each phase and the errors against the exact solution.
struct BenchRow {
  std::string method, stencil;
  int n_theta = 0, n_r = 0;
  long unknowns = 0;
  double setup_s = 0, factor_s = 0, solve_s = 0,
         post_s = 0;   ///< grid+operator+assembly, factor, solve, forces
  double total_s = 0;  ///< the sum: what one lift figure costs
  double cl_rel = 0, psi_rel = 0, cp_abs = 0;
  double order_cl = NAN, order_psi = NAN;  ///< observed order against the previous rung, NaN if none
};

/// Run the ladder for a case. progress(text) is called before each rung.
std::vector<BenchRow> run_bench(const Case& base, const BenchOptions& opt,
                                const std::function<void(const std::string&)>& progress = {});

}  // namespace magnus
