// What k40t probe found: one row per reading (the driver parameter's name, the value, the
// evidence), printed as a table and written as the parameter file k40t.launch's `conventions:=`
// loads. A reading the run could not settle keeps its default and is written as a comment, so
// the user sees it and the driver keeps its own default (or its `auto`).
#pragma once

#include <string>
#include <vector>

#include "k40t_driver/protocol/result.h"

namespace k40t::tool {

struct Finding {
  std::string name;      // the driver parameter (docs/protocol/decisions.md's table)
  std::string value;     // learned, or the default when not learned
  std::string evidence;  // which frames showed it, or why it is not known
  bool learned = false;
};

class ProbeReport {
 public:
  void learned(const std::string& name, const std::string& value, const std::string& evidence);
  // Not settled by this run: `why` says what would settle it ("run with --allow-motion") or
  // that no traffic can ("not learnable from traffic: default kept").
  void kept(const std::string& name, const std::string& default_value, const std::string& why);
  // A row for a reading already in the report is replaced (a later, stronger test wins).
  const std::vector<Finding>& findings() const { return findings_; }
  const Finding* find(const std::string& name) const;

  // "reading  value  evidence" with aligned columns.
  std::string table() const;
  // `name: value  # evidence` per learned reading, `# name: default  # why` for the others.
  std::string yaml(const std::string& header) const;
  Status write_yaml(const std::string& path, const std::string& header) const;

 private:
  void put(Finding finding);
  std::vector<Finding> findings_;
};

}  // namespace k40t::tool
