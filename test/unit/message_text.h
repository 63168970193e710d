// Messages written as "name=value name=value ..." text, for tests whose samples set or check many
// fields of one message: one readable statement instead of a line per field. Names and spellings
// are those of protocol/field_assign.h (integers, reals, bools 0/1/true/false, enums by code or by
// label with '_' for spaces). A value cannot contain a space: set such a text field by hand.
// Labels that differ only in punctuation ("+1" and "-1" both read "1") are ambiguous: set and
// check such a field by hand.
// A misspelt name, a value that does not read or a word without '=' fails the test.
// Works for the pod's messages (T::fields()) and the PSDK's commands with a layout(), whose bit
// fields go by their own names ("motors_rotating", not "state.motors_rotating").
#pragma once

#include <gtest/gtest.h>

#include <initializer_list>
#include <sstream>
#include <string>
#include <type_traits>

#include "field_recorder.h"
#include "k40t_driver/codec/layout.h"
#include "k40t_driver/protocol/field_assign.h"

namespace k40t::testing {

// The words of `text` as name=value pairs, in the order written; a word without '=' fails the test.
inline FieldValues field_values_from_text(const std::string& text) {
  FieldValues values;
  std::istringstream words(text);
  for (std::string word; words >> word;) {
    const size_t equals = word.find('=');
    if (equals == std::string::npos || equals == 0) {
      ADD_FAILURE() << "'" << word << "' is not name=value in: " << text;
      continue;
    }
    values.emplace_back(word.substr(0, equals), word.substr(equals + 1));
  }
  return values;
}

// Sets the fields `text` names in `message` (field_assign.h's assigning visitor, which
// message_from_args applies to a default message), leaving the others as they are.
template <class T>
void set_fields(T& message, const std::string& text) {
  protocol::FieldArgs args;
  for (const auto& [name, value] : field_values_from_text(text)) {
    if (!args.emplace(name, value).second)
      ADD_FAILURE() << T::kName << ": field '" << name << "' given twice in: " << text;
  }
  protocol::detail::ArgAssigner assigner(args);
  visit_named_fields(message, assigner);
  EXPECT_TRUE(assigner.status) << T::kName << ": " << assigner.status.message();
  for (const auto& [name, value] : args) {
    bool known = false;
    for (const std::string& field : assigner.names) known = known || field == name;
    EXPECT_TRUE(known) << "'" << name << "' is not a field of " << T::kName;
  }
}

// The message T with the fields `text` names set, the others at the struct's defaults.
template <class T>
T message_from_text(const std::string& text) {
  T message{};
  set_fields(message, text);
  return message;
}

// Calls check(name, message) for each field of T set to each of `values`, the other fields at
// their defaults: for range checks that every field must pass.
template <class T, class Check>
void for_each_field_set_to(std::initializer_list<const char*> values, Check check) {
  const FieldRecorder defaults = record_fields(T{});
  for (const FieldRecorder::Field& field : defaults.fields()) {
    for (const char* value : values) {
      T message{};
      set_fields(message, field.name + "=" + value);
      check(field.name, message);
    }
  }
}

// Each field `text` names has that value (field_recorder.h's comparison: numbers as numbers,
// reals within 1e-9 relative, enums by code or label); the fields it does not name are not
// checked. A name that is not a field of T is a failure.
template <class T>
::testing::AssertionResult fields_are(const T& message, const std::string& text) {
  const FieldRecorder recorded = record_fields(message);
  std::string differences;
  for (const auto& [name, expected] : field_values_from_text(text)) {
    std::string problem = "field '" + name + "' is not a field of " + T::kName;
    for (const FieldRecorder::Field& field : recorded.fields()) {
      if (field.name == name) problem = value_difference(field, expected);
    }
    if (!problem.empty()) differences += "  " + problem + "\n";
  }
  if (differences.empty()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << T::kName << " fields differ:\n" << differences;
}

}  // namespace k40t::testing
