#include "k40t_driver/psdk/app_key_file.h"

#include <cctype>
#include <fstream>

namespace k40t::psdk {

Result<std::string> read_app_key_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) return Status::fail("cannot read '" + path + "'");
  std::string line;
  std::getline(in, line);
  while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
  if (line.empty()) return Status::fail("'" + path + "' has no key on its first line");
  return line;
}

}  // namespace k40t::psdk
