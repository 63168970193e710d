#include "input.h"

#include <cctype>
#include <cerrno>
#include <cstring>

namespace k40t::tool {

namespace {
int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}
bool is_separator(char c) {
  return std::isspace(static_cast<unsigned char>(c)) || c == ',';
}
}  // namespace

Result<std::vector<uint8_t>> parse_hex(const std::string& text) {
  std::vector<uint8_t> bytes;
  int high = -1;  // first digit of a byte seen, waiting for the second
  size_t digits = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (is_separator(c)) continue;
    const bool token_start = i == 0 || is_separator(text[i - 1]);
    if (token_start && c == '0' && i + 1 < text.size() &&
        (text[i + 1] == 'x' || text[i + 1] == 'X')) {
      if (high >= 0) break;  // "F 0x.." : report the odd digit count below
      ++i;
      continue;
    }
    const int v = hex_value(c);
    if (v < 0) {
      const std::string shown = std::isprint(static_cast<unsigned char>(c))
                                    ? std::string(1, c)
                                    : "\\x" + std::to_string(static_cast<unsigned char>(c));
      return Result<std::vector<uint8_t>>::fail("invalid hex digit '" + shown + "' at character " +
                                                std::to_string(i + 1));
    }
    ++digits;
    if (high < 0) {
      high = v;
    } else {
      bytes.push_back(static_cast<uint8_t>(high << 4 | v));
      high = -1;
    }
  }
  if (high >= 0) {
    return Result<std::vector<uint8_t>>::fail("odd number of hex digits (" +
                                              std::to_string(digits) + "): each byte needs two");
  }
  return bytes;
}

Result<std::vector<uint8_t>> read_binary_file(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) {
    return Result<std::vector<uint8_t>>::fail("cannot open '" + path +
                                              "': " + std::strerror(errno));
  }
  std::vector<uint8_t> bytes;
  uint8_t buffer[4096];
  size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof(buffer), file)) > 0)
    bytes.insert(bytes.end(), buffer, buffer + n);
  const bool failed = std::ferror(file) != 0;
  std::fclose(file);
  if (failed) return Result<std::vector<uint8_t>>::fail("cannot read '" + path + "'");
  return bytes;
}

std::string read_all(std::FILE* stream) {
  std::string text;
  char buffer[4096];
  size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof(buffer), stream)) > 0) text.append(buffer, n);
  return text;
}

void feed_capture(session::Dispatcher& dispatcher, const std::vector<uint8_t>& bytes,
                  CaptureCursor& cursor) {
  for (uint8_t b : bytes) {
    ++cursor.fed;
    dispatcher.feed(&b, 1);
  }
}

std::string to_hex(const uint8_t* data, size_t size) {
  static const char kDigits[] = "0123456789ABCDEF";
  std::string out;
  out.reserve(size * 3);
  for (size_t i = 0; i < size; ++i) {
    if (i > 0) out += ' ';
    out += kDigits[data[i] >> 4];
    out += kDigits[data[i] & 0x0F];
  }
  return out;
}

}  // namespace k40t::tool
