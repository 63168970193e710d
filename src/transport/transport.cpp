#include "k40t_driver/transport/transport.h"

#include <algorithm>
#include <vector>

#include "k40t_driver/codec/enum_names.h"
#include "k40t_driver/transport/device_url.h"
#include "k40t_driver/transport/fd_transport.h"
#include "links.h"

namespace k40t::transport {
namespace {

struct SchemeEntry {
  const char* name;
  UrlRules rules;
  LinkResult (*make_link)(const DeviceUrl& url);
};

// Adding a scheme = adding a row (and its factory in links.h).
const std::vector<SchemeEntry>& scheme_table() {
  static const std::vector<SchemeEntry> kTable = {
      {"serial", {UrlForm::kPath, {"baud"}}, make_serial_link},
      {"pty", {UrlForm::kPath, {}}, make_pty_link},
      {"udp", {UrlForm::kHostPort, {"bind"}}, make_udp_client_link},
      {"udp-server", {UrlForm::kHostPort, {}}, make_udp_server_link},
      {"tcp", {UrlForm::kHostPort, {}}, make_tcp_client_link},
      {"tcp-server", {UrlForm::kHostPort, {}}, make_tcp_server_link},
  };
  return kTable;
}

}  // namespace

const char* to_string(LinkState state) {
  static constexpr EnumName<LinkState> kNames[] = {{LinkState::kClosed, "closed"},
                                                   {LinkState::kConnecting, "connecting"},
                                                   {LinkState::kConnected, "connected"},
                                                   {LinkState::kReconnecting, "reconnecting"}};
  return name_in(kNames, state, "invalid link state");
}

std::vector<std::string> known_schemes() {
  std::vector<std::string> names;
  for (const SchemeEntry& entry : scheme_table()) names.emplace_back(entry.name);
  return names;
}

Result<std::unique_ptr<Transport>> make_transport(const std::string& url) {
  using R = Result<std::unique_ptr<Transport>>;
  auto scheme = parse_url_scheme(url);
  if (!scheme) return R::fail(scheme.error());
  const auto& table = scheme_table();
  const auto entry = std::find_if(table.begin(), table.end(),
                                  [&](const SchemeEntry& e) { return *scheme == e.name; });
  if (entry == table.end()) {
    std::string known;
    for (const auto& name : known_schemes()) known += (known.empty() ? "" : ", ") + name;
    return R::fail(url_error(url, "unknown scheme '" + *scheme + "' (known: " + known + ")"));
  }
  auto parsed = parse_device_url(url, entry->rules);
  if (!parsed) return R::fail(parsed.error());
  auto link = entry->make_link(*parsed);
  if (!link) return R::fail(link.error());
  return R(std::make_unique<FdTransport>(url, std::move(link).value()));
}

}  // namespace k40t::transport
