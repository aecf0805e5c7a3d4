#include "io/checkpoint.hpp"

#include <fmt/core.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <stdexcept>

#include "io/hdf5_io.hpp"
#include "io/schema_files.hpp"
#include "io/schema_io.hpp"
#include "solver/navier_stokes/rotation.hpp"

namespace magnus {

namespace {

constexpr const char* kFormat = "magnus-checkpoint";

/// The entries of a stored key "key=value key=value …", in order.
std::vector<IdentityEntry> parse_key(const std::string& key) {
  std::vector<IdentityEntry> out;
  size_t b = 0;
  while (b < key.size()) {
    size_t e = key.find(' ', b);
    if (e == std::string::npos) e = key.size();
    const std::string item = key.substr(b, e - b);
    const size_t eq = item.find('=');
    if (eq != std::string::npos) out.push_back({item.substr(0, eq), item.substr(eq + 1)});
    b = e + 1;
  }
  return out;
}

/// Whether two values of one parameter agree: as numbers when both read as numbers, else as text.
bool same_value(const std::string& a, const std::string& b) {
  char *ea = nullptr, *eb = nullptr;
  const double x = std::strtod(a.c_str(), &ea), y = std::strtod(b.c_str(), &eb);
  if (!a.empty() && !b.empty() && *ea == '\0' && *eb == '\0') return x == y;
  return a == b;
}

/// "" when the stored key continues case c; else one line saying which parameters differ (there, here).
std::string identity_mismatch(const std::string& path, const std::string& stored, const Case& c) {
  const std::vector<IdentityEntry> there = parse_key(stored), here = checkpoint_identity(c);
  auto find = [](const std::vector<IdentityEntry>& v, const std::string& k) -> const IdentityEntry* {
    for (const IdentityEntry& e : v)
      if (e.key == k) return &e;
    return nullptr;
  };
  // A key without the advection orders comes from an older magnus: it cannot say what it was run with.
  if (!find(there, "solver.advection_order"))
    return fmt::format(
        "checkpoint '{}' does not record the advection orders (an older magnus wrote it): "
        "remove it or run without --resume",
        path);
  std::string diff;
  auto add = [&diff](const std::string& key, const std::string& a, const std::string& b) {
    diff += fmt::format("{}{} {} there, {} here", diff.empty() ? "" : "; ", key, a, b);
  };
  for (const IdentityEntry& h : here) {
    const IdentityEntry* t = find(there, h.key);
    if (!t)
      add(h.key, "undefined", h.value);
    else if (!same_value(t->value, h.value))
      add(h.key, t->value, h.value);
  }
  for (const IdentityEntry& t : there)
    if (!find(here, t.key)) add(t.key, t.value, "undefined");
  if (diff.empty()) return "";
  return fmt::format("checkpoint '{}' is from another scene: {}", path, diff);
}

}  // namespace

std::string checkpoint_path(const std::string& result_path) {
  const size_t slash = result_path.rfind('/');
  const size_t dot = result_path.rfind('.');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return (has_ext ? result_path.substr(0, dot) : result_path) + ".checkpoint.h5";
}

std::vector<IdentityEntry> checkpoint_identity(const Case& c) {
  const NsParams p = ns_params(c);
  const PolarGrid g = ns_grid(p);  // the grid as built: n_r = 0 asks for square cells
  auto num = [](double v) { return fmt::format("{}", v + 0.0); };  // shortest text that reads back exactly
  std::vector<IdentityEntry> id = {
      {"cylinder.radius", num(p.a)}, {"flow.speed", num(p.U)}, {"cylinder.spin", num(p.omega)}};
  if (p.U > 0.0) id.push_back({"cylinder.spin_ratio", num(p.a * p.omega / p.U)});
  id.push_back({"flow.viscosity", num(p.nu)});
  if (p.U > 0.0) id.push_back({"flow.reynolds", num(p.U * 2.0 * p.a / p.nu)});
  id.push_back({"flow.density", num(c.scene.density)});
  id.push_back({"domain.outer_radius", num(g.outer_radius() / p.a)});
  if (p.absorbing_start > 0.0) {  // no layer: no entries, as checkpoints stored before the layer
    id.push_back({"domain.absorbing_layer", num(p.absorbing_start)});
    id.push_back({"domain.absorbing_strength", num(c.grid.absorbing_strength)});
  }
  id.push_back({"grid.n_theta", std::to_string(g.n_theta)});
  id.push_back({"grid.n_r", std::to_string(g.n_r)});
  if (p.wall_refinement != 1.0) {  // uniform ξ: no entries, as checkpoints stored before the stretched rings
    id.push_back({"grid.wall_refinement", num(p.wall_refinement)});
    id.push_back({"grid.wall_layer", num(p.wall_layer)});
  }
  id.push_back({"solver.advection_order", std::to_string(p.advection_order)});
  id.push_back({"solver.advection_order_xi", std::to_string(p.advection_order_xi)});
  if (p.wall_closure != NsWallClosure::thom)  // Thom's: no entry, as checkpoints stored before the option
    id.push_back({"solver.wall_closure", "jensen"});
  // Its N_prev is the explicit part J(ψ − ψ_ref, ζ): a checkpoint of the other scheme is refused (before the
  // key every checkpoint was explicit: no entry, as for ω = 0 and the cases that stay explicit).
  if (rotation_implicit(p)) id.push_back({"solver.implicit_rotation", "true"});
  return id;
}

std::string checkpoint_key(const Case& c) {
  std::string key;
  for (const IdentityEntry& e : checkpoint_identity(c))
    key += (key.empty() ? "" : " ") + e.key + "=" + e.value;
  return key;
}

void write_checkpoint(const std::string& path, const Case& c, const Checkpoint& cp) {
  write_hdf5_atomic(path, [&](H5Writer& w) {
    const CheckpointOut out{c, cp};
    FileGroups g{w};
    write_attrs(attr_values(checkpoint_attributes(), out, Shown::file_only), g, Gaps::as_is);
    write_datasets(g, checkpoint_datasets(), out, Gaps::as_is);
  });
}

namespace {

/// The history and the kept snapshots from their arrays (read_datasets' rest); throws when they do not match
/// the state.
void assemble(const std::string& path, std::map<std::string, std::vector<double>>& a, Checkpoint& cp) {
  const auto& cols = checkpoint_history_members();
  cp.history.resize(a["/history/t"].size());
  for (const auto& [name, m] : cols) {
    const std::vector<double>& v = a[std::string("/history/") + name];
    if (v.size() != cp.history.size())
      throw std::runtime_error(
          fmt::format("--resume: '{}' is damaged: /history columns differ in length", path));
    for (size_t q = 0; q < v.size(); ++q) cp.history[q].*m = v[q];
  }
  const std::vector<double>&t = a["/snapshots/t"], &psi = a["/snapshots/psi"], &zeta = a["/snapshots/vorticity"];
  const size_t n = cp.state.psi.size();
  if (cp.state.zeta.size() != n || psi.size() != t.size() * n || zeta.size() != t.size() * n)
    throw std::runtime_error(fmt::format("--resume: '{}' is damaged: its arrays do not match", path));
  for (size_t k = 0; k < t.size(); ++k)
    cp.snapshots.push_back({t[k],
                            {psi.begin() + long(k * n), psi.begin() + long((k + 1) * n)},
                            {zeta.begin() + long(k * n), zeta.begin() + long((k + 1) * n)}});
}

}  // namespace

Checkpoint read_checkpoint(const std::string& path, const Case& c) {
  std::unique_ptr<ResultFile> f;
  try {
    f = std::make_unique<ResultFile>(path, std::vector<std::string>{kFormat});
  } catch (const std::exception& e) {
    throw std::runtime_error(fmt::format("--resume: {}", e.what()));
  }
  const std::string mismatch = identity_mismatch(path, f->attr_string("/", "key"), c);
  if (!mismatch.empty()) {
    const bool old_magnus = mismatch.find("does not record") != std::string::npos;
    throw std::runtime_error(old_magnus ? mismatch : mismatch + "; remove it or run without --resume");
  }
  // Every value is checked as it is read: a non-finite one is refused naming where it is.
  auto non_finite = [&path](const std::string& name) {
    return std::runtime_error(fmt::format("checkpoint '{}': {} holds a non-finite value", path, name));
  };
  Checkpoint cp;
  read_attrs(checkpoint_attributes(), *f, cp);
  const CheckpointOut out{c, cp};
  for (const auto& a : checkpoint_attributes())
    if (a.kind == AttrKind::number && !std::isfinite(*a.number(out)))
      throw non_finite(std::string(a.group) + "/" + a.name);
  auto rest = read_datasets(checkpoint_datasets(), *f, cp, [&](const std::string& name, const std::vector<double>& v) {
    for (double e : v)
      if (!std::isfinite(e)) throw non_finite(name);
  });
  assemble(path, rest, cp);
  for (ForceSample& h : cp.history) h.has_coefficients = c.scene.speed > 0.0;
  return cp;
}

std::string foreign_checkpoint(const std::string& path, const Case& c) {
  std::string stored;
  try {
    const ResultFile f(path, std::vector<std::string>{kFormat});
    stored = f.attr_string("/", "key");
  } catch (const std::exception&) {
    return "";  // none, or not a checkpoint that can say whose it is
  }
  const std::string mismatch = identity_mismatch(path, stored, c);
  if (mismatch.empty()) return "";
  if (mismatch.find("does not record") != std::string::npos)  // an older magnus's: whose it is is unknown
    return fmt::format(
        "checkpoint '{}' does not record its scene fully (an older magnus wrote it); a run from rest would "
        "overwrite it: remove it or give another -o",
        path);
  return mismatch +
         "; a run from rest would overwrite it: resume that scene (--resume), remove it, or give "
         "another -o";
}

}  // namespace magnus
