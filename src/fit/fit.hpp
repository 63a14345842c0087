#pragma once
// The phone-toss lab's physics (docs/phone-lab.md): a gyroscope recording read
// (recording.hpp), its free flights found (flights.hpp), and the exact motion fitted to them
// (toss_fit.hpp), what it reports as text (fit_tables.hpp), each toss as a scene's values
// (toss_scene.hpp), and all of it as one value (report.hpp); a class's live fit, warm-started
// from the last (prepared_recording.hpp, live_fit.hpp). Eigen and Ceres; no GL, and no
// file written.
#include "fit/fit_options.hpp"
#include "fit/fit_tables.hpp"
#include "fit/flights.hpp"
#include "fit/live_fit.hpp"
#include "fit/pool.hpp"
#include "fit/prepared_recording.hpp"
#include "fit/recording.hpp"
#include "fit/report.hpp"
#include "fit/toss_fit.hpp"
#include "fit/toss_scene.hpp"
