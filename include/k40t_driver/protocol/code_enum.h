// Coded values of the document: enums whose enumerators are the wire codes, each with a
// to_string() that gives the code's meaning, or nullptr for a code the document does not define
// (check_enum and the field visitor rely on that).
#pragma once

#include <cstdint>

// The tables the to_string()s read: by_code, consecutive_name.
#include "k40t_driver/codec/enum_names.h"

// Declares `enum class Name : uint8_t { enumerators }` and its to_string().
#define K40T_CODE_ENUM(Name, ...)            \
  enum class Name : uint8_t { __VA_ARGS__ }; \
  const char* to_string(Name v)
