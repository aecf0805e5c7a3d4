#pragma once
// Checkpoints of a navier-stokes run (format "magnus-checkpoint", version 1): the state of the time
// stepper, the force history and the kept snapshots, written atomically beside the result so that a killed
// run resumes (`magnus run CASE --resume`) and loses at most one checkpoint interval.
#include <string>
#include <vector>

#include "postproc/navier_stokes/run.hpp"

namespace magnus {

/// The checkpoint file of a result path: "out.h5" → "out.checkpoint.h5".
std::string checkpoint_path(const std::string& result_path);

/// One parameter a checkpoint must share with the case it continues: the case key it comes from and its
/// value as text (the shortest form that reads back exactly).
struct IdentityEntry {
  std::string key, value;
};

/// What must agree for a checkpoint to continue a case: the scene (a m, U m/s, ω rad/s, α = aω/U, ν m²/s,
/// Re = U·2a/ν, ρ kg/m³), the grid as built (R/a, n_θ, n_r), the advection orders in θ and ξ and whether
/// the spin is implicit (solver.implicit_rotation, stored only when it is in effect);
/// time.end, the output and the tolerances may change between runs. α and Re only when U > 0.
std::vector<IdentityEntry> checkpoint_identity(const Case& c);

/// The identity as the file stores it: "key=value key=value …" (checkpoint_identity's entries).
std::string checkpoint_key(const Case& c);

/// Write cp for case c to path atomically (temporary name, then rename).
void write_checkpoint(const std::string& path, const Case& c, const Checkpoint& cp);

/// For a run from rest of case c: "" when the checkpoint at path may be overwritten (there is none, it is
/// unreadable, or it is c's scene); else one line saying whose it is (each parameter that differs) and
/// that the run would overwrite it.
std::string foreign_checkpoint(const std::string& path, const Case& c);

/// Read the checkpoint at path for case c. Throws std::runtime_error in one line when it is missing,
/// damaged, holds a non-finite value (naming the dataset or attribute), or belongs to another scene or grid
/// (naming each parameter that differs, with its value there and here).
Checkpoint read_checkpoint(const std::string& path, const Case& c);

}  // namespace magnus
