// Numbers typed by people (command line, control socket): the whole text must be a finite number
// within [lo, hi]; the error names `what` and the range.
#pragma once

#include <string>

#include "k40t_driver/protocol/result.h"

namespace k40t::sim {

Result<double> parse_number_in(const std::string& text, const std::string& what, double lo,
                               double hi);

}  // namespace k40t::sim
