#pragma once
// The declared tables of the files beside the flow result (io/schema_table.hpp): the potential sweep and the
// navier-stokes S(Re, α) map (format "magnus-sweep", version 2) and the checkpoint ("magnus-checkpoint",
// version 1). Each lists every attribute, dataset and column once, in file order, with its unit and
// description; the writers, readers and --json outputs walk them (io/sweep_file.cpp, io/ns_sweep_file.cpp,
// io/checkpoint.cpp, io/json_output.cpp).
#include <vector>

#include "io/schema_table.hpp"
#include "postproc/navier_stokes/continuation.hpp"
#include "postproc/navier_stokes/run.hpp"
#include "postproc/potential/sweep.hpp"

namespace magnus {

/// The potential sweep's attributes: root, /parameters and /timing (file order, which is also the order of
/// `magnus sweep --json`; some rows are the file's or the JSON's only).
const std::vector<Attr<SweepResult>>& sweep_attributes();

/// The potential sweep's columns /sweep/NAME at each point (a SweepRow; angles in rad; alpha's description
/// follows the swept variable v).
std::vector<Column<SweepRow>> sweep_columns(SweepVariable v);

/// The S(Re, α) map's attributes: root (shard K of N, stability), /parameters (the grid) and /timing.
const std::vector<Attr<NsMap>>& ns_map_attributes();

/// The map's axes /axes/alpha and /axes/reynolds (the whole map's, every shard alike).
const std::vector<Dataset<NsMap>>& ns_map_axes();

/// The map's columns /sweep/NAME, one value per computed point (row-major).
const std::vector<Column<NsMapPoint>>& ns_map_columns();

/// What a checkpoint is written from: the case it continues (its identity key and text) and the state.
struct CheckpointOut {
  const Case& c;
  const Checkpoint& cp;
};

/// The checkpoint's attributes: root (format, key, case) and /state (t, Γ_R, the previous step's flux and
/// dt, the steps taken); each number is read back into a Checkpoint.
const std::vector<Attr<CheckpointOut, Checkpoint>>& checkpoint_attributes();

/// The checkpoint's datasets, flat: /state/psi, zeta, N_prev (read back by their set), then the history's
/// columns /history/NAME and the snapshots /snapshots/t, psi, vorticity (each state after the other; both
/// assembled by the reader, io/checkpoint.cpp).
const std::vector<Dataset<CheckpointOut, Checkpoint>>& checkpoint_datasets();

/// The history's columns: name in /history and member of ForceSample, in file order.
const std::vector<std::pair<const char*, double ForceSample::*>>& checkpoint_history_members();

}  // namespace magnus
