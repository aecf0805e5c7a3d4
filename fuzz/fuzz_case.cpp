// libFuzzer target for the case-file parser and the --set parser.
//
// Each input is used twice:
//   1. as a whole TOML case file: parse_case(text, "fuzz.toml");
//   2. split on newlines into "section.key=value" overrides applied to a case with only the required scene.
// CaseError is the parser's one documented failure and is caught. Anything else is a finding:
// another exception (it escapes, std::terminate aborts), a crash, a hang, a sanitizer report,
// or a broken invariant of an accepted case (checked below, reported by abort()).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "io/case_file.hpp"

using namespace magnus;

namespace {

[[noreturn]] void finding(const char* what, const std::string& detail) {
  std::fprintf(stderr, "fuzz_case: invariant broken: %s\n%s\n", what, detail.c_str());
  std::abort();
}

/// What every accepted case must satisfy (the case-file ranges), and its resolved TOML must read back the
/// same.
void check_accepted(const Case& c) {
  for (double v : {c.scene.radius, c.scene.spin, c.scene.speed, c.scene.density, c.scene.pressure_inf,
                   c.scene.circulation_value, c.grid.outer_radius, c.grid.tolerance, c.scene.Gamma(),
                   c.scene.spin_ratio()})
    if (!std::isfinite(v)) finding("a number of an accepted case is not finite", c.source_text);
  if (!(c.scene.radius > 0 && c.scene.speed >= 0 && c.scene.density > 0 && c.grid.outer_radius > 1))
    finding("a range check let a value through", c.source_text);
  if (c.grid.n_theta < 8 || c.grid.n_theta % 2 != 0 || c.grid.n_r < 0 || c.output.file.empty())
    finding("a grid or output check let a value through", c.source_text);
  // The viscosity (given, or derived from Re) and the Reynolds number: finite, and ν > 0 when given.
  if (!std::isfinite(c.scene.viscosity) || c.scene.viscosity < 0 || !std::isfinite(c.scene.reynolds()) ||
      (c.scene.reynolds_given && !(c.scene.reynolds_value > 0 && c.scene.viscosity > 0)))
    finding("a viscosity check let a value through", c.source_text);
  if (c.model == FlowModel::navier_stokes) {
    const TimeRequest& t = c.time;
    if (!(c.scene.viscosity > 0) || (c.scene.speed == 0 && c.scene.spin == 0) || c.scene.circulation_given ||
        c.grid.tolerance != 0 || c.grid.spacing != Spacing::geometric ||
        !std::isfinite(c.scene.reference_speed() * 2.0 * c.scene.radius / c.scene.viscosity))
      finding("a navier-stokes case check let a value through", c.source_text);
    if (!(t.end > 0 && std::isfinite(t.end) && t.dt >= 0 && std::isfinite(t.dt) && t.cfl > 0 &&
          t.cfl <= 0.8 && t.mean_tolerance > 0 && t.mean_tolerance <= 0.1 && t.checkpoint_interval >= 0 &&
          std::isfinite(t.checkpoint_interval) && c.output.snapshots >= 0 && c.output.snapshots <= 10000 &&
          c.output.snapshot_interval > 0 && std::isfinite(c.output.snapshot_interval)))
      finding("a [time] or snapshot check let a value through", c.source_text);
  }
  // The resolved case is stored in every result and echoed: it must be a valid case that resolves to itself.
  Case again;
  try {
    again = parse_case(c.source_text, "resolved.toml");
  } catch (const CaseError& e) {
    finding("the resolved TOML of an accepted case does not parse",
            std::string(e.what()) + "\n" + c.source_text);
  }
  if (again.source_text != c.source_text)
    finding("the resolved TOML does not resolve to itself", c.source_text + "\n---\n" + again.source_text);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);

  // 1. The whole input as a case file.
  try {
    check_accepted(parse_case(text, "fuzz.toml"));
  } catch (const CaseError&) {
  }

  // 2. Each line as a --set override on a case with only the required scene (and with more sections present).
  std::vector<std::string> sets;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t nl = text.find('\n', start);
    const size_t end = nl == std::string::npos ? text.size() : nl;
    sets.push_back(text.substr(start, end - start));
    if (nl == std::string::npos) break;
    start = nl + 1;
  }
  const std::string scene = "[cylinder]\nradius = 0.1\nspin = 100.0\n[flow]\nspeed = 10.0\n";
  for (const std::string& base : {scene, scene + "[grid]\n[output]\n"}) {
    try {
      check_accepted(parse_case(base, "fuzz.toml", sets));
    } catch (const CaseError&) {
    }
  }
  return 0;
}
