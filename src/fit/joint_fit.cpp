#include "fit/joint_fit.hpp"

#include <algorithm>

#include "common/errors.hpp"
#include "fit/toss_flags.hpp"

namespace bookspin::fit {

BiasFreedom bias_freedom(const std::vector<RecordingPart>& parts, const std::vector<TossData>& data,
                         const std::vector<bool>& held) {
  BiasFreedom b;
  const std::size_t groups = parts.size();
  b.bound.resize(groups);
  for (std::size_t g = 0; g < groups; ++g)
    if (parts[g].rest.samples > 0) b.bound[g] = parts[g].rest.bound();
  const std::vector<int> group_tosses = tosses_per_group(data, groups);
  b.held.assign(groups, false);
  for (std::size_t g = 0; g < groups && g < held.size(); ++g) b.held[g] = held[g];
  b.fitted.resize(groups);
  b.free.resize(groups);
  for (std::size_t g = 0; g < groups; ++g) {
    b.fitted[g] = group_tosses[g] >= 2 && !(g < held.size() && held[g]);
    b.free[g] = b.fitted[g] && !b.bound[g];
    b.any_bound = b.any_bound || (b.fitted[g] && b.bound[g]);
    b.fitted_groups += b.fitted[g];
  }
  return b;
}

Solved joint_fit(const std::vector<TossData>& data, Parameters& p, const BiasFreedom& bias,
                 const FitSettings& settings, const std::string& source,
                 std::vector<bool>& rate_held) {
  const bool fixed = settings.moments.has_value();
  const physics::DragLaw law = settings.drag;
  const auto failed = [&] {
    const std::string cause = scale_cause(data);
    return InputError(source + ": the fit did not converge" + (cause.empty() ? "" : ": " + cause));
  };
  for (double fraction : {0.3, 0.6, 1.0}) {
    SolveOptions options;
    options.stop = &settings.stop;
    options.moments_fixed = fixed;
    options.fraction = fraction;
    options.spacing = 0.01;
    options.drag = law;
    options.rates_fixed = fraction < 1.0;
    options.bias_group_held = bias.held;
    for (std::size_t g = 0; g < bias.free.size() && fraction < 1.0; ++g)
      options.bias_group_held[g] = bias.held[g] || bias.free[g];
    if (!solve(data, p, options).usable) throw failed();
    normalise(p);
  }
  SolveOptions full;
  full.stop = &settings.stop;
  full.moments_fixed = fixed;
  full.drag = law;
  full.bias_group_held = bias.held;
  if (bias.any_bound) {
    for (std::size_t g = 0; g < bias.bound.size(); ++g)
      if (bias.bound[g])
        for (int i = 0; i < 3; ++i)
          p.e[g][i] = std::clamp(p.e[g][i], -(*bias.bound[g])[i], (*bias.bound[g])[i]);
    full.bias_held = true;
    if (!solve(data, p, full).usable) throw failed();
    full.bias_held = false;
    full.bias_bound = bias.bound;
  }
  Solved solved = solve(data, p, full);
  if (!solved.usable) throw failed();
  if (law != physics::DragLaw::none) {
    full.rate_held.assign(data.size(), false);
    bool any = false;
    for (std::size_t k = 0; k < data.size(); ++k)
      if (p.omega0[k][3] < 0.0) {
        p.omega0[k][3] = 0.0;
        full.rate_held[k] = any = true;
      }
    if (any) {
      solved = solve(data, p, full);
      if (!solved.usable) throw failed();
    }
    rate_held = full.rate_held;
  }
  return solved;
}

}  // namespace bookspin::fit
