#pragma once
// The magnus driver: case → grid → ψ → fields → forces → files.
#include <string>
#include <vector>
#include "postproc/result.hpp"

namespace magnus {

/// Solve one case and post-process it (no files). threads ≥ 1. The memory the run needs is estimated
/// before anything large is allocated and refused if above max_bytes (0: the memory available).
FlowResult run_case(const Case& c, int threads = 1, size_t max_bytes = 0);

/// `magnus run`: solve, write HDF5 + XDMF atomically, print the summary. Throws on failure.
void command_run(const std::string& case_path, const std::string& output, const std::vector<std::string>& sets,
                int threads, bool quiet, size_t max_bytes = 0);

/// `magnus inspect`: print what a result holds. Throws on failure.
void command_inspect(const std::string& path);

}  // namespace magnus
