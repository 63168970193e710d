// k40t list: the message catalogue.
#include <cstdio>
#include <string>

#include "command.h"
#include "frame_text.h"
#include "k40t_driver/protocol/catalogue.h"

namespace k40t::tool {

namespace {

// "name:kind=default" entries of a message's fields, for `list --fields`.
class FieldListSink : public protocol::FieldSink {
 public:
  void integer(const char* name, int64_t v) override { add(name, "integer", std::to_string(v)); }
  void unsigned_integer(const char* name, uint64_t v) override {
    add(name, "integer", std::to_string(v));
  }
  void real(const char* name, double v) override {
    char buffer[32];
    std::snprintf(buffer, sizeof(buffer), "%g", v);
    add(name, "real", buffer);
  }
  void boolean(const char* name, bool v) override { add(name, "bool", v ? "1" : "0"); }
  void text(const char* name, const std::string& v) override { add(name, "text", "\"" + v + "\""); }
  void enumeration(const char* name, int64_t code, const char*) override {
    add(name, "enum", std::to_string(code));
  }
  void bytes(const char* name, const uint8_t*, size_t size) override {
    add(name, std::to_string(size) + " bytes",
        "0" + std::string(size > 1 ? ",0" : "") + (size > 2 ? ",..." : ""));
  }
  const std::string& text() const { return text_; }

 private:
  void add(const char* name, const std::string& kind, const std::string& value) {
    text_ += "      " + std::string(name) + " (" + kind + ", default " + value + ")\n";
  }
  std::string text_;
};

int run_list(const Command& self, const ParsedArgs& args) {
  if (!args.positional.empty())
    return usage_error(self, "unexpected argument '" + args.positional[0] + "'");
  const bool with_fields = args.has("--fields");
  std::printf("%-10s %-36s %-10s %-8s %s\n", "id", "name", "section", "kind", "direction");
  for (const protocol::MessageInfo& m : protocol::catalogue()) {
    std::printf("%-10s %-36s %-10s %-8s %s\n", id_text(m.id).c_str(), m.name, m.section,
                kind_name(m.id), protocol::to_string(m.direction));
    if (with_fields && m.default_fields != nullptr) {
      FieldListSink sink;
      m.default_fields(sink);
      std::fputs(sink.text().c_str(), stdout);
    }
  }
  return kExitOk;
}

}  // namespace

const Command& list_command() {
  static const Command command{
      "list",
      "list [--fields]",
      "the message catalogue: id, name, section, kind, direction",
      "Prints every message the protocol layer knows, sorted by id. The names are what\n"
      "`k40t send` takes; with --fields, each message's fields (the name=value arguments\n"
      "of `k40t send`, units in the names) follow it with their defaults.",
      {{"--fields", nullptr, "list each message's fields too"}},
      &run_list};
  return command;
}

}  // namespace k40t::tool
