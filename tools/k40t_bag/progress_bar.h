// A one-line progress bar on stderr, drawn only when stderr is a terminal (never in logs or
// pipes): "[=========>          ]  45% flight.bag". Redrawn when the shown percentage changes.
#pragma once

#include <string>

namespace k40t::tool {

class ProgressBar {
 public:
  explicit ProgressBar(std::string label);
  ~ProgressBar();  // clears the line
  void update(double fraction);

 private:
  std::string label_;
  bool enabled_;
  int shown_ = -1;
};

}  // namespace k40t::tool
