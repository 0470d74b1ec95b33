#include "analysis/Analysis.hpp"

#include "output/OutputDirectory.hpp"

namespace choc {

bool RunContext::failedChecks() const {
  for (const auto& c : checks)
    if (!c.ok) return true;
  return false;
}

const StateArchive* Analysis::resumeFor(const RunContext& ctx) const {
  if (!ctx.restart || ctx.restart->text("identity/analysis") != name_) return nullptr;
  return ctx.restart.get();
}

CheckpointPlan Analysis::checkpointPlan(const RunContext& ctx) const {
  CheckpointPlan p;
  p.path = ctx.outputDir + "/" + name_ + suffix::checkpoint;
  p.identity.analysis = name_;
  if (ctx.input) p.identity.input = canonicalInput(*ctx.input, name_);
  p.identity.mesh = meshHash(ctx.model.mesh());
  p.identity.ranks = ctx.model.comm()->getSize();
  return p;
}

}  // namespace choc
