// The class's live fit (docs/phone-lab.md, "The live fit"): each recording prepared once, the
// set fitted warm from the last live fit. Held to the exact fit (fit_report, `bookspin fit`'s)
// on the real recordings of one phone.
#include "fit/live_fit.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "fit/pool.hpp"
#include "fit/report.hpp"
#include "real_recordings.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

/// The real session's recordings as read, in their folders' order.
std::vector<GyroRecording> real_recordings() {
  std::vector<std::filesystem::path> folders;
  for (const auto& entry : std::filesystem::directory_iterator(real_dir()))
    if (entry.is_directory()) folders.push_back(entry.path());
  std::sort(folders.begin(), folders.end());
  std::vector<GyroRecording> recordings;
  for (const auto& folder : folders) recordings.push_back(read_recording(folder));
  return recordings;
}

std::vector<const PreparedRecording*> pointers(const std::vector<PreparedRecording>& prepared,
                                               std::size_t n) {
  std::vector<const PreparedRecording*> out;
  for (std::size_t k = 0; k < n; ++k) out.push_back(&prepared[k]);
  return out;
}

TEST(LiveFit, StartedFromItsOwnResultItStaysThere) {
  REQUIRE_REAL_RECORDINGS();
  std::vector<PreparedRecording> prepared;
  for (const GyroRecording& r : real_recordings()) prepared.push_back(prepare_recording(r));
  const std::vector<const PreparedRecording*> all = pointers(prepared, prepared.size());
  const LiveFit cold = live_fit(all, nullptr);
  const LiveFit warm = live_fit(all, &cold);
  // The same minimum: the warm solve starts at it and stops there (to the solver's tolerance).
  ASSERT_EQ(warm.tosses.size(), cold.tosses.size());
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(warm.ratios[i], cold.ratios[i], 1e-7) << i;
  EXPECT_LT((warm.axes - cold.axes).cwiseAbs().maxCoeff(), 1e-6);
  for (std::size_t k = 0; k < warm.tosses.size(); ++k) {
    EXPECT_LT((warm.tosses[k].omega0 - cold.tosses[k].omega0).norm(), 1e-6) << k;
    EXPECT_EQ(warm.tosses[k].recording, cold.tosses[k].recording);
    EXPECT_EQ(warm.tosses[k].toss, static_cast<int>(k) + 1);
  }
  // Its σ is the covariance's: present, positive, and no wider than the exact fit's (which the
  // folds widen).
  ASSERT_TRUE(warm.ratio_sigma.has_value());
  EXPECT_GT((*warm.ratio_sigma)[0], 0.0);
}

TEST(LiveFit, OneMoreRecordingFromTheLastBodyAgreesWithTheExactFitWithinItsSigma) {
  REQUIRE_REAL_RECORDINGS();
  const std::vector<GyroRecording> recordings = real_recordings();
  std::vector<PreparedRecording> prepared;
  for (const GyroRecording& r : recordings) prepared.push_back(prepare_recording(r));
  const std::size_t n = prepared.size();
  ASSERT_GE(n, 3u);
  const LiveFit before = live_fit(pointers(prepared, n - 1), nullptr);
  const LiveFit live = live_fit(pointers(prepared, n), &before);
  const FitReport exact = fit_report(pool_recordings(recordings), {});
  const BodyEstimate& body = exact.result.body;
  ASSERT_TRUE(body.ratio_sigma.has_value());
  for (int i = 0; i < 2; ++i)
    EXPECT_NEAR(live.ratios[i], body.ratios[i], (*body.ratio_sigma)[i])
        << "ratio " << i << ": live " << live.ratios[i] << ", exact " << body.ratios[i];
  // Each axis within a few degrees of the exact fit's (the same sign convention).
  for (int a = 0; a < 3; ++a)
    EXPECT_GT(live.axes.col(a).dot(body.axes.col(a)), std::cos(5.0 * 3.14159265 / 180.0)) << a;
  // The recordings in their canonical order, each flight numbered within its recording, its
  // times its own; as many flights as the exact fit's (whose ends it trims).
  EXPECT_EQ(live.recordings, static_cast<int>(n));
  EXPECT_EQ(live.tosses.size(), exact.result.tosses.size());
  for (std::size_t k = 1; k < live.tosses.size(); ++k) {
    const LiveToss &a = live.tosses[k - 1], &b = live.tosses[k];
    EXPECT_LE(a.recording, b.recording);
    EXPECT_EQ(b.flight, a.recording == b.recording ? a.flight + 1 : 1);
  }
  // Each flight the exact fit's, its start within 0.15 s (the exact fit trims its ends).
  for (std::size_t k = 0; k < live.tosses.size(); ++k) {
    const LiveToss& t = live.tosses[k];
    EXPECT_GT(t.t_end, t.t_start);
    EXPECT_GT(t.residual_rms, 0.0);
    const Flight& f = exact.result.tosses[k].flight;
    const double offset = part_at(exact.result.parts, f.t_start).t_offset;
    EXPECT_NEAR(t.t_start, f.t_start - offset, 0.15) << k;
  }
}

TEST(LiveFit, RefusesWhatTheExactFitRefuses) {
  // None, one given twice, and no flight in any of them: InputError, one line naming it.
  EXPECT_THROW(live_fit({}, nullptr), InputError);
  test::SyntheticRecording still = test::make_recording(test::phone_alone(), {}, 7, 0.01);
  GyroRecording r = test::as_recording(still);
  r.name = "still";
  r.source = "still.csv";
  const PreparedRecording prepared = prepare_recording(r);
  EXPECT_TRUE(prepared.search.flights.empty());
  try {
    live_fit({&prepared}, nullptr);
    FAIL() << "no flight, no refusal";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "still.csv: no free flight found");
  }
  try {
    live_fit({&prepared, &prepared}, nullptr);
    FAIL() << "given twice, no refusal";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "still.csv: given twice");
  }
}

}  // namespace
}  // namespace bookspin::fit
