#include "k40t_driver/transport/device_url.h"

#include <algorithm>
#include <cctype>

namespace k40t::transport {
namespace {

constexpr char kSeparator[] = "://";

bool is_scheme_char(char c) {
  return std::islower(static_cast<unsigned char>(c)) ||
         std::isdigit(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.';
}

bool has_space_or_control(const std::string& text) {
  return std::any_of(text.begin(), text.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return std::isspace(u) || std::iscntrl(u);
  });
}

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

Result<uint16_t> parse_port(const std::string& text) {
  if (text.empty()) return Result<uint16_t>::fail("missing port number after ':'");
  if (text.size() > 6 || !std::all_of(text.begin(), text.end(), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c));
      })) {
    return Result<uint16_t>::fail("port '" + text + "' is not a number in 1..65535");
  }
  const long value = std::stol(text);
  if (value < 1 || value > 65535) {
    return Result<uint16_t>::fail("port " + text + " is out of range 1..65535");
  }
  return static_cast<uint16_t>(value);
}

// Splits "k=v&k2=v2" into `out`, rejecting empty or duplicate keys and missing values.
Status parse_query(const std::string& query, std::map<std::string, std::string>* out) {
  if (query.empty()) return Status::fail("empty query after '?'");
  size_t start = 0;
  while (start <= query.size()) {
    const size_t end = std::min(query.find('&', start), query.size());
    const std::string item = query.substr(start, end - start);
    const size_t eq = item.find('=');
    if (item.empty()) return Status::fail("empty query parameter (stray '&')");
    if (eq == std::string::npos) return Status::fail("query parameter '" + item + "' has no '='");
    const std::string key = item.substr(0, eq);
    const std::string value = item.substr(eq + 1);
    if (key.empty()) return Status::fail("query parameter '" + item + "' has no name");
    if (value.empty()) return Status::fail("query parameter '" + key + "' has no value");
    if (!out->emplace(key, value).second) {
      return Status::fail("query parameter '" + key + "' is given twice");
    }
    start = end + 1;
  }
  return Status::ok();
}

Status check_query_keys(const DeviceUrl& url, const std::vector<std::string>& allowed) {
  for (const auto& [key, value] : url.query) {
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    return Status::fail("unknown query parameter '" + key + "' for " + url.scheme + "://" +
                        (allowed.empty() ? " (it takes none)" : " (known: " + join(allowed) + ")"));
  }
  return Status::ok();
}

// `authority` is what sits between "://" and the first '/'; `path` is the rest before '?'.
Status split_address(const std::string& authority, const std::string& path, UrlForm form,
                     DeviceUrl* url) {
  const std::string& scheme = url->scheme;
  if (form == UrlForm::kPath) {
    if (!authority.empty()) {
      return Status::fail("unexpected host '" + authority + "' (expected " + scheme +
                          ":///absolute/path, with three slashes)");
    }
    if (path.empty() || path == "/") {
      return Status::fail("empty path (expected " + scheme + ":///absolute/path)");
    }
    url->path = path;
    return Status::ok();
  }
  if (!path.empty() && path != "/") {
    return Status::fail("unexpected path '" + path + "' (expected " + scheme + "://host:port)");
  }
  if (authority.empty()) return Status::fail("missing host (expected " + scheme + "://host:port)");
  auto host_port = parse_host_port(authority);
  if (!host_port) return Status::fail(host_port.error() + " (expected " + scheme + "://host:port)");
  url->host = host_port->host;
  url->port = host_port->port;
  return Status::ok();
}

}  // namespace

std::string url_error(const std::string& url, const std::string& what) {
  return "bad device URL \"" + url + "\": " + what;
}

std::optional<std::string> DeviceUrl::query_value(const std::string& key) const {
  const auto it = query.find(key);
  if (it == query.end()) return std::nullopt;
  return it->second;
}

Result<std::string> parse_url_scheme(const std::string& url) {
  using R = Result<std::string>;
  if (url.empty()) return R::fail(url_error(url, "empty URL (expected scheme://...)"));
  const size_t sep = url.find(kSeparator);
  if (sep == std::string::npos) {
    return R::fail(url_error(url, "no scheme (expected scheme://..., e.g. serial:///dev/ttyUSB0)"));
  }
  const std::string scheme = url.substr(0, sep);
  if (scheme.empty()) return R::fail(url_error(url, "empty scheme before \"://\""));
  if (!std::islower(static_cast<unsigned char>(scheme[0])) ||
      !std::all_of(scheme.begin(), scheme.end(), is_scheme_char)) {
    return R::fail(url_error(url, "scheme '" + scheme +
                                      "' must be lower-case letters, digits, '+', '-' or '.', "
                                      "starting with a letter"));
  }
  return scheme;
}

Result<HostPort> parse_host_port(const std::string& text) {
  using R = Result<HostPort>;
  HostPort out;
  std::string port_text;
  if (!text.empty() && text[0] == '[') {  // [IPv6]:port
    const size_t close = text.find(']');
    if (close == std::string::npos) return R::fail("unterminated '[' in '" + text + "'");
    out.host = text.substr(1, close - 1);
    if (close + 1 >= text.size() || text[close + 1] != ':') {
      return R::fail("missing port in '" + text + "'");
    }
    port_text = text.substr(close + 2);
  } else {
    const size_t colon = text.rfind(':');
    if (colon == std::string::npos) return R::fail("missing port in '" + text + "'");
    out.host = text.substr(0, colon);
    if (out.host.find(':') != std::string::npos) {
      return R::fail("IPv6 address in '" + text + "' needs brackets, e.g. [::1]:port");
    }
    port_text = text.substr(colon + 1);
  }
  if (out.host.empty()) return R::fail("missing host in '" + text + "'");
  auto port = parse_port(port_text);
  if (!port) return R::fail(port.error());
  out.port = *port;
  return out;
}

Result<DeviceUrl> parse_device_url(const std::string& text, const UrlRules& rules) {
  using R = Result<DeviceUrl>;
  auto scheme = parse_url_scheme(text);
  if (!scheme) return R::fail(scheme.error());
  if (has_space_or_control(text)) {
    return R::fail(url_error(text, "contains white space or control characters"));
  }
  DeviceUrl url;
  url.text = text;
  url.scheme = *scheme;

  std::string rest = text.substr(url.scheme.size() + sizeof(kSeparator) - 1);
  const size_t question = rest.find('?');
  if (question != std::string::npos) {
    if (Status s = parse_query(rest.substr(question + 1), &url.query); !s) {
      return R::fail(url_error(text, s.message()));
    }
    rest.resize(question);
  }
  const size_t slash = rest.find('/');
  const std::string authority = rest.substr(0, slash);
  const std::string path = slash == std::string::npos ? std::string() : rest.substr(slash);
  if (Status s = split_address(authority, path, rules.form, &url); !s) {
    return R::fail(url_error(text, s.message()));
  }
  if (Status s = check_query_keys(url, rules.query_keys); !s) {
    return R::fail(url_error(text, s.message()));
  }
  return url;
}

std::string device_url_with_baud(const std::string& url, int baud) {
  if (url.rfind("serial://", 0) != 0 || url.find("baud=") != std::string::npos) return url;
  return url + (url.find('?') == std::string::npos ? "?" : "&") + "baud=" + std::to_string(baud);
}

}  // namespace k40t::transport
