#pragma once
// Render progress on stderr: a redrawn bar on a terminal, plain periodic lines otherwise.
#include <chrono>
#include <string>

namespace bookspin::cli {

class Progress {
 public:
  Progress(std::string label, int total_frames);
  /// Reports that `done` frames are complete (rate-limited output).
  void update(int done);
  /// Final line.
  void finish(int done);

 private:
  void print(int done, bool final);

  std::string label_;
  int total_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_, last_print_;
};

}  // namespace bookspin::cli
