#include "fit/fit_tables.hpp"

#include <sstream>

#include "fit/pool.hpp"

namespace bookspin::fit {

std::string fixed(double value, int digits) {
  std::ostringstream text;
  text.precision(digits);
  text << std::fixed << value;
  return text.str();
}

namespace {

/// Pooled time `t` (s) in its own recording's time, and that recording's name (empty for a
/// recording not pooled).
std::pair<double, std::string> own_time(const FitResult& fit, double t) {
  const RecordingPart* part = part_at(fit.parts, t);
  if (!part) return {t, {}};
  return {t - part->t_offset, part->name};
}

}  // namespace

CsvTable fit_toss_csv(const FitResult& fit) {
  CsvTable table{{"toss", "t_start", "t_end", "omega0_x", "omega0_y", "omega0_z",
                  "half_period_measured", "half_period_fitted", "half_period_predicted",
                  "predicted_from_tosses", "predicted_from_seconds", "residual_rms", "L_decay",
                  "drag_rate", "drag_rate_sigma", "saturated", "stable", "poor_fit", "flag"},
                 {}};
  // Pooled: each toss's recording named, its times its own.
  const bool pooled = !fit.parts.empty();
  if (pooled) table.columns.insert(table.columns.begin() + 1, "recording");
  for (std::size_t k = 0; k < fit.tosses.size(); ++k) {
    const TossFit& t = fit.tosses[k];
    const auto [t_start, recording] = own_time(fit, t.flight.t_start);
    const double t_end = t.flight.t_end - (t.flight.t_start - t_start);
    table.rows.push_back(
        {std::to_string(k + 1), shortest_cell(t_start), shortest_cell(t_end),
         shortest_cell(t.omega0[0]), shortest_cell(t.omega0[1]), shortest_cell(t.omega0[2]),
         shortest_cell(t.half_period_measured), shortest_cell(t.half_period_fitted),
         shortest_cell(t.half_period_predicted),
         t.predicted_from_tosses ? std::to_string(*t.predicted_from_tosses) : std::string(),
         shortest_cell(t.predicted_from_seconds), shortest_cell(t.residual_rms),
         shortest_cell(t.L_decay), shortest_cell(t.drag_rate), shortest_cell(t.drag_rate_sigma),
         std::to_string(t.saturated), std::string(t.stable ? "yes" : "no"),
         std::string(t.poor_fit ? "yes" : "no"), t.flag});
    if (pooled) table.rows.back().insert(table.rows.back().begin() + 1, recording);
  }
  return table;
}

CsvTable fit_body_csv(const FitResult& fit) {
  const BodyEstimate& b = fit.body;
  CsvTable table{
      {"I1_over_I3",      "I2_over_I3",      "I3_over_I3", "I1_sigma",     "I2_sigma",
       "axis1_x",         "axis1_y",         "axis1_z",    "axis2_x",      "axis2_y",
       "axis2_z",         "axis3_x",         "axis3_y",    "axis3_z",      "axis1_sigma_deg",
       "axis2_sigma_deg", "axis3_sigma_deg", "moments",    "tosses",       "drag",
       "bias_x",          "bias_y",          "bias_z",     "bias_sigma_x", "bias_sigma_y",
       "bias_sigma_z"},
      {}};
  std::vector<CsvCell> row{shortest_cell(b.ratios[0]), shortest_cell(b.ratios[1]),
                           shortest_cell(b.ratios[2])};
  for (int i = 0; i < 2; ++i)
    row.push_back(
        shortest_cell(b.ratio_sigma ? std::optional<double>((*b.ratio_sigma)[i]) : std::nullopt));
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c) row.push_back(shortest_cell(b.axes(c, a)));
  for (int a = 0; a < 3; ++a)
    row.push_back(shortest_cell(b.axis_sigma_deg ? std::optional<double>((*b.axis_sigma_deg)[a])
                                                 : std::nullopt));
  row.push_back(std::string(b.moments_fixed        ? "given"
                            : b.moments_determined ? "fitted"
                                                   : "poorly determined"));
  row.push_back(std::to_string(fit.tosses.size()));
  row.push_back(std::string(physics::to_string(fit.drag)));
  // The bias removed: the rest's mean and its scatter, or fitted from the flights and its
  // standard error; no σ where neither (docs/outputs.md, "bookspin fit"). Pooled: a row per
  // recording, the body's columns repeated, with its recording's bias and a `recording` column
  // first.
  const auto bias_cells = [](std::vector<CsvCell> cells, const Eigen::Vector3d& bias,
                             const std::optional<Eigen::Vector3d>& sigma) {
    for (int c = 0; c < 3; ++c) cells.push_back(shortest_cell(bias[c]));
    for (int c = 0; c < 3; ++c)
      cells.push_back(shortest_cell(sigma ? std::optional<double>((*sigma)[c]) : std::nullopt));
    return cells;
  };
  if (fit.parts.empty()) {
    table.rows.push_back(bias_cells(row, fit.search.bias,
                                    fit.search.rest_samples > 0
                                        ? std::optional<Eigen::Vector3d>(fit.search.bias_sigma)
                                        : fit.bias_fitted_sigma));
    return table;
  }
  table.columns.insert(table.columns.begin(), "recording");
  for (const RecordingPart& part : fit.parts) {
    std::vector<CsvCell> cells =
        bias_cells(row, part.bias + part.bias_correction,
                   part.rest_samples > 0 ? std::optional<Eigen::Vector3d>(part.bias_sigma)
                                         : part.bias_fitted_sigma);
    cells.insert(cells.begin(), part.name);
    table.rows.push_back(std::move(cells));
  }
  return table;
}

std::vector<std::string> fit_summary(const FitResult& fit) {
  std::vector<std::string> lines;
  const auto with_sigma = [](const Eigen::Vector3d& v, const Eigen::Vector3d& sigma) {
    return fixed(v[0], 4) + " ± " + fixed(sigma[0], 4) + ", " + fixed(v[1], 4) + " ± " +
           fixed(sigma[1], 4) + ", " + fixed(v[2], 4) + " ± " + fixed(sigma[2], 4);
  };
  const auto three = [](const Eigen::Vector3d& v) {
    return fixed(v[0], 4) + ", " + fixed(v[1], 4) + ", " + fixed(v[2], 4);
  };
  // Pooled: each recording's own bias, measured on its own rest and corrected by its own
  // flights.
  for (const RecordingPart& part : fit.parts) {
    const bool corrected = part.bias_correction != Eigen::Vector3d::Zero();
    if (part.rest_samples > 0) {
      lines.push_back(
          "bias of " + part.name + " (rad/s, the mean of " + std::to_string(part.rest_samples) +
          " samples at rest ± their scatter): " + with_sigma(part.bias, part.bias_sigma));
      if (corrected)
        lines.push_back("bias of " + part.name +
                        " in flight (rad/s): " + three(part.bias + part.bias_correction) +
                        ", the rest's corrected by its flights by " + three(part.bias_correction) +
                        " (within 3 σ of its rest's scatter)");
    } else if (part.bias_fitted_sigma) {
      lines.push_back("no rest in " + part.name +
                      ": its bias (rad/s) is fitted from its flights: " +
                      with_sigma(part.bias_correction, *part.bias_fitted_sigma));
    } else if (corrected) {
      lines.push_back(
          "no rest in " + part.name +
          ": its bias (rad/s) is fitted from its flights: " + three(part.bias_correction));
    } else {
      lines.push_back("no rest in " + part.name + ": its bias is not removed");
    }
  }
  if (fit.parts.empty()) {
    const Eigen::Vector3d& bias = fit.search.bias;  // removed in flight: the rest's + correction
    const Eigen::Vector3d rest = bias - fit.bias_correction;
    const bool corrected = fit.bias_correction != Eigen::Vector3d::Zero();
    if (fit.search.rest_samples > 0) {
      lines.push_back(
          "bias (rad/s, the mean of " + std::to_string(fit.search.rest_samples) +
          " samples at rest ± their scatter): " + with_sigma(rest, fit.search.bias_sigma));
      if (corrected)
        lines.push_back("bias in flight (rad/s): " + three(bias) +
                        ", the rest's corrected by the flights by " + three(fit.bias_correction) +
                        " (within 3 σ of the rest's scatter)");
    } else if (fit.bias_fitted_sigma) {
      lines.push_back("no rest in the recording: the bias (rad/s) is fitted from the flights: " +
                      with_sigma(bias, *fit.bias_fitted_sigma));
    } else if (corrected) {
      lines.push_back("no rest in the recording: the bias (rad/s) is fitted from the flights: " +
                      three(bias));
    } else {
      lines.push_back("no rest in the recording: the gyroscope's bias is not removed");
    }
  }
  for (std::size_t k = 0; k < fit.tosses.size(); ++k) {
    const TossFit& t = fit.tosses[k];
    std::string drag;
    if (fit.drag != physics::DragLaw::none)
      drag = ", drag " + fixed(t.drag_rate, 3) +
             (t.drag_rate_sigma ? " ± " + fixed(*t.drag_rate_sigma, 3) : std::string()) + " /s";
    const auto [t_start, recording] = own_time(fit, t.flight.t_start);
    const double t_end = t.flight.t_end - (t.flight.t_start - t_start);
    lines.push_back("kept toss " + std::to_string(k + 1) + ": " +
                    (recording.empty() ? "" : recording + " ") + fixed(t_start, 3) + "–" +
                    fixed(t_end, 3) + " s" + drag + (t.stable ? " (stable: no flip)" : "") +
                    (t.poor_fit ? " (flagged)" : ""));
  }
  for (const DroppedStretch& d : fit.search.dropped) {
    const auto [t_start, recording] = own_time(fit, d.t_start);
    const double t_end = d.t_end - (d.t_start - t_start);
    lines.push_back("dropped " + (recording.empty() ? "" : recording + " ") + fixed(t_start, 3) +
                    "–" + fixed(t_end, 3) + " s: " + d.reason);
  }
  const BodyEstimate& b = fit.body;
  std::string sigma;
  if (b.ratio_sigma && !b.moments_fixed)
    sigma = " (± " + fixed((*b.ratio_sigma)[0], 4) + ", ± " + fixed((*b.ratio_sigma)[1], 4) + ")";
  lines.push_back("moments I1 : I2 : I3 = " + fixed(b.ratios[0], 4) + " : " +
                  fixed(b.ratios[1], 4) + " : 1" + (b.moments_fixed ? " (given)" : sigma) +
                  (fit.drag == physics::DragLaw::none
                       ? ", no drag"
                       : ", " + std::string(physics::to_string(fit.drag)) + " drag"));
  for (const std::string& note : b.notes) lines.push_back("note: " + note);
  return lines;
}

}  // namespace bookspin::fit
