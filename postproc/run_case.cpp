#include "postproc/run_case.hpp"

namespace magnus {

FlowResult run_case(const Case& c, const RunHooks& hooks) {
  if (c.model == FlowModel::navier_stokes) {
    if (hooks.on_plan) hooks.on_plan(c);
    ViscousHooks vh = hooks.viscous;
    if (hooks.max_bytes > 0) vh.max_bytes = hooks.max_bytes;
    FlowResult r = run_viscous(c, vh, hooks.resume, hooks.threads);
    if (r.viscous) set_onset3d(*r.viscous, c.scene.spin_ratio(), hooks.onset3d, hooks.onset3d_files);
    return r;
  }
  const RunPlan plan = plan_run(c, hooks.threads, hooks.max_bytes);
  if (hooks.on_plan) hooks.on_plan(plan.c);
  return run_planned(plan, hooks.threads, hooks.max_bytes);
}

}  // namespace magnus
