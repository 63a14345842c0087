#include "fit/fit_tables.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "common/number_text.hpp"
#include "fit/pool.hpp"

namespace bookspin::fit {

std::string fixed(double value, int digits) {
  std::ostringstream text;
  text.precision(digits);
  text << std::fixed << value;
  return text.str();
}

namespace {

/// Two or more recordings fitted as one: each toss and bias is named by its recording (the
/// `recording` column, "of NAME"); one recording's are its own.
bool named(const FitResult& fit) { return fit.parts.size() >= 2; }

/// Pooled time `t` (s) in its own recording's time, and that recording's name where named().
std::pair<double, std::string> own_time(const FitResult& fit, double t) {
  const RecordingPart& part = part_at(fit.parts, t);
  return {t - part.t_offset, named(fit) ? part.name : std::string()};
}

/// ", T/2 predicted 0.412 ± 0.060 s (2σ) from its first 0.2 s": ± 2σ, as the result table
/// gives it (to its precision, or the millisecond without a σ), ", not predicted: " and why, or
/// nothing.
std::string predicted_words(const TossFit& t) {
  if (!t.half_period_predicted)
    return t.not_predicted.empty() ? "" : ", not predicted: " + t.not_predicted;
  return ", T/2 predicted " +
         (t.half_period_predicted_sigma
              ? plus_minus(*t.half_period_predicted, 2.0 * *t.half_period_predicted_sigma) +
                    " s (2σ)"
              : fixed(*t.half_period_predicted, 3) + " s") +
         (t.predicted_window
              ? " from its first " + finite_text(*t.predicted_window, "predicted_window") + " s"
              : "") +
         (t.prediction_interval.empty() ? "" : " (" + t.prediction_interval + ")");
}

/// A cell of the result table, padded to `width` characters (UTF-8 counted by code points).
std::string padded(const std::string& text, std::size_t width) {
  std::size_t points = 0;
  for (unsigned char c : text) points += (c & 0xC0) != 0x80;
  return text + std::string(points < width ? width - points : 0, ' ');
}

}  // namespace

std::vector<std::string> fit_result_lines(const FitResult& fit) {
  struct Row {
    std::string toss, recording, times, measured, predicted, within;
  };
  std::vector<Row> rows{{"toss", "recording", "flight (s)", "T/2 measured (s)",
                         "T/2 predicted ± 2σ (s)", "within 2σ"}};
  for (std::size_t k = 0; k < fit.tosses.size(); ++k) {
    const TossFit& t = fit.tosses[k];
    const RecordingPart& part = part_at(fit.parts, t.flight.t_start);
    Row row;
    row.toss = std::to_string(k + 1);
    row.recording = part.name;
    row.times =
        fixed(t.flight.t_start - part.t_offset, 3) + "–" + fixed(t.flight.t_end - part.t_offset, 3);
    row.measured = t.half_period_measured ? fixed(*t.half_period_measured, 3) : "–";
    if (!t.half_period_predicted) {
      row.predicted = "not predicted";
      row.within = "–";
    } else if (!t.half_period_predicted_sigma) {
      row.predicted = fixed(*t.half_period_predicted, 3) + " (uncalibrated)";
      row.within = "–";
    } else {
      row.predicted = plus_minus(*t.half_period_predicted, 2.0 * *t.half_period_predicted_sigma);
      row.within = !t.half_period_measured ? "–"
                   : std::abs(*t.half_period_measured - *t.half_period_predicted) <=
                           2.0 * *t.half_period_predicted_sigma
                       ? "yes"
                       : "no";
    }
    rows.push_back(row);
  }
  std::array<std::size_t, 6> width{};
  const auto points = [](const std::string& text) {
    std::size_t n = 0;
    for (unsigned char c : text) n += (c & 0xC0) != 0x80;
    return n;
  };
  for (const Row& r : rows) {
    const std::array<const std::string*, 6> cells{&r.toss,     &r.recording, &r.times,
                                                  &r.measured, &r.predicted, &r.within};
    for (std::size_t c = 0; c < 6; ++c) width[c] = std::max(width[c], points(*cells[c]));
  }
  std::vector<std::string> lines;
  for (const Row& r : rows)
    lines.push_back("  " + padded(r.toss, width[0]) + "  " + padded(r.recording, width[1]) + "  " +
                    padded(r.times, width[2]) + "  " + padded(r.measured, width[3]) + "  " +
                    padded(r.predicted, width[4]) + "  " + r.within);
  return lines;
}

CsvTable fit_toss_csv(const FitResult& fit) {
  CsvTable table{{"toss",
                  "t_start",
                  "t_end",
                  "omega0_x",
                  "omega0_y",
                  "omega0_z",
                  "half_period_measured",
                  "half_period_fitted",
                  "half_period_predicted",
                  "half_period_predicted_sigma",
                  "half_period_propagated_sigma",
                  "prediction_interval",
                  "predicted_from_tosses",
                  "predicted_from_seconds",
                  "predicted_window",
                  "not_predicted",
                  "residual_rms",
                  "L_decay",
                  "drag_rate",
                  "drag_rate_sigma",
                  "saturated",
                  "stable",
                  "poor_fit",
                  "flag"},
                 {}};
  // Several recordings: each toss's recording named, its times its own.
  const bool pooled = named(fit);
  if (pooled) table.columns.insert(table.columns.begin() + 1, "recording");
  for (std::size_t k = 0; k < fit.tosses.size(); ++k) {
    const TossFit& t = fit.tosses[k];
    const auto [t_start, recording] = own_time(fit, t.flight.t_start);
    const double t_end = t.flight.t_end - (t.flight.t_start - t_start);
    table.rows.push_back(
        {std::to_string(k + 1),
         shortest_cell(t_start),
         shortest_cell(t_end),
         shortest_cell(t.omega0[0]),
         shortest_cell(t.omega0[1]),
         shortest_cell(t.omega0[2]),
         shortest_cell(t.half_period_measured),
         shortest_cell(t.half_period_fitted),
         shortest_cell(t.half_period_predicted),
         shortest_cell(t.half_period_predicted_sigma),
         shortest_cell(t.half_period_predicted ? t.half_period_propagated_sigma : std::nullopt),
         t.prediction_interval,
         t.predicted_from_tosses ? std::to_string(*t.predicted_from_tosses) : std::string(),
         shortest_cell(t.predicted_from_seconds),
         shortest_cell(t.predicted_window),
         t.not_predicted,
         shortest_cell(t.residual_rms),
         shortest_cell(t.L_decay),
         shortest_cell(t.drag_rate),
         shortest_cell(t.drag_rate_sigma),
         std::to_string(t.saturated),
         std::string(t.stable ? "yes" : "no"),
         std::string(t.poor_fit ? "yes" : "no"),
         t.flag});
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
  // The bias removed in flight: the rest's mean and its scatter, or fitted from the flights and
  // its standard error; no σ where neither (docs/outputs.md, "bookspin fit"). Several
  // recordings: a row per recording, the body's columns repeated, with its recording's bias and
  // a `recording` column first.
  if (named(fit)) table.columns.insert(table.columns.begin(), "recording");
  for (const RecordingPart& part : fit.parts) {
    std::vector<CsvCell> cells = row;
    const Eigen::Vector3d bias = part.bias_in_flight();
    const std::optional<Eigen::Vector3d> sigma =
        part.rest.samples > 0 ? std::optional<Eigen::Vector3d>(part.rest.sigma)
                              : part.bias_fitted_sigma;
    for (int c = 0; c < 3; ++c) cells.push_back(shortest_cell(bias[c]));
    for (int c = 0; c < 3; ++c)
      cells.push_back(shortest_cell(sigma ? std::optional<double>((*sigma)[c]) : std::nullopt));
    if (named(fit)) cells.insert(cells.begin(), part.name);
    table.rows.push_back(std::move(cells));
  }
  return table;
}

std::vector<std::string> fit_summary(const FitResult& fit, Reader reader) {
  // The result first: each toss's measured half period against its prediction (fit_result_lines).
  std::vector<std::string> lines{
      "result (T/2 measured against T/2 predicted from the other "
      "tosses, ± 2σ):"};
  for (std::string& line : fit_result_lines(fit)) lines.push_back(std::move(line));
  // Then a fit that describes no motion read, before anything else: a toss whose residual is a
  // large share of |ω| (times or ω in other units, not a free flight).
  for (std::size_t k = 0; k < fit.tosses.size(); ++k)
    if (fit.tosses[k].residual_share > kLargeResidualShare)
      lines.push_back("warning: toss " + std::to_string(k + 1) + "'s fit leaves " +
                      fixed(100.0 * fit.tosses[k].residual_share, 0) +
                      " % of |ω| unexplained (RMS): no free rigid body's motion as read, its "
                      "values not to be trusted (are the times in s and ω in rad/s?)");
  // Each value to its σ's precision (common/number_text.hpp, plus_minus).
  const auto with_sigma = [](const Eigen::Vector3d& v, const Eigen::Vector3d& sigma) {
    return plus_minus(v[0], sigma[0]) + ", " + plus_minus(v[1], sigma[1]) + ", " +
           plus_minus(v[2], sigma[2]);
  };
  const auto three = [](const Eigen::Vector3d& v) {
    return fixed(v[0], 4) + ", " + fixed(v[1], 4) + ", " + fixed(v[2], 4);
  };
  // The bias removed from each recording, on its own still rest, corrected by its own flights
  // (one recording: "the" rest and flights). `rest` is the still rest (its mean 0
  // without one; its stretches in the recording's own times), `correction` what the flights
  // added to it.
  const auto bias_lines = [&](const std::string& who, const Rest& rest,
                              const Eigen::Vector3d& correction,
                              const std::optional<Eigen::Vector3d>& fitted_sigma,
                              const std::optional<Eigen::Vector3d>& not_applied) {
    const bool one = who.empty();
    const std::string of = one ? "" : " of " + who;
    const std::string own = one ? "the" : "its";
    const Eigen::Vector3d in_flight = rest.mean + correction;
    if (rest.samples > 0) {
      std::string seconds;
      for (const auto& [a, b] : rest.stretches)
        seconds += (seconds.empty() ? "" : ", ") + fixed(a, 2) + "–" + fixed(b, 2);
      // One line a recording: the rest's, and the bias in flight where its flights corrected it.
      std::string line = "bias" + of + " (rad/s, the mean of " + std::to_string(rest.samples) +
                         " samples where the phone lay still, " + seconds +
                         " s, ± their scatter): " + with_sigma(rest.mean, rest.sigma);
      if (correction != Eigen::Vector3d::Zero())
        line += "; in flight " + three(in_flight) + ", the still rest's corrected by " + own +
                " flights by " + three(correction) + " (within 3 standard errors of " +
                (one ? "the rest's" : "its rest's") + " mean and " + fixed(kBiasDrift, 3) +
                " rad/s of drift and " + fixed(kHandTurn, 3) + " rad/s of a hand's slow turn)";
      lines.push_back(line);
      return;
    }
    const std::string fitted = "no still stretch in " +
                               (one ? "the recording: the" : who + ": its") +
                               " bias (rad/s) is fitted from " + own + " flights: ";
    if (not_applied && fitted_sigma)
      lines.push_back(
          "no still stretch in " + (one ? "the recording" : who) + ": the bias (rad/s) " + own +
          " flights give, " + with_sigma(*not_applied, *fitted_sigma) +
          " (1σ), is consistent with zero (χ² " +
          fixed(bias_chi_square(*not_applied, *fitted_sigma), 1) + " over 3 axes, " + "under " +
          fixed(kBiasChiSquare, 1) + "): not removed, held at zero within those σ");
    else if (fitted_sigma)
      lines.push_back(fitted + with_sigma(in_flight, *fitted_sigma) + " (1σ)");
    else if (correction != Eigen::Vector3d::Zero())
      lines.push_back(fitted + three(in_flight));
    else
      lines.push_back(one ? "no still stretch in the recording: the gyroscope's bias is not "
                            "removed"
                          : "no still stretch in " + who + ": its bias is not removed");
  };
  for (const RecordingPart& part : fit.parts)
    bias_lines(named(fit) ? part.name : std::string(), part.rest, part.bias_correction,
               part.bias_fitted_sigma, part.bias_not_applied);
  for (std::size_t k = 0; k < fit.tosses.size(); ++k) {
    const TossFit& t = fit.tosses[k];
    std::string drag;
    if (fit.drag != physics::DragLaw::none)
      drag = ", drag " +
             (t.drag_rate_sigma ? plus_minus(t.drag_rate, *t.drag_rate_sigma) + " /s (1σ)"
                                : fixed(t.drag_rate, 3) + " /s") +
             (t.drag_rate == 0.0 ? " (at its bound: air cannot speed a body up)" : "");
    const auto [t_start, recording] = own_time(fit, t.flight.t_start);
    const double t_end = t.flight.t_end - (t.flight.t_start - t_start);
    lines.push_back("kept toss " + std::to_string(k + 1) + ": " +
                    (recording.empty() ? "" : recording + " ") + fixed(t_start, 3) + "–" +
                    fixed(t_end, 3) + " s" + drag + predicted_words(t) +
                    (t.stable ? " (stable: no flip)" : "") + (t.poor_fit ? " (flagged)" : ""));
  }
  // The stretches dropped, one line per reason with their count (a hand-held recording drops
  // dozens, some a sample long); a reason given once keeps its stretch's times.
  const std::vector<std::string> dropped = fit_dropped_lines(fit);
  std::vector<std::pair<std::string, int>> reasons;  // in order of first appearance
  for (const DroppedStretch& d : fit.search.dropped) {
    auto at = std::find_if(reasons.begin(), reasons.end(),
                           [&](const auto& r) { return r.first == d.reason; });
    if (at == reasons.end())
      reasons.emplace_back(d.reason, 1);
    else
      ++at->second;
  }
  for (const auto& [reason, count] : reasons) {
    if (count > 1) {
      lines.push_back("dropped " + std::to_string(count) + " stretches of motion: " + reason);
      continue;
    }
    for (std::size_t k = 0; k < dropped.size(); ++k)
      if (fit.search.dropped[k].reason == reason) lines.push_back(dropped[k]);
  }
  const BodyEstimate& b = fit.body;
  const bool with_ratio_sigma = b.ratio_sigma && !b.moments_fixed;
  const auto ratio = [&](int i) {
    return with_ratio_sigma ? plus_minus(b.ratios[i], (*b.ratio_sigma)[i]) : fixed(b.ratios[i], 4);
  };
  lines.push_back("moments I1 : I2 : I3 = " + ratio(0) + " : " + ratio(1) + " : 1" +
                  (b.moments_fixed    ? " (given)"
                   : with_ratio_sigma ? " (1σ)"
                                      : "") +
                  (fit.drag == physics::DragLaw::none
                       ? ", no drag"
                       : ", " + std::string(physics::to_string(fit.drag)) + " drag"));
  for (std::string note : b.notes) {
    const std::size_t at = note.find(kGiveMoments);
    if (reader == Reader::page && at != std::string::npos)
      note.replace(at, std::string(kGiveMoments).size(), kMomentsRemedyPage);
    lines.push_back("note: " + note);
  }
  return lines;
}

std::vector<std::string> fit_dropped_lines(const FitResult& fit) {
  std::vector<std::string> lines;
  for (const DroppedStretch& d : fit.search.dropped) {
    const auto [t_start, recording] = own_time(fit, d.t_start);
    const double t_end = d.t_end - (d.t_start - t_start);
    lines.push_back("dropped " + (recording.empty() ? "" : recording + " ") + fixed(t_start, 3) +
                    "–" + fixed(t_end, 3) + " s: " + d.reason);
  }
  return lines;
}

}  // namespace bookspin::fit
