#include "k40t_driver/sim/option_table.h"

#include <sstream>

namespace k40t::sim {

SplitArgument split_argument(const std::string& arg) {
  if (const size_t eq = arg.find('='); arg.rfind("--", 0) == 0 && eq != std::string::npos)
    return {arg.substr(0, eq), arg.substr(eq + 1)};
  return {arg, std::nullopt};
}

bool is_ros_argument(const std::string& arg) {
  return arg.rfind("__", 0) == 0 && arg.find(":=") != std::string::npos;
}

std::string format_option(const char* name, const char* argument, const char* help) {
  constexpr size_t kColumn = 30;
  constexpr size_t kWidth = 100;
  std::ostringstream out;
  std::string head = std::string("  ") + name + (argument ? std::string(" ") + argument : "");
  if (head.size() + 1 > kColumn) {
    out << head << "\n";
    head.clear();
  }
  head.resize(kColumn, ' ');
  std::istringstream words(help);
  std::string line = head;
  bool first = true;
  for (std::string word; words >> word;) {
    if (!first && line.size() + 1 + word.size() > kWidth) {
      out << line << "\n";
      line = std::string(kColumn, ' ');
      first = true;
    }
    line += (first ? "" : " ") + word;
    first = false;
  }
  out << line << "\n";
  return out.str();
}

}  // namespace k40t::sim
