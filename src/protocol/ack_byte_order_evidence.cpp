#include "k40t_driver/protocol/ack_byte_order_evidence.h"

#include <array>
#include <cstdio>

namespace k40t::protocol {

namespace {

bool known_response_code(uint16_t code) {
  return code <= 0x000A || (code >= 0x0201 && code <= 0x0204);
}

// A multi-byte ACK field with a documented range; `at` counts from the payload's first byte.
struct Int16Field {
  MessageId ack;
  size_t at;
  int lo;
  int hi;
  bool off_code;  // -2732 (-273.2 degC) means "off"
};
constexpr std::array<Int16Field, 7> kRangedFields = {{{0x010100, 10, -1000, 5000, true},
                                                      {0x010100, 12, -1000, 5000, true},
                                                      {0x010100, 14, 1, 6000, true},
                                                      {0x010100, 17, -300, 500, false},
                                                      {0x010100, 19, 0, 800, false},
                                                      {0x010502, 2, 0, 2047, false},
                                                      {0x010502, 4, 0, 2047, false}}};

bool fits(const Int16Field& f, uint16_t raw) {
  const int value = static_cast<int16_t>(raw);
  return (value >= f.lo && value <= f.hi) || (f.off_code && value == -2732);
}

uint16_t big_at(const uint8_t* p, size_t at) {
  return static_cast<uint16_t>((p[at] << 8) | p[at + 1]);
}
uint16_t little_at(const uint8_t* p, size_t at) {
  return static_cast<uint16_t>(p[at] | (p[at + 1] << 8));
}

// One field: both readings tried; the first that tells them apart is the evidence.
template <class Fits>
void fold(MessageId ack_id, const uint8_t* payload, size_t at, Fits fits_value, AckOrderFit& fit) {
  const bool as_big = fits_value(big_at(payload, at));
  const bool as_little = fits_value(little_at(payload, at));
  if (as_big != as_little && fit.evidence.empty()) {
    char text[64];
    std::snprintf(text, sizeof text, "ACK 0x%06X bytes %zu-%zu: %02X %02X", ack_id, at + 1, at + 2,
                  payload[at], payload[at + 1]);
    fit.evidence = text;
  }
  fit.big = fit.big && as_big;
  fit.little = fit.little && as_little;
}

}  // namespace

void fit_ack_byte_order(MessageId ack_id, const uint8_t* payload, size_t size, AckOrderFit& fit) {
  if (size < 2) return;
  fold(ack_id, payload, 0, known_response_code, fit);
  for (const Int16Field& field : kRangedFields) {
    if (field.ack != ack_id || size < field.at + 2) continue;  // a code-only refusal
    fold(
        ack_id, payload, field.at, [&](uint16_t raw) { return fits(field, raw); }, fit);
  }
}

}  // namespace k40t::protocol
