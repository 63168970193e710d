// The message tables of docs/protocol/*.md, read as data: the checked transcription of the pod
// protocol document's message list. Each table starts with a header row naming its columns ("id",
// "struct ..." with the struct and catalogue name, "section", "payload" or "bytes" with the size
// and, in parentheses, the fewest bytes accepted); rows whose first cell is a 0x id are messages.
// ACKs that are the bare response code are not listed (the catalogue generates them).
#pragma once

#include <string>
#include <vector>

#include "k40t_driver/protocol/message_id.h"

namespace k40t::testing {

struct DocsMessage {
  protocol::MessageId id = 0;
  std::string struct_name;  // `ThermalStatus`
  std::string name;         // thermal_status
  std::string section;      // 3.2.1.2 (a remark after the number, "(Chinese only)", dropped)
  size_t size = 0;
  size_t min_size = 0;  // = size when no "(n accepted)" is given
  std::string where;    // thermal_visible.md:15
};

// Every message row of every docs/protocol/*.md table; a row that does not parse is reported
// in `problems` (file:line and why).
struct DocsMessages {
  std::vector<DocsMessage> rows;
  std::vector<std::string> problems;
};
DocsMessages load_docs_messages();

// The ids of the rows that are requests of the document (0x00xxxx, not a periodic report), in
// table order.
std::vector<protocol::MessageId> docs_request_ids(const DocsMessages& docs);

}  // namespace k40t::testing
