#include "docs_message_tables.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>

namespace k40t::testing {

namespace {

std::string trim(const std::string& s) {
  const size_t first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells;
  size_t start = 1;  // after the leading '|'
  for (size_t bar = line.find('|', start); bar != std::string::npos; bar = line.find('|', start)) {
    cells.push_back(trim(line.substr(start, bar - start)));
    start = bar + 1;
  }
  return cells;
}

// The column whose header starts with one of `names`, or -1.
int column(const std::vector<std::string>& header, std::initializer_list<const char*> names) {
  for (size_t i = 0; i < header.size(); ++i) {
    for (const char* name : names) {
      if (header[i].rfind(name, 0) == 0) return static_cast<int>(i);
    }
  }
  return -1;
}

struct Columns {
  int id = -1;
  int names = -1;
  int section = -1;
  int size = -1;
  bool complete() const { return id == 0 && names >= 0 && section >= 0 && size >= 0; }
};

// "`ThermalStatus` / `thermal_status`" or "`CameraSystemStatus` (camera_system_status)".
bool parse_names(const std::string& cell, DocsMessage* m) {
  static const std::regex re(R"(^`(\w+)`\s*(?:/|\()\s*`?([a-z0-9_]+)`?\)?$)");
  std::smatch match;
  if (!std::regex_match(cell, match, re)) return false;
  m->struct_name = match[1];
  m->name = match[2];
  return true;
}

// "34", "34 (30 accepted)", "25 (2)", "23 (2, or 21+ accepted)": the first number in the
// parentheses is the fewest accepted.
bool parse_size(const std::string& cell, DocsMessage* m) {
  static const std::regex re(R"(^(\d+)(?:\s*\((\d+)[^)]*\))?$)");
  std::smatch match;
  if (!std::regex_match(cell, match, re)) return false;
  m->size = std::stoul(match[1]);
  m->min_size = match[2].matched ? std::stoul(match[2]) : m->size;
  return true;
}

bool parse_section(const std::string& cell, DocsMessage* m) {
  static const std::regex re(R"(^(\d+(?:\.\d+)+)(?:\s+\(.*\))?$)");
  std::smatch match;
  if (!std::regex_match(cell, match, re)) return false;
  m->section = match[1];
  return true;
}

void read_file(const std::filesystem::path& path, DocsMessages* out) {
  std::ifstream in(path);
  const std::string file = path.filename().string();
  std::string line;
  Columns columns;
  int number = 0;
  static const std::regex id_re(R"(^0x[0-9A-Fa-f]{6}$)");
  while (std::getline(in, line)) {
    ++number;
    if (line.rfind('|', 0) != 0) {
      columns = Columns{};  // a table ends at the first line that is not a row
      continue;
    }
    const std::vector<std::string> cells = cells_of(line);
    if (!cells.empty() && cells[0] == "id") {
      columns.id = column(cells, {"id"});
      columns.names = column(cells, {"struct"});
      columns.section = column(cells, {"section"});
      columns.size = column(cells, {"payload", "bytes"});
      continue;
    }
    if (!columns.complete() || cells.empty() || !std::regex_match(cells[0], id_re)) continue;
    DocsMessage m;
    m.where = file + ":" + std::to_string(number);
    m.id = static_cast<protocol::MessageId>(std::stoul(cells[0], nullptr, 16));
    const auto cell = [&](int i) { return i < static_cast<int>(cells.size()) ? cells[i] : ""; };
    if (!parse_names(cell(columns.names), &m)) {
      out->problems.push_back(m.where + ": struct/name cell '" + cell(columns.names) + "'");
    } else if (!parse_section(cell(columns.section), &m)) {
      out->problems.push_back(m.where + ": section cell '" + cell(columns.section) + "'");
    } else if (!parse_size(cell(columns.size), &m)) {
      out->problems.push_back(m.where + ": size cell '" + cell(columns.size) + "'");
    } else {
      out->rows.push_back(m);
    }
  }
}

}  // namespace

DocsMessages load_docs_messages() {
  DocsMessages out;
  const std::filesystem::path dir =
      std::filesystem::path(K40T_TEST_DATA_DIR) / ".." / ".." / "docs" / "protocol";
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() == ".md") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  for (const auto& path : files) read_file(path, &out);
  return out;
}

std::vector<protocol::MessageId> docs_request_ids(const DocsMessages& docs) {
  std::vector<protocol::MessageId> ids;
  for (const DocsMessage& m : docs.rows) {
    if (protocol::kind_of(m.id) == protocol::MessageKind::kRequestOrReport &&
        !protocol::is_periodic_report(m.id)) {
      ids.push_back(m.id);
    }
  }
  return ids;
}

}  // namespace k40t::testing
