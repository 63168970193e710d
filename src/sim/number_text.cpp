#include "k40t_driver/sim/number_text.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace k40t::sim {

Result<double> parse_number_in(const std::string& text, const std::string& what, double lo,
                               double hi) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end == text.c_str() || *end != '\0' || !std::isfinite(v)) {
    return Status::fail(what + " must be a number, got '" + text + "'");
  }
  if (v < lo || v > hi) {
    std::ostringstream out;
    out << what << " must be " << lo << ".." << hi << ", got " << text;
    return Status::fail(out.str());
  }
  return v;
}

}  // namespace k40t::sim
