#include "probe_report.h"

#include <algorithm>
#include <cstdio>
#include <fstream>

namespace k40t::tool {

void ProbeReport::learned(const std::string& name, const std::string& value,
                          const std::string& evidence) {
  put({name, value, evidence, true});
}

void ProbeReport::kept(const std::string& name, const std::string& default_value,
                       const std::string& why) {
  put({name, default_value, why, false});
}

void ProbeReport::put(Finding finding) {
  for (Finding& existing : findings_) {
    if (existing.name == finding.name) {
      existing = std::move(finding);
      return;
    }
  }
  findings_.push_back(std::move(finding));
}

const Finding* ProbeReport::find(const std::string& name) const {
  for (const Finding& f : findings_) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

std::string ProbeReport::table() const {
  size_t name_width = 7;  // "reading"
  size_t value_width = 5;
  for (const Finding& f : findings_) {
    name_width = std::max(name_width, f.name.size());
    value_width = std::max(value_width, f.value.size() + (f.learned ? 0 : 10));
  }
  auto row = [&](const std::string& a, const std::string& b, const std::string& c) {
    std::string line = a + std::string(name_width - a.size() + 2, ' ') + b +
                       std::string(value_width - std::min(value_width, b.size()) + 2, ' ') + c;
    return line + "\n";
  };
  std::string text = row("reading", "value", "evidence");
  for (const Finding& f : findings_) {
    text += row(f.name, f.learned ? f.value : f.value + " (default)", f.evidence);
  }
  return text;
}

std::string ProbeReport::yaml(const std::string& header) const {
  std::string text;
  if (!header.empty()) text += "# " + header + "\n";
  for (const Finding& f : findings_) {
    if (f.learned) {
      text += f.name + ": " + f.value + "  # " + f.evidence + "\n";
    } else {
      text += "# " + f.name + ": " + f.value + "  # " + f.evidence + "\n";
    }
  }
  return text;
}

Status ProbeReport::write_yaml(const std::string& path, const std::string& header) const {
  // Written beside the target and renamed over it: an interrupted run never leaves half a file.
  const std::string temporary = path + ".part";
  {
    std::ofstream out(temporary, std::ios::trunc);
    if (!out) return Status::fail("cannot write " + path + " (is its directory there?)");
    out << yaml(header);
    if (!out.flush()) return Status::fail("cannot write " + path);
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    return Status::fail("cannot write " + path);
  }
  return Status::ok();
}

}  // namespace k40t::tool
