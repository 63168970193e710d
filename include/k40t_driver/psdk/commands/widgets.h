// DJI Pilot widgets, APP function command set 0x02, ids 0x04..0x08 (protocol document sections
// 3.2.4 to 3.2.8): the adapter reads the payload's widget list and widget values, and sets values.
#pragma once

#include "k40t_driver/psdk/commands/declare.h"

namespace k40t::psdk {

constexpr size_t kMaxWidgets = 30;
constexpr size_t kMaxWidgetsPerGroup = 15;
constexpr size_t kMaxWidgetGroups = (kMaxWidgets + kMaxWidgetsPerGroup - 1) / kMaxWidgetsPerGroup;
constexpr size_t kWidgetNameSize = 32;
constexpr size_t kChooseItemNameSize = 16;
constexpr size_t kMaxChooseItems = 10;
constexpr size_t kInputBoxSuffixSize = 32;

enum class WidgetType : uint8_t {
  kButton = 1,
  kSwitch = 2,
  kRangeBar = 3,
  kChooseList = 4,
  kIntegerInputBox = 5,
};
const char* to_string(WidgetType type);

// An ACK that reports how many there are of something, 0..Max (one byte).
template <size_t Max>
struct CountUpTo {
  K40T_PSDK_FIELDS((uint8_t, count, wire::u8));
  Status validate() const { return check_int("count", count, 0, static_cast<int64_t>(Max)); }
};

// 3.2.4: GetWidgetListLength, WidgetListLengthAck.
K40T_PSDK_GET(WidgetListLength, widget_list_length, CountUpTo<kMaxWidgets>, kAppFunction, 0x04,
              "3.2.4");

// 3.2.5 ACK: one widget's description. Choose lists add their item names, integer input boxes
// the text shown after the number; the other types end after the name (35 bytes in all).
struct WidgetListDataAck : Reply<CommandSet::kAppFunction, 0x05, Sender::kPayload> {
  K40T_PSDK_NAMED("get_widget_list_data_ack", "3.2.5");
  static constexpr size_t kMinBodySize = 2 + kWidgetNameSize;
  static constexpr size_t kMaxBodySize = kMinBodySize + 1 + kMaxChooseItems * kChooseItemNameSize;

  WidgetType type = WidgetType::kButton;
  uint8_t index = 0;              // position in DJI Pilot's widget box, 0 on top
  std::string name;               // at most 31 bytes + NUL
  uint8_t choose_item_count = 0;  // choose list: 1..10
  std::array<std::string, kMaxChooseItems> choose_items{};  // each at most 15 bytes + NUL
  std::string input_box_suffix;                             // integer input box: at most 31 + NUL

  K40T_PSDK_VARIABLE_LENGTH();
};

// 3.2.5: the n-th widget of the list, from 0.
struct GetWidgetListData
    : Command<CommandSet::kAppFunction, 0x05, Sender::kAdapter, WidgetListDataAck> {
  K40T_PSDK_NAMED("get_widget_list_data", "3.2.5");
  K40T_PSDK_FIELDS((uint8_t, index, wire::u8));
  Status validate() const { return check_int("index", index, 0, kMaxWidgets - 1); }
};

// 3.2.6: GetWidgetGroupCount, WidgetGroupCountAck: widget values are read in groups of at most 15.
K40T_PSDK_GET(WidgetGroupCount, widget_group_count, CountUpTo<kMaxWidgetGroups>, kAppFunction, 0x06,
              "3.2.6");

struct WidgetValue {
  K40T_PSDK_FIELDS((WidgetType, type, wire::u8, WidgetType::kButton), (uint8_t, index, wire::u8),
                   (int32_t, value, wire::i32));
};

// 3.2.7 ACK: 1..15 widget values.
struct WidgetGroupDataAck : Reply<CommandSet::kAppFunction, 0x07, Sender::kPayload> {
  K40T_PSDK_NAMED("get_widget_group_data_ack", "3.2.7");
  static constexpr size_t kMinBodySize = 1;
  static constexpr size_t kMaxBodySize = 1 + kMaxWidgetsPerGroup * 6;

  uint8_t count = 0;
  std::array<WidgetValue, kMaxWidgetsPerGroup> widgets{};

  K40T_PSDK_VARIABLE_LENGTH();
};

// 3.2.7: the values of group n, from 0.
struct GetWidgetGroupData
    : Command<CommandSet::kAppFunction, 0x07, Sender::kAdapter, WidgetGroupDataAck> {
  K40T_PSDK_NAMED("get_widget_group_data", "3.2.7");
  K40T_PSDK_FIELDS((uint8_t, group, wire::u8));
  Status validate() const { return check_int("group", group, 0, kMaxWidgetGroups - 1); }
};

// 3.2.8: DJI Pilot changed a widget.
struct SetWidgetValue : Command<CommandSet::kAppFunction, 0x08, Sender::kAdapter, PlainAck> {
  K40T_PSDK_NAMED("set_widget_value", "3.2.8");
  WidgetValue widget;
  K40T_PSDK_LAYOUT(s, v) { WidgetValue::layout(s.widget, v); }
};

}  // namespace k40t::psdk
