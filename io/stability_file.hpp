#pragma once
// The spectra of `magnus stability` as an HDF5 file (format "magnus-stability", version 1): the 2D
// eigenvalues of the steady state, the spanwise (3D) scan per wavenumber, and the search for the 3D
// onset, written from the command's JSON object so that the file and `--json` carry the same numbers.
//
//     /            format, format_version, software_version, model, title, case (TOML), reynolds,
//                  spin_ratio, stable (0/1), eigensolver
//     /eigenvalues growth_rate, frequency (λ·D/U), strouhal, residual          one row per eigenvalue
//     /spanwise    beta_D, wavelength_D, growth_rate, frequency, covered, solves, seconds
//                  (+ multiplier_real, multiplier_imag of an orbit); attrs base, verdict, accuracy_note, stable,
//                  period (D/U), most_unstable_beta_D, most_unstable_wavelength_D, most_unstable_growth_rate
//     /onset3d     reynolds, periodic (0/1), growth_rate, beta_D, seconds      one row per Reynolds number
//                  attrs found, critical_reynolds, change, bracket_lo, bracket_hi, beta_D, wavelength_D,
//                  message (when not found), accuracy_note
// Undefined values are never stored as NaN: a column's undefined rows hold the fill value named by its
// _FillValue attribute, an undefined attribute is listed in its group's `undefined` attribute.
#include <string>

#include "io/json_output.hpp"
#include "postproc/navier_stokes/spanwise_critical.hpp"
#include "postproc/run_case.hpp"

namespace magnus {

/// Write the stability result j (the object `magnus stability --json` prints; no 2D onset search) with the
/// case's title and TOML text to path, atomically. Throws std::runtime_error with one line naming path.
void write_stability_hdf5(const std::string& path, const Json& j, const std::string& title,
                          const std::string& case_text);

/// The 3D onset a stability file holds (written with --spanwise --critical-reynolds): its spin ratio and
/// critical Reynolds number (the fine grid's, /onset3d/fine_grid, when it was refined there and found).
/// Throws std::runtime_error (one line naming path) when the file is not a magnus-stability file or holds no
/// onset that was found.
Onset3d read_onset3d(const std::string& path);

/// A run's computed 3D onset curve: read_onset3d of each file into hooks (onset3d, onset3d_files), before
/// solving. Throws std::invalid_argument ("<option>: only for a navier-stokes case …") for potential flow,
/// and what read_onset3d throws.
void give_onset3d(RunHooks& hooks, const Case& c, const std::vector<std::string>& files, const std::string& option);

}  // namespace magnus
