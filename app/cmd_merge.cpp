// magnus merge OUT.h5 SHARD.h5… — one S(Re, α) map from the shards of `magnus sweep --shard K/N`.
#include <fmt/core.h>

#include <cstdio>
#include <memory>

#include "app/commands.hpp"
#include "base/atomic_file.hpp"
#include "io/ns_sweep_file.hpp"

namespace magnus {

namespace {

struct MergeOptions {
  std::string output;
  std::vector<std::string> shards;
  bool quiet = false;
};

void command_merge(const MergeOptions& o) {
  check_distinct_paths(o.shards, {o.output});
  check_file_writable(o.output, "the merged HDF5 sweep file");
  std::vector<NsMap> maps;
  for (const auto& p : o.shards) maps.push_back(read_ns_map_hdf5(p));
  const NsMap m = merge_ns_maps(maps, o.shards);
  write_ns_map_hdf5(m, o.output);
  if (!o.quiet)
    std::printf("%s: %zu points (%zu Re × %zu α) from %zu shards\n", o.output.c_str(), m.points.size(),
                m.reynolds.size(), m.alphas.size(), maps.size());
}

}  // namespace

void add_merge_command(CLI::App& app) {
  auto o = std::make_shared<MergeOptions>();
  auto* merge = app.add_subcommand(
      "merge", "one navier-stokes sweep file from the shards of magnus sweep --shard K/N (checked complete)");
  output_file(merge->add_option("output", o->output, "the merged sweep file (HDF5)")->required());
  add_force_flag(merge);
  merge->add_option("shards", o->shards, "the shard files, one per K of K/N")->required();
  merge->add_flag("-q,--quiet", o->quiet, "print nothing on success");
  merge->callback([o] { command_merge(*o); });
}

}  // namespace magnus
