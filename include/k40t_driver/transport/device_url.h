// Device URLs: `scheme://host:port[?key=value&...]` or `scheme:///absolute/path[?key=value&...]`.
//
// Parsing is split in two so that errors can be specific: parse_url_scheme() finds the scheme
// (the transport table then says what that scheme accepts), and parse_device_url() checks the rest
// against those rules. Every failure message quotes the URL and says what is wrong.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "k40t_driver/codec/result.h"

namespace k40t::transport {

// Where a scheme's URL points.
enum class UrlForm {
  kHostPort,  // scheme://host:port (no path)
  kPath,      // scheme:///absolute/path (no host)
};

// What one scheme accepts; the transport table holds one per scheme.
struct UrlRules {
  UrlForm form = UrlForm::kHostPort;
  std::vector<std::string> query_keys;  // every other key is an error
};

struct HostPort {
  std::string host;  // as written, without IPv6 brackets
  uint16_t port = 0;
};

struct DeviceUrl {
  std::string text;  // the URL as given, for messages
  std::string scheme;
  std::string host;  // empty for kPath URLs
  uint16_t port = 0;
  std::string path;  // empty for kHostPort URLs
  std::map<std::string, std::string> query;

  std::optional<std::string> query_value(const std::string& key) const;
};

// The scheme part (lower-case letters, digits, '+', '-', '.'; starting with a letter).
Result<std::string> parse_url_scheme(const std::string& url);

// Parses and checks the whole URL against `rules`.
Result<DeviceUrl> parse_device_url(const std::string& url, const UrlRules& rules);

// "host:port" or "[v6addr]:port" with port 1..65535. Error messages do not name a URL; callers
// prefix them with one (see url_error()).
Result<HostPort> parse_host_port(const std::string& text);

// `bad device URL "<url>": <what>` — the common shape of every URL error.
std::string url_error(const std::string& url, const std::string& what);

// The URL with a baud rate parameter applied (the drivers' ~device and ~baud): serial URLs without
// "baud=" get "?baud=N" (or "&baud=N"); other URLs are returned unchanged.
std::string device_url_with_baud(const std::string& url, int baud);

}  // namespace k40t::transport
